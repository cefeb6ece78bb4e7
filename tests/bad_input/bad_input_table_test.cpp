// Issue 14, "always on": a table of bad inputs to every command of the `trapdem` binary, each row the
// arguments (and the text of an input file, if the row needs one), the exit code expected and a
// fragment of the message. The exit codes are README.md's "Exit codes" (apps/main.cpp): InputError
// and every command-line refusal (CLI11's own codes 105, 106, 109 mapped, issue 41) exit 2,
// FileError 4; the ExitCode rows walk that table. Every row runs as a separate process in a folder
// of its own.
//
// Placeholders in the arguments: {IN} the row's input file (its text is the row's `input`), {TINY}
// the tiny preset, {RUN} a tiny run stopped after 300 steps (checkpoint.h5, resolved.toml, run.log),
// {DUMP0} {DUMP1} {DUMPNAN} LAMMPS dumps of a small bed (the last with a nan coordinate), {GEOM} a
// geometry file for them, {IMG1} {IMG2} two speckle images, {EMPTY} an empty folder, {NOWHERE} a
// path that does not exist, {SNAPRUN} a folder holding only a snapshots.h5 of {DUMP0}'s bed.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "experiment/folder_run.hpp"
#include "io/snapshot.hpp"
#include "../scratch_dir.hpp"

namespace trapdem {
namespace {

namespace fs = std::filesystem;

struct BadInput {
  const char* name;
  const char* args;      // after `trapdem`, placeholders replaced
  const char* input;     // text of {IN}, or nullptr
  int exit_code;
  const char* fragment;  // must appear in stdout + stderr
};

std::ostream& operator<<(std::ostream& os, const BadInput& b) { return os << b.name; }


const std::vector<BadInput>& table() {
  static const std::vector<BadInput> rows = {
      // ---- README.md's exit codes, one row per case a bad input gives cheaply (issue 41); CLI11's
      // former 105 (a bad value), 106 (a missing option) and 109 (an unknown option) are the rows
      // RunThreadsText, CompareMissingAt and RunUnknownOption below, now 2; 4 is AnalyzeDumpMissingFile.
      // 3 (the physics guard) and 130 (interrupted) are tested where a run stops (tests/experiment,
      // tests/study)
      {"ExitCode0Help", "--help", nullptr, 0, "Usage:"},
      {"ExitCode0CommandHelp", "analyze --help", nullptr, 0, "Usage:"},
      {"ExitCode2UnknownCommand", "NOSUCH", nullptr, 2, "'NOSUCH' is not a trapdem command (the commands: run,"},
      {"ExitCode2UnknownCommandHelp", "NOSUCH --help", nullptr, 2, "'NOSUCH' is not a trapdem command"},
      {"ExitCode2MisspeltCommand", "anlyze {RUN}", nullptr, 2, "'anlyze' is not a trapdem command (did you mean analyze?)"},
      {"ExitCode2NoCommand", "", nullptr, 2, "A subcommand is required"},
      {"ExitCode2BadConfigKey", "run {IN}", "[trapdoor]\nrat = 0.1\n", 2, "unknown key trapdoor.rat"},
      {"ExitCode3RunStoppedByTheGuard", "run {TINY} --set contact.normal_stiffness=1 --set numerics.time_step=1e-5", nullptr, 3, "run stopped"},
      {"ExitCode130StoppedWithItsCheckpoint", "run {TINY} --stop-after 0.001 --out {EMPTY}/stopped", nullptr, 130, "resume"},
      // ---- run: files, syntax, keys
      {"RunMissingFile", "run {NOWHERE}/x.toml", nullptr, 2, "File does not exist"},
      {"RunSyntaxError", "run {IN}", "x = [1, 2\n", 2, "TOML syntax error"},
      {"RunTypoAndMissingPourTogether", "run {IN}", "[box]\nwidht = 0.3\n", 2, "unknown key box.widht (did you mean box.width?)"},
      {"RunTypoBeforeRule", "run {IN}", "[box]\nwidht = 0.3\n", 2, "a particle count or a fill_height"},
      {"RunUnknownTable", "run {IN}", "[trapdor]\nwidth = 0.05\n[pluviation]\ncount = 100\n", 2, "unknown key trapdor.width"},
      {"RunWrongType", "run {IN}", "[box]\nheight = \"tall\"\n[pluviation]\ncount = 100\n", 2, "box.height = \"tall\" (a string): expected a number"},
      {"RunFloatForInteger", "run {TINY} --set pluviation.count=3e5", nullptr, 2, "pluviation.count = 300000.0 (a float): expected an integer"},
      {"RunDeepNesting", "run {IN}", "DEEP", 2, "nested 100 levels deep: expected at most 64"},
      {"RunHertzWallWithoutModulus", "run {IN}", "[pluviation]\ncount = 100\n[walls.base]\nnormal_model = \"hertz\"\n", 2, "youngs_modulus"},
      {"RunEmptyFile", "run {IN}", "", 2, "a particle count or a fill_height"},
      // ---- run: values not finite or not sane
      {"RunInfRate", "run {TINY} --set trapdoor.rate=inf", nullptr, 2, "trapdoor.rate = inf (a float): expected a finite number"},
      {"RunInfRampTime", "run {TINY} --set spin_up.ramp_time=inf", nullptr, 2, "spin_up.ramp_time = inf (a float): expected a finite number"},
      {"RunInfSkin", "run {TINY} --set numerics.skin_fraction=inf", nullptr, 2, "numerics.skin_fraction = inf"},
      {"RunHugePourSkin", "run {TINY} --set pluviation.skin_fraction=3", nullptr, 2, "pluviation.skin_fraction = 3"},
      {"RunPourSkinPastThePeriod", "run {TINY} --set box.depth_boundary=periodic --set pluviation.skin_fraction=1.5", nullptr, 2,
       "a pour skin the periodic depth holds"},
      {"RunNanDepth", "run {TINY} --set box.depth=nan", nullptr, 2, "box.depth = nan (a float): expected a finite number"},
      {"RunInfGLevel", "run {TINY} --set spin_up.g_level=inf", nullptr, 2, "spin_up.g_level = inf"},
      {"RunNegativeInfFriction", "run {TINY} --set contact.static_friction=-inf", nullptr, 2, "contact.static_friction = -inf"},
      {"RunNanSnapshot", "run {TINY} --set output.snapshot_displacements=[0.0,nan]", nullptr, 2, "output.snapshot_displacements[1] = nan"},
      {"RunHugeWidth", "run {TINY} --set box.width=1e300", nullptr, 2, "box.width = 1e+300 (a float): expected a number in (0, 10] (m)"},
      {"RunHugeDensity", "run {TINY} --set particles.density=1e9", nullptr, 2, "expected a number in (0, 100000] (kg/m^3)"},
      {"RunHugeCount", "run {TINY} --set pluviation.count=1000000000000", nullptr, 2, "expected an integer in [0, 100000000]"},
      {"RunDenormalStiffness", "run {TINY} --set contact.normal_stiffness=1e-320", nullptr, 2, "contact.normal_stiffness = 1e-320 (a float): expected a value that gives a finite critical time step"},
      {"RunTinyTimeStepFraction", "run {TINY} --set numerics.time_step_fraction=1e-300", nullptr, 2, "numerics.time_step_fraction = 1e-300 (a float): expected a time step of at least 1e-15 s"},
      {"RunEndlessLowering", "run {TINY} --set trapdoor.rate=1e-9", nullptr, 2, "trapdoor.rate = 1e-09 (a float): expected a stage of at most 1e+11 time steps"},
      {"RunTooManyRows", "run {TINY} --set output.ground_reaction_step=1e-12", nullptr, 2, "output.ground_reaction_step"},
      {"RunZeroCheckpointInterval", "run {TINY} --set output.checkpoint_interval=0", nullptr, 2, "output.checkpoint_interval = 0 (an integer): expected a number in (0, 10000000] (s)"},
      {"RunMinAboveMaxTime", "run {TINY} --set settling.min_time=1", nullptr, 2, "settling.min_time = 1 (an integer): expected at most max_time"},
      {"RunTrapdoorWiderThanBox", "run {TINY} --set trapdoor.width=0.09", nullptr, 2, "expected a trapdoor narrower than the box"},
      // ---- run: [packing] (a run from a packing made elsewhere; {DUMP0} fits the tiny box)
      {"RunPackingNoFormat", "run {TINY} --set packing.from={DUMP0}", nullptr, 2, "packing.format: expected a format for packing.from"},
      {"RunPackingBadFormat", "run {TINY} --set packing.from={DUMP0} --set packing.format=xyz", nullptr, 2, "packing.format = \"xyz\""},
      {"RunPackingDumpReadAsData", "run {TINY} --set packing.from={DUMP0} --set packing.format=lammps-data", nullptr, 2, "d0.dump:2: header line holds only numbers"},
      {"RunPackingMissingFile", "run {TINY} --set packing.from={NOWHERE}/p.data --set packing.format=lammps-data", nullptr, 2, "cannot open the LAMMPS data file"},
      {"RunPackingBelowTheBase", "run {TINY} --set packing.from={DUMP0} --set packing.format=lammps-dump --set packing.shift=[0.0,0.0,-0.01]", nullptr, 2, "d0.dump:10: particle 1 at"},
      {"RunPackingOverlap", "run {TINY} --set packing.from={IN} --set packing.format=lammps-dump",
       "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: ATOMS id x y z radius\n1 0.02 0.007 0.01 0.002\n2 0.022 0.007 0.01 0.002\n", 2,
       "in.txt:6: particle 1 at (0.02, 0.007, 0.01) m, radius 0.002 m: overlaps particle 2"},
      {"RunPackingZeroRadius", "run {TINY} --set packing.from={IN} --set packing.format=lammps-dump",
       "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n1\nITEM: ATOMS id x y z radius\n7 0.02 0.007 0.01 0\n", 2, "in.txt:6: the radius of atom 7 must be positive"},
      {"RunPackingSnapshotWithDump", "run {TINY} --set packing.from={DUMP0} --set packing.format=lammps-dump --set packing.snapshot=1", nullptr, 2, "no snapshot index with this format"},
      {"RunPackingNegativeSnapshot", "run {TINY} --set packing.from={RUN} --set packing.format=trapdem --set packing.snapshot=-1", nullptr, 2, "packing.snapshot = -1 (an integer): expected an integer in [0, 10000]"},
      {"RunPackingRunWithoutSnapshots", "run {TINY} --set packing.from={RUN} --set packing.format=trapdem", nullptr, 2, "snapshots.h5: not found"},
      {"RunPackingShiftOfTwo", "run {TINY} --set packing.from={DUMP0} --set packing.format=lammps-dump --set packing.shift=[0.0,0.0]", nullptr, 2, "three numbers [dx, dy, dz] in m (found 2)"},
      {"RunPackingNanShift", "run {TINY} --set packing.from={DUMP0} --set packing.format=lammps-dump --set packing.shift=[0.0,nan,0.0]", nullptr, 2, "packing.shift[1] = nan"},
      {"RunPackingStartStage", "run {TINY} --set packing.from={DUMP0} --set packing.format=lammps-dump --set packing.start_stage=lowering", nullptr, 2, "packing.start_stage = \"lowering\""},
      // ---- run: command line
      {"RunThreadsText", "run {TINY} --threads abc", nullptr, 2, "--threads 'abc': expected 0 (all cores) or a thread count up to 4096"},
      {"RunThreadsHuge", "run {TINY} --threads 100000", nullptr, 2, "--threads '100000': expected 0 (all cores) or a thread count up to 4096"},
      {"RunThreadsOverflow", "run {TINY} --threads 99999999999999999999", nullptr, 2, "expected 0 (all cores) or a thread count up to 4096"},
      {"RunThreadsInConfig", "run {TINY} --set numerics.threads=100000", nullptr, 2, "numerics.threads = 100000 (an integer): expected an integer in [0, 4096]"},
      {"RunSetWithoutEquals", "run {TINY} --set trapdoor.rate", nullptr, 2, "--set trapdoor.rate: expected key.path=value"},
      {"RunSetBadKey", "run {TINY} --set 'trap door.rate=1'", nullptr, 2, "is not a key path"},
      {"RunSetDeepKey", "run {TINY} --set a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a=1", nullptr, 2, "levels deep: expected at most 64"},
      {"RunUnknownPreset", "run --preset nosuch", nullptr, 2, "nosuch"},
      {"RunConfigAndPreset", "run {TINY} --preset tiny", nullptr, 2, "give either a configuration file or --preset, not both"},
      {"RunOccupiedFolder", "run {TINY} --out {RUN}", nullptr, 2, "already holds a run: resume it with --resume"},
      {"RunUnknownOption", "run {TINY} --colour red", nullptr, 2, "--colour"},
      // ---- run: resume
      {"ResumeMissingFolder", "run --resume {NOWHERE}", nullptr, 2, "Directory does not exist"},
      {"ResumeNotARunFolder", "run --resume {EMPTY}", nullptr, 2, "neither checkpoint.h5 nor resolved.toml there: not a run folder"},
      {"ResumeWithSet", "run --resume {RUN} --set trapdoor.rate=0.2", nullptr, 2, "to change trapdoor.rate on purpose add --allow-change trapdoor.rate"},
      {"ResumeWithConfig", "run {TINY} --resume {RUN}", nullptr, 2, "give no configuration file or --preset with it"},
      {"ResumeWithPreset", "run --preset tiny --resume {RUN}", nullptr, 2, "give no configuration file or --preset with it"},
      {"ResumeWithOut", "run --resume {RUN} --out {EMPTY}", nullptr, 2, "give no --out"},
      {"AllowChangeWithoutResume", "run {TINY} --allow-change trapdoor.rate", nullptr, 2, "--allow-change trapdoor.rate: only with --resume"},
      // ---- analyze
      {"AnalyzeNoRunFolder", "analyze {EMPTY}", nullptr, 2, "resolved.toml: not found"},
      {"AnalyzeDumpCountMismatch", "analyze {EMPTY} --dumps {DUMP0} {DUMP1} --displacements 0mm --config {GEOM} --no-figures", nullptr, 2, "2 dump files but 1 displacements"},
      {"AnalyzeGridTooFine", "analyze {EMPTY} --dumps {DUMP0} {DUMP1} --displacements 0mm,1mm --config {GEOM} --no-figures --quiet --grid 1e-9", nullptr, 2, "bytes per field; expected at most 1 GiB per field"},
      {"AnalyzeHistoryGridZero", "analyze {EMPTY} --dumps {DUMP0} {DUMP1} --displacements 0mm,1mm --config {GEOM} --no-figures --quiet --field-history-grid 0mm", nullptr, 2, "--field-history-grid 0mm: expected a positive length"},
      {"AnalyzeHistoryGridTooFine", "analyze {EMPTY} --dumps {DUMP0} {DUMP1} --displacements 0mm,1mm --config {GEOM} --no-figures --quiet --field-history-grid 1e-9", nullptr, 2, "--field-history-grid 1e-09 m over"},
      {"AnalyzeHistoryGridText", "analyze {EMPTY} --dumps {DUMP0} {DUMP1} --displacements 0mm,1mm --config {GEOM} --no-figures --quiet --field-history-grid abc", nullptr, 2, "--field-history-grid"},
      {"AnalyzeGridText", "analyze {EMPTY} --dumps {DUMP0} {DUMP1} --displacements 0mm,1mm --config {GEOM} --no-figures --quiet --grid abc", nullptr, 2, "'abc'"},
      {"AnalyzeNanInDump", "analyze {EMPTY} --dumps {DUMP0} {DUMPNAN} --displacements 0mm,1mm --config {GEOM} --no-figures --quiet", nullptr, 2, "coordinate: 'nan' is not a finite number"},
      {"AnalyzeDumpMissingFile", "analyze {EMPTY} --dumps {DUMP0} {NOWHERE}/x.dump --displacements 0mm,1mm --config {GEOM} --no-figures", nullptr, 2, "x.dump: no such dump file"},
      {"AnalyzeDumpIsAFolder", "analyze {EMPTY} --dumps {DUMP0} {EMPTY} --displacements 0mm,1mm --config {GEOM} --no-figures", nullptr, 2, "empty: a folder, not a dump file"},
      {"AnalyzeSmoothingText", "analyze {RUN} --smoothing abc", nullptr, 2, "--smoothing: 'abc': expected a number >= 0 and <= 100 mean diameters"},
      {"AnalyzeSmoothingInf", "analyze {RUN} --smoothing inf", nullptr, 2, "expected a number >= 0 and <= 100"},
      {"AnalyzeBadView", "analyze {RUN} --view sideways", nullptr, 2, "sideways"},
      {"AnalyzeRunWithoutSnapshots", "analyze {RUN}", nullptr, 2, "snapshots.h5"},
      // ---- compare
      {"CompareMissingAt", "compare {RUN} {EMPTY}", nullptr, 2, "--at is required"},
      {"CompareRunWithoutSnapshots", "compare {RUN} {EMPTY} --at 10mm", nullptr, 2, "snapshots.h5: not found (run `trapdem run` first)"},
      {"CompareNoDemFolder", "compare {NOWHERE} {EMPTY} --at 10mm", nullptr, 2, "nowhere"},
      {"CompareBadAtBeforeAnyFile", "compare {NOWHERE} {NOWHERE} --at 10pc", nullptr, 2, "--at '10pc'"},
      {"CompareBadGridBeforeAnyFile", "compare {NOWHERE} {NOWHERE} --at 10mm --grid 0", nullptr, 2, "--grid must be positive"},
      {"CompareUnknownOption", "compare {RUN} {EMPTY} --at 10mm --colour red", nullptr, 2, "--colour"},
      // ---- piv and synth
      {"PivOneImage", "piv {IMG1} --out {EMPTY}/p", nullptr, 2, "give at least two images"},
      {"PivEmptyRoi", "piv {IMG1} {IMG2} --out {EMPTY}/p --roi 40,10,40,70 --quiet --no-figures", nullptr, 2, "--roi"},
      {"PivMissingImage", "piv {IMG1} {NOWHERE}/b.png --out {EMPTY}/p --quiet", nullptr, 2, "b.png': no such file"},
      {"PivNotAnImage", "piv {IMG1} {IN} --out {EMPTY}/p --quiet", "not an image\n", 2, "in.txt': not an image format OpenCV can read"},
      {"PivThreadsHuge", "piv {IMG1} {IMG2} --out {EMPTY}/p --threads 100000", nullptr, 2, "expected 0 (all cores) or a thread count up to 4096"},
      {"SynthHugeImage", "synth --out {EMPTY}/s --size 200000x200000", nullptr, 2, "needs 3.2e+11 bytes of working memory; expected at most 1 GiB"},
      {"SynthNanNoise", "synth --out {EMPTY}/s --size 64x64 --noise nan", nullptr, 2, "noise nan grey levels: expected a finite number >= 0"},
      {"SynthBadSize", "synth --out {EMPTY}/s --size abc", nullptr, 2, "--size 'abc': expected WIDTHxHEIGHT"},
      {"SynthOneImage", "synth --out {EMPTY}/s --images 1", nullptr, 2, "at least 2"},
      {"SynthNanMagnitude", "synth --out {EMPTY}/s --size 64x64 --magnitude nan", nullptr, 2, "not finite"},
      // ---- render: the image size from --px-per-mm
      {"RenderHugeScale", "render {SNAPRUN} --config {GEOM} --px-per-mm 1e9 --out {EMPTY}/r", nullptr, 2, "'1e9': expected a number > 0 and <= 1000 px per mm"},
      {"RenderViewTooLarge", "render {SNAPRUN} --config {GEOM} --px-per-mm 1000 --out {EMPTY}/r", nullptr, 2, "--px-per-mm 1000: the view of 80 x"},
      {"RenderNoSnapshots", "render {RUN}", nullptr, 2, "snapshots.h5: not found (run `trapdem run` first)"},
      // ---- sinkhole
      {"SinkholeInfiniteDiameter", "sinkhole --throat 2 --layer 1e308:89.99", nullptr, 2, "(D_s = inf m); expected a thickness in metres that gives a finite D_s"},
      {"SinkholeAngle90", "sinkhole --throat 2 --layer 12:90", nullptr, 2, "outside [0, 90)"},
      {"SinkholeNoAngle", "sinkhole --throat 2 --layer 12", nullptr, 2, "expected THICKNESS:ANGLE_OF_DRAW"},
      {"SinkholeNegativeThroat", "sinkhole --throat -1 --layer 12:30", nullptr, 2, "--throat"},
      {"SinkholeNanThroat", "sinkhole --throat nan --layer 12:30", nullptr, 2, "--throat"},
      {"SinkholeNanThickness", "sinkhole --throat 2 --layer nan:30", nullptr, 2, "not a number"},
      {"SinkholeNanAngle", "sinkhole --throat 2 --layer 12:nan", nullptr, 2, "the angle of draw 'nan' is not a number"},
      {"SinkholeNoLayer", "sinkhole --throat 2", nullptr, 2, "layer"},
      {"SinkholeFromNowhere", "sinkhole --from {NOWHERE} --layer :30", nullptr, 2, "nowhere: not a folder"},
      // ---- study
      {"StudyMissingFile", "study {NOWHERE}/s.toml", nullptr, 2, "File does not exist"},
      {"StudySyntaxError", "study {IN}", "name = \n", 2, "TOML syntax error"},
      {"StudyDeepNesting", "study {IN}", "DEEP", 2, "nested 100 levels deep: expected at most 64"},
      {"StudyNoScales", "study {IN} --out {EMPTY}/st", "name = \"s\"\n", 2, "scales: expected a table of scales"},
      {"StudyUnknownKey", "study {IN} --out {EMPTY}/st",
       "name = \"s\"\ncolour = 1\n[scales.demo]\npreset = \"tiny\"\n[cases.a]\nlabel = \"A\"\n", 2, "unknown key colour"},
      {"StudyTooManyReplicates", "study {IN} --out {EMPTY}/st",
       "[scales.s]\npreset = \"tiny\"\n[cases.a]\nreplicates = 5000\n", 2, "in [1, 1000]"},
      {"StudySeedPastJsonExactness", "study {IN} --out {EMPTY}/st",
       "[scales.s]\npreset = \"tiny\"\n[cases.a]\nseeds = [9007199254740993]\n", 2, "in [0, 9007199254740991]"},
      {"StudyStrainScaleTooHigh", "study {IN} --out {EMPTY}/st",
       "[scales.s]\npreset = \"tiny\"\n[cases.a]\nlabel = \"A\"\n[report]\nmax_strain = 1e9\n", 2, "report.max_strain"},
      {"StudyThreadsText", "study {IN} --threads abc", "name = \"s\"\n", 2, "expected 0 (all cores) or a thread count up to 4096"},
      {"StudyStopAfterNegative", "study {IN} --stop-after -5", "name = \"s\"\n", 2, "--stop-after"},
      {"StudyStopAfterWithStatus", "study {IN} --out {EMPTY}/st --status --stop-after 60",
       "[scales.s]\npreset = \"tiny\"\n[cases.a]\nlabel = \"A\"\n", 2, "--stop-after: a budget for the runs here"},
      {"StudyCaseUnknown", "study {IN} --out {EMPTY}/sc --case nosuch",
       "[scales.s]\npreset = \"tiny\"\n[cases.a]\nlabel = \"A\"\n", 2, "--case nosuch: study"},
      {"StudySeedNoRunPacksWith", "study {IN} --out {EMPTY}/ss --seed 99",
       "[scales.s]\npreset = \"tiny\"\n[cases.a]\nlabel = \"A\"\n", 2, "--seed 99: no run of study"},
      {"StudySeedNegative", "study {IN} --seed -3", "name = \"s\"\n", 2, "--seed"},
      {"StudyCaseWithReportOnly", "study {IN} --out {EMPTY}/sr --report-only --case a",
       "[scales.s]\npreset = \"tiny\"\n[cases.a]\nlabel = \"A\"\n", 2, "--case, --seed: choose the runs run here"},
      // ---- figure
      {"FigureMaxStrainNegative", "figure {RUN} --max-strain -1 --out {EMPTY}/p.png", nullptr, 2, "--max-strain -1: expected"},
      {"FigureLabelsNotOnePerRun", "figure {RUN} {RUN} --labels A --out {EMPTY}/p.png", nullptr, 2, "--labels: 1 labels for 2 run folders"},
      {"FigureBadExtension", "figure {RUN} --out {EMPTY}/p.gif", nullptr, 2, "p.gif"},
      // ---- calibrate
      {"CalibrateMissingVary", "calibrate {TINY} --target {EMPTY} --at 10mm", nullptr, 2, "--vary is required"},
      {"CalibrateNoTarget", "calibrate {TINY} --vary trapdoor.rate=0.1,0.2 --target {EMPTY} --at 10mm --out {EMPTY}/c", nullptr, 2, "piv.h5"},
      {"CalibrateBadVary", "calibrate {TINY} --vary trapdoor.rate --target {EMPTY} --at 10mm --out {EMPTY}/c", nullptr, 2, "trapdoor.rate"},
      {"CalibrateThreadsHuge", "calibrate {TINY} --vary trapdoor.rate=0.1 --target {EMPTY} --at 10mm --threads 100000", nullptr, 2, "expected 0 (all cores) or a thread count up to 4096"},
      // ---- element
      {"ElementTooFewParticles", "element --preset tiny --set element.particles=10 --out {EMPTY}/e", nullptr, 2, "element.particles = 10 (an integer): expected an integer in [50, 1000000]"},
      {"ElementHugeSpecimen", "element --preset tiny --set element.particles=1000000000 --out {EMPTY}/e", nullptr, 2, "expected an integer in [50, 1000000]"},
      {"ElementHugeConfining", "element --preset tiny --confining 1e300 --out {EMPTY}/e", nullptr, 2, "element.confining[0] = 1e+300 (a float): expected a number in (0, 1000000000] (Pa)"},
      {"ElementInfInertialNumber", "element --preset tiny --set element.inertial_number=inf --out {EMPTY}/e", nullptr, 2, "element.inertial_number = inf (a float): expected a finite number"},
      {"ElementBadTest", "element --preset tiny --test shear", nullptr, 2, "shear"},
      {"ElementThreadsText", "element --preset tiny --threads abc", nullptr, 2, "expected 0 (all cores) or a thread count up to 4096"},
      {"ElementDeepNesting", "element {IN}", "DEEP", 2, "nested 100 levels deep: expected at most 64"},
      {"ElementNoParticles", "element {IN} --out {EMPTY}/e", "[box]\nwidth = 0.3\n", 2, "no [particles] table"},
      {"ElementTypoInRunKeys", "element {IN} --out {EMPTY}/e", "[particles]\ndiameter = 0.002\n[contact]\nrestitution = 0.5\nstatic_frction = 0.3\n", 2, "unknown key contact.static_frction"},
  };
  return rows;
}

class BadInputTable : public ::testing::TestWithParam<BadInput> {
 protected:
  static std::optional<test::ScratchDir> scratch_;
  static fs::path root_;
  static std::map<std::string, std::string> places_;

  static void SetUpTestSuite() {
    root_ = scratch_.emplace("trapdem-bad-input").path();
    places_.clear();
  }

  // The file or folder a placeholder stands for, made the first time a row names it: ctest runs
  // each row as a process of its own, and most rows need none of the costly ones ({RUN} is a tiny
  // run of 300 steps, {IMG1} a `trapdem synth`).
  static const std::string& place(const std::string& name) {
    auto found = places_.find(name);
    if (found != places_.end()) return found->second;
    return places_[name] = make_place(name);
  }

  static std::string make_place(const std::string& name) {
    if (name == "{TINY}") return (fs::path(TRAPDEM_SOURCE_DIR) / "presets" / "tiny.toml").string();
    if (name == "{EMPTY}") {
      fs::create_directories(root_ / "empty");
      return (root_ / "empty").string();
    }
    if (name == "{NOWHERE}") return (root_ / "nowhere").string();
    // A small bed as two LAMMPS dumps: 20 x 10 spheres of 4 mm near the front window, the second
    // settled up to 1 mm above the trapdoor.
    auto dump = [&](const std::string& file, double settlement, bool nan) {
      std::ostringstream atoms;
      int id = 0;
      for (int ix = 0; ix < 20; ++ix)
        for (int iz = 0; iz < 10; ++iz) {
          const double x = 0.002 + 0.004 * ix, z = 0.002 + 0.004 * iz;
          const double dz = -settlement * std::max(0.0, 1.0 - std::abs(x - 0.04) / 0.01);
          ++id;
          if (nan && id == 7) atoms << id << " nan 0.012 " << z << " 0.002\n";
          else atoms << id << ' ' << x << " 0.012 " << z + dz << " 0.002\n";
        }
      const fs::path path = root_ / file;
      std::ofstream(path) << "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n200\nITEM: BOX BOUNDS ff ff ff\n0 0.08\n0 0.014\n"
                             "0 0.045\nITEM: ATOMS id x y z radius\n"
                          << atoms.str();
      return path.string();
    };
    if (name == "{DUMP0}") return dump("d0.dump", 0.0, false);
    if (name == "{DUMP1}") return dump("d1.dump", 0.001, false);
    if (name == "{DUMPNAN}") return dump("dnan.dump", 0.001, true);
    if (name == "{GEOM}") {
      std::ofstream(root_ / "geom.toml") << "[box]\nwidth = 0.08\ndepth = 0.014\nheight = 0.045\n[trapdoor]\nwidth = 0.016\n"
                                            "travel = 0.004\n";
      return (root_ / "geom.toml").string();
    }
    if (name == "{SNAPRUN}") {  // the {DUMP0} bed as a run's only snapshot (for render)
      Particles bed;
      for (int ix = 0; ix < 20; ++ix)
        for (int iz = 0; iz < 10; ++iz) bed.add(ix * 10 + iz + 1, {0.002 + 0.004 * ix, 0.012, 0.002 + 0.004 * iz}, 0.002, 2500.0);
      fs::create_directories(root_ / "snaprun");
      append_snapshot(root_ / "snaprun" / "snapshots.h5", make_snapshot(bed, 0.0, "pour", 0.0, 0));
      return (root_ / "snaprun").string();
    }
    if (name == "{RUN}") {  // a run stopped after 300 steps (of the pour): what a resume needs
      FolderRunOptions run;
      run.config_file = place("{TINY}");
      run.out_dir = root_ / "run";
      run.quiet = true;
      run.threads = 1;
      run.stop_at_step = 300;
      run_in_folder(run);
      return run.out_dir.string();
    }
    if (name == "{IMG1}" || name == "{IMG2}") {  // two speckle images
      if (!fs::exists(root_ / "img" / "image_001.png")) {
        const std::string synth = fmt::format("'{}' synth --out '{}' --size 64x64 > /dev/null", TRAPDEM_EXECUTABLE,
                                              (root_ / "img").string());
        if (std::system(synth.c_str()) != 0) throw std::runtime_error("synth failed: " + synth);
      }
      return (root_ / "img" / (name == "{IMG1}" ? "image_001.png" : "image_002.png")).string();
    }
    throw std::logic_error("the bad-input table names an unknown placeholder " + name);
  }

  static void TearDownTestSuite() { scratch_.reset(); }
};

std::optional<test::ScratchDir> BadInputTable::scratch_;
fs::path BadInputTable::root_;
std::map<std::string, std::string> BadInputTable::places_;

std::string deep_toml() {
  std::string key = "a";
  for (int i = 1; i < 100; ++i) key += ".a";
  return "[" + key + "]\nx = 1\n";
}

TEST_P(BadInputTable, ExitCodeAndMessage) {
  const BadInput& row = GetParam();
  const fs::path dir = root_ / "rows" / row.name;
  fs::create_directories(dir);
  if (row.input) std::ofstream(dir / "in.txt") << (std::string(row.input) == "DEEP" ? deep_toml() : row.input);
  // Each {NAME} in the arguments replaced by its place ({IN}: the row's input file).
  std::string args;
  for (std::size_t from = 0; from < std::strlen(row.args);) {
    const std::string rest = row.args + from;
    const std::size_t open = rest.find('{'), close = rest.find('}', open);
    if (open == std::string::npos || close == std::string::npos) {
      args += rest;
      break;
    }
    const std::string name = rest.substr(open, close - open + 1);
    args += rest.substr(0, open) + (name == "{IN}" ? (dir / "in.txt").string() : place(name));
    from += close + 1;
  }
  // Every row fails within a second; a row that hangs (inf passed on as a stage length once did)
  // is stopped after 60 s and fails with exit code 124.
  const std::string command =
      fmt::format("cd '{}' && timeout 60 '{}' {} > out.txt 2> err.txt", dir.string(), TRAPDEM_EXECUTABLE, args);
  const int status = std::system(command.c_str());
  auto read = [](const fs::path& p) {
    std::ifstream in(p);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  const std::string said = read(dir / "out.txt") + read(dir / "err.txt");
  SCOPED_TRACE("trapdem " + args + "\n" + said.substr(0, 1500));
  ASSERT_TRUE(WIFEXITED(status)) << "killed by a signal";
  EXPECT_EQ(WEXITSTATUS(status), row.exit_code);
  EXPECT_NE(said.find(row.fragment), std::string::npos) << "expected the message to say: " << row.fragment;
}

INSTANTIATE_TEST_SUITE_P(Rows, BadInputTable, ::testing::ValuesIn(table()),
                         [](const ::testing::TestParamInfo<BadInput>& info) { return std::string(info.param.name); });

TEST(BadInputTableSize, AtLeastSixtyRowsCoveringEveryCommand) {
  EXPECT_GE(table().size(), 60u);
  for (const char* command : {"run", "analyze", "compare", "piv", "synth", "sinkhole", "study", "calibrate", "element"}) {
    int rows = 0;
    for (const BadInput& b : table()) rows += std::string(b.args).rfind(std::string(command) + " ", 0) == 0;
    EXPECT_GE(rows, 3) << command;
  }
}

}  // namespace
}  // namespace trapdem
