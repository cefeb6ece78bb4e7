// A study end to end on two tiny cases: the report and its page (opened in headless Chromium), a
// study killed during its second case and started again (same numbers as one that ran straight
// through), a case whose configuration changed under a finished run (refused), and finished runs
// of an older trapdem (a key added since, another description: kept; another value, a retired key:
// refused).
#include <gtest/gtest.h>
#include <omp.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <cmath>
#include <sstream>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <regex>
#include <thread>

#include "core/json.hpp"
#include "core/errors.hpp"
#include "core/exit_codes.hpp"
#include "io/text_file.hpp"
#include "study_command.hpp"
#include "tiny_study.hpp"
#include "../scratch_dir.hpp"

extern char** environ;

namespace fs = std::filesystem;
using namespace trapdem;
using trapdem::test::ScratchDir;

namespace {

// Two tiny cases that differ in sliding friction; shortened (a shallow pour, 3 mm of travel) so that a
// case takes a few seconds.
const std::string kStudy = "name = \"tiny-pair\"\ndescription = \"Two tiny cases, smooth and rough grains\"\n" +
                           test::tiny_scale("the tiny preset, a shallow pour and 3 mm of travel") +
                           test::three_mm_of_travel + "[report]\ncontours_at = 0.002\n" + test::smooth_and_rough_cases;

fs::path write_study_file(const fs::path& dir, const std::string& text = kStudy) {
  const fs::path file = dir / "study.toml";
  std::ofstream(file) << text;
  return file;
}

// The study in `file` into `out` on one thread (bitwise reproducible), quietly.
app::StudyOptions one_thread_study(const fs::path& file, const fs::path& out) {
  app::StudyOptions o;
  o.file = file.string();
  o.out = out.string();
  o.threads = 1;
  o.quiet = true;
  return o;
}

Json summary_of(const fs::path& out) {
  const fs::path file = out / "report" / "summary.json";
  return Json::parse(read_text_file(file), file.string());
}

// The report's numbers without the run costs (wall clock differs between any two runs).
std::string numbers_without_cost(const Json& summary) {
  Json copy = Json::object();
  Json cases = Json::array();
  for (std::size_t k = 0; k < summary["cases"].size(); ++k) {
    Json c = Json::object();
    for (const auto& [key, value] : summary["cases"][k].members())
      if (key != "cost") c.set(key, value);
    cases.push_back(c);
  }
  copy.set("cases", cases);
  copy.set("findings", summary["findings"]);
  copy.set("strain_scale_max", summary["strain_scale_max"]);
  return copy.dump();
}

// The study that runs straight through into `dir`/out, its file `dir`/study.toml.
void run_the_straight_study(const fs::path& dir) {
  const app::StudyOptions o = one_thread_study(write_study_file(dir), dir / "out");
  ASSERT_EQ(app::run_study(o), 0);
}

// One study that ran straight through, shared by the tests, which only read it (a test that writes
// works in a copy). ctest makes it once for all of them (tests/CMakeLists.txt: the fixture
// study.straight_run runs StudyRunFixture below with TRAPDEM_STUDY_RUN naming the folder, which
// ctest gives each test); without that variable (the program run by hand) the suite makes its own.
class StudyRun : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (const char* shared = std::getenv("TRAPDEM_STUDY_RUN"); shared != nullptr && *shared != '\0') {
      root_ = shared;
      ASSERT_TRUE(fs::exists(out() / "report" / "summary.json"))
          << "TRAPDEM_STUDY_RUN=" << shared << " holds no finished study (the fixture study.straight_run makes it)";
      return;
    }
    dir_.emplace("trapdem-study-straight");
    root_ = dir_->path();
    run_the_straight_study(root_);
  }
  static void TearDownTestSuite() { dir_.reset(); }
  static fs::path out() { return root_ / "out"; }
  // A copy of the study's folder (its file and its output) in `dir`: for a test that writes.
  static fs::path copy_into(const fs::path& dir) {
    fs::copy(root_, dir, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
    return dir / "out";
  }
  static std::optional<ScratchDir> dir_;
  static fs::path root_;
};
std::optional<ScratchDir> StudyRun::dir_;
fs::path StudyRun::root_;

// What the fixture study.straight_run runs (not discovered as a test of its own: tests/CMakeLists.txt
// leaves out suites named *Fixture): the shared study, made afresh in TRAPDEM_STUDY_RUN; the program
// run by hand without that variable makes it in a scratch folder (as SetUpTestSuite would).
TEST(StudyRunFixture, MakesTheSharedStudy) {
  const char* shared = std::getenv("TRAPDEM_STUDY_RUN");
  if (shared == nullptr || *shared == '\0') {
    const ScratchDir scratch("trapdem-study-straight");
    run_the_straight_study(scratch.path());
    return;
  }
  fs::remove_all(shared);
  fs::create_directories(shared);
  run_the_straight_study(shared);
}

struct BrowserResult {
  int exit_code = -1;
  int images = -1;                  // <img> elements on the page
  std::string broken_images;        // their src, space-separated, of those that did not load
  std::vector<std::string> console; // console messages (errors, warnings, logs: the page writes none)
};

// Opens `page` in headless Chromium with a checker appended (in a copy beside it, so relative image
// paths resolve as for the page itself): after the load event it records which images did not load.
// Console messages come from Chromium's log on stderr.
BrowserResult open_in_chromium(const fs::path& page, const std::string& extra_script = "") {
  std::string html = read_text_file(page);
  const std::string checker =
      "<script>window.addEventListener('load', () => {"
      " const bad = Array.from(document.images).filter(i => !(i.complete && i.naturalWidth > 0))"
      "   .map(i => i.getAttribute('src'));"
      " document.body.setAttribute('data-image-count', String(document.images.length));"
      " document.body.setAttribute('data-broken-images', bad.join(' ')); });</script>" + extra_script;
  const std::size_t body_end = html.rfind("</body>");
  EXPECT_NE(body_end, std::string::npos) << page;
  html.insert(body_end, checker);
  const fs::path copy = page.parent_path() / ".browser-check.html";
  std::ofstream(copy) << html;
  const ScratchDir scratch("trapdem-study-chromium-profile");
  const fs::path& profile = scratch.path();
  const fs::path dom = profile / "dom.html", log = profile / "stderr.txt";
  const std::string command = "timeout 120 chromium --headless --no-sandbox --disable-gpu --no-first-run "
                              "--user-data-dir=" + profile.string() +
                              " --enable-logging=stderr --v=0 --virtual-time-budget=10000 --dump-dom 'file://" +
                              fs::absolute(copy).string() + "' > " + dom.string() + " 2> " + log.string();
  BrowserResult r;
  const int status = std::system(command.c_str());
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  const std::string text = read_text_file(dom);
  std::smatch m;
  if (std::regex_search(text, m, std::regex("data-image-count=\"([0-9]+)\""))) r.images = std::stoi(m[1]);
  if (std::regex_search(text, m, std::regex("data-broken-images=\"([^\"]*)\""))) r.broken_images = m[1];
  std::istringstream lines(read_text_file(log));
  for (std::string line; std::getline(lines, line);)
    if (line.find(":CONSOLE") != std::string::npos) r.console.push_back(line);
  fs::remove(copy);
  return r;
}

bool chromium_installed() { return std::system("command -v chromium > /dev/null 2>&1") == 0; }

}  // namespace

TEST_F(StudyRun, ReportHasEveryFigureAndMeasuredNumbers) {
  const fs::path report = out() / "report";
  for (const char* f : {"index.html", "strain_panel.png", "ground_reaction.png", "contours_smooth.png",
                        "contours_rough.png", "summary.json", "metrics.csv"})
    EXPECT_TRUE(fs::exists(report / f)) << f;
  const Json s = summary_of(out());
  ASSERT_EQ(s["cases"].size(), 2u);
  EXPECT_EQ(s["cases"][0]["name"].as_string(), "smooth");
  EXPECT_EQ(s["cases"][1]["name"].as_string(), "rough");
  // The report's numbers are the cases' own analyses (whether a tiny shallow bed forms a band or a
  // surface trough is the mechanism's business, not the report's: a missing one is null on both sides).
  auto same = [](double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; };
  for (std::size_t k = 0; k < 2; ++k) {
    const Json& c = s["cases"][k];
    const fs::path metrics_file = out() / "cases" / c["name"].as_string() / "analysis" / "metrics.json";
    const Json m = Json::parse(read_text_file(metrics_file), metrics_file.string());
    const Json& bands = json_member_or_null(m, "shear_bands");
    const double left = json_number_or_nan(json_member_or_null(bands, "left"), "angle_deg");
    const double right = json_number_or_nan(json_member_or_null(bands, "right"), "angle_deg");
    EXPECT_TRUE(same(c["band_angle_left_deg"].as_number(), left));
    EXPECT_TRUE(same(c["band_angle_right_deg"].as_number(), right));
    const Json& zone = json_member_or_null(m, "zone_of_influence");
    EXPECT_TRUE(same(c["zone_surface_m"].as_number(), json_number_or_nan(zone, "surface_width_m")));
    EXPECT_TRUE(same(c["zone_mid_height_m"].as_number(), json_number_or_nan(zone, "mid_height_width_m")));
    EXPECT_NEAR(c["travel_m"].as_number(), 0.003, 1e-4);
    // Arching: the trapdoor load falls well below its value before lowering.
    EXPECT_LT(c["min_load_ratio"].as_number(), 0.6);
    EXPECT_GT(c["cost"]["particle_steps_per_second"].as_number(), 0.0);
    EXPECT_EQ(c["cost"]["segments"].as_number(), 1.0);
  }
  // The findings are the trends of these numbers: the one for the arching says which way the least
  // trapdoor load goes from Smooth to Rough, as the numbers do. Not which way the physics goes:
  // in a bed this small and shallow a few force chains decide the least load, and runs that
  // differ only in round-off (1e-14 of the wall forces) gave Rough both less and more of it than
  // Smooth. The trend with friction is measured where it means something: the paper's Table 2
  // study at the demo scale (docs/study.md).
  const double smooth = s["cases"][0]["min_load_ratio"].as_number();
  const double rough = s["cases"][1]["min_load_ratio"].as_number();
  bool arching_sentence = false;
  for (std::size_t k = 0; k < s["findings"].size(); ++k) {
    const std::string f = s["findings"][k].as_string();
    if (f.rfind("The least trapdoor load", 0) == 0) {
      arching_sentence = true;
      if (std::fabs(rough - smooth) > 0.02) {  // the findings' resolution for a load ratio
        EXPECT_NE(f.find(rough < smooth ? "falls from" : "rises from"), std::string::npos)
            << f << " (Smooth " << smooth << ", Rough " << rough << ")";
      } else {
        EXPECT_NE(f.find("about the same"), std::string::npos) << f << " (Smooth " << smooth << ", Rough " << rough << ")";
      }
    }
  }
  EXPECT_TRUE(arching_sentence);
  // The page names what differs: the two friction keys, and not the name.
  const std::string page = read_text_file(report / "index.html");
  EXPECT_NE(page.find("<code>contact.kinetic_friction</code>"), std::string::npos);
  EXPECT_NE(page.find("<code>contact.static_friction</code>"), std::string::npos);
  EXPECT_EQ(page.find("<code>name</code>"), std::string::npos);
  EXPECT_EQ(page.find("http"), std::string::npos) << "the page must work offline";
  // The contour figures share one scale, and the page says which (contours_at = 2 mm: colours over
  // +-2 mm, lines at a 1-2-5 step of it).
  EXPECT_NE(page.find("One scale for every case: the colours span settlement −δ to +δ (the trapdoor's displacement, "
                      "2 mm), the contour lines every "),
            std::string::npos)
      << page;
}

// study.json names the study file relative to the study folder (a published copy names no
// machine's absolute path), and that path leads to the file from there.
TEST_F(StudyRun, StudyJsonNamesTheStudyFileRelativeToTheFolder) {
  const Json j = Json::parse(read_text_file(out() / "study.json"), "study.json");
  const std::string file = j["study_file"].as_string();
  EXPECT_FALSE(fs::path(file).is_absolute()) << file;
  EXPECT_TRUE(fs::exists(out() / file)) << file;
}

TEST_F(StudyRun, PageOpensInHeadlessChromiumWithoutMissingImagesOrConsoleErrors) {
  ASSERT_TRUE(chromium_installed()) << "chromium (Debian package) is needed: scripts/install-deps installs it";
  const ScratchDir scratch("trapdem-study-page");  // the checks write pages beside the report's
  const fs::path page = copy_into(scratch.path()) / "report" / "index.html";
  const BrowserResult ok = open_in_chromium(page);
  EXPECT_EQ(ok.exit_code, 0);
  EXPECT_EQ(ok.images, 4);  // the strain panel, two contour maps, the ground reaction curves
  EXPECT_EQ(ok.broken_images, "");
  EXPECT_TRUE(ok.console.empty()) << ok.console.front();

  // The check itself can fail: a page pointing at a missing image, and one writing to the console.
  const fs::path broken = page.parent_path() / "broken.html";
  std::string html = read_text_file(page);
  html.replace(html.find("ground_reaction.png\" alt"), std::string("ground_reaction.png").size(), "no_such_figure.png");
  std::ofstream(broken) << html;
  const BrowserResult missing = open_in_chromium(broken);
  EXPECT_EQ(missing.broken_images, "no_such_figure.png");
  const BrowserResult noisy = open_in_chromium(page, "<script>console.error('checked');</script>");
  ASSERT_EQ(noisy.console.size(), 1u);
  EXPECT_NE(noisy.console[0].find("checked"), std::string::npos);
  fs::remove(broken);
}

// --format svg and pdf (a copy of the study, reported again): every figure of the report and of the
// runs' analyses in that format, told by the file's signature; the page shows the SVGs themselves,
// and beside each PDF a PNG (a browser shows no PDF as an image), every image linked to its file.
TEST_F(StudyRun, ReportFiguresInSvgAndPdf) {
  ASSERT_TRUE(chromium_installed()) << "chromium (Debian package) is needed: scripts/install-deps installs it";
  for (const std::string format : {"svg", "pdf"}) {
    const ScratchDir dir("trapdem-study-format-" + format);
    const fs::path out = dir / "out", report = out / "report";
    fs::copy(StudyRun::out(), out, fs::copy_options::recursive);
    fs::remove_all(report);
    for (const char* c : {"smooth", "rough"}) fs::remove_all(out / "cases" / c / "analysis");
    app::StudyOptions o;
    o.file = write_study_file(dir.path()).string();
    o.out = out.string();
    o.quiet = true;
    o.report_only = true;
    o.format = format;
    ASSERT_EQ(app::run_study(o), 0);
    const bool pdf = format == "pdf";
    const std::string signature = pdf ? "%PDF-" : "<?xml";
    const std::string page = read_text_file(report / "index.html");
    for (const std::string stem : {"strain_panel", "ground_reaction", "contours_smooth", "contours_rough"}) {
      const fs::path figure = report / (stem + "." + format);
      ASSERT_TRUE(fs::exists(figure)) << figure;
      EXPECT_EQ(read_text_file(figure).substr(0, 5), signature) << figure;
      if (!pdf) {
        EXPECT_NE(read_text_file(figure).find("<svg"), std::string::npos) << figure;
      }
      EXPECT_EQ(fs::exists(report / (stem + ".png")), pdf) << stem << ".png only beside a PDF";
      const std::string shown = stem + (pdf ? ".png" : ".svg");
      EXPECT_NE(page.find("<a href=\"" + stem + "." + format + "\"><img src=\"" + shown + "\""), std::string::npos)
          << stem;
    }
    for (const char* c : {"smooth", "rough"}) {
      const fs::path analysis = out / "cases" / c / "analysis";
      for (const std::string stem : {"shear_strain", "vertical_displacement", "ground_reaction"}) {
        ASSERT_TRUE(fs::exists(analysis / (stem + "." + format))) << analysis << " " << stem;
        EXPECT_EQ(read_text_file(analysis / (stem + "." + format)).substr(0, 5), signature);
        EXPECT_FALSE(fs::exists(analysis / (stem + ".png")));
      }
    }
    const BrowserResult shown = open_in_chromium(report / "index.html");
    EXPECT_EQ(shown.exit_code, 0);
    EXPECT_EQ(shown.images, 4);
    EXPECT_EQ(shown.broken_images, "") << format;
  }
  const ScratchDir scratch("trapdem-study-format-eps");
  app::StudyOptions eps;
  eps.out = copy_into(scratch.path()).string();
  eps.file = (scratch.path() / "study.toml").string();
  eps.report_only = true;
  eps.format = "eps";
  EXPECT_THROW(app::run_study(eps), InputError);
}

TEST_F(StudyRun, KilledDuringTheSecondCaseAndStartedAgainGivesTheSameReport) {
  const ScratchDir scratch("trapdem-study-killed");
  const fs::path& dir = scratch.path();
  const fs::path file = write_study_file(dir), out = dir / "out";
  const std::string executable = TRAPDEM_EXECUTABLE;
  std::vector<std::string> args = {executable, "study", file.string(), "--out", out.string(), "--threads", "1",
                                   "--quiet"};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, executable.c_str(), nullptr, nullptr, argv.data(), environ), 0);
  // Kill it (no chance to write anything) once the second case has written its first checkpoint.
  const fs::path second = out / "cases" / "rough";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(3);
  while (!fs::exists(second / "checkpoint.h5") && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_TRUE(fs::exists(second / "checkpoint.h5")) << "the second case never checkpointed";
  ASSERT_EQ(::kill(pid, SIGKILL), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the study ended before it was killed";
  ASSERT_FALSE(fs::exists(second / "run.json")) << "the second case had finished: nothing left to resume";
  EXPECT_TRUE(fs::exists(out / "cases" / "smooth" / "run.json"));
  EXPECT_FALSE(fs::exists(out / "report"));

  app::StudyOptions again;
  again.file = file.string();
  again.out = out.string();
  again.threads = 1;
  again.quiet = true;
  ASSERT_EQ(app::run_study(again), 0);
  const std::string log = read_text_file(out / "study.log");
  EXPECT_NE(log.find("[1/2] smooth: finished before, skipped"), std::string::npos) << log;
  EXPECT_NE(log.find("[2/2] rough: resuming from its checkpoint"), std::string::npos) << log;
  // Bitwise-reproducible runs at one thread: the resumed study's numbers are exactly the straight one's.
  EXPECT_EQ(numbers_without_cost(summary_of(out)), numbers_without_cost(summary_of(StudyRun::out())));
  // The killed segment counts up to its checkpoint (run_record.hpp); the work is the straight run's.
  EXPECT_EQ(summary_of(out)["cases"][1]["cost"]["segments"].as_number(), 2.0);
  EXPECT_EQ(summary_of(out)["cases"][1]["cost"]["particle_steps"].as_number(),
            summary_of(StudyRun::out())["cases"][1]["cost"]["particle_steps"].as_number());
}

// --stop-after: a budget of a nanosecond stops the first run with its checkpoint at its first look at
// the clock (the budget's clock starts with that run) and starts no other; the same command again,
// with a budget no tiny run nears, resumes it, runs the second and gives the straight study's numbers;
// a budget spent when a run would start starts none.
TEST_F(StudyRun, StopAfterStopsTheRunningCaseWithItsCheckpointAndTheSameCommandCarriesOn) {
  const ScratchDir scratch("trapdem-study-stop-after");
  const fs::path file = write_study_file(scratch.path()), out = scratch.path() / "out";
  app::StudyOptions o = one_thread_study(file, out);
  o.stop_after_seconds = 1e-9;
  ASSERT_EQ(app::run_study(o), kExitInterrupted);
  EXPECT_TRUE(fs::exists(out / "cases" / "smooth" / "checkpoint.h5"));
  EXPECT_FALSE(fs::exists(out / "cases" / "rough")) << "a run started after the budget was spent";
  EXPECT_FALSE(fs::exists(out / "report"));
  std::string log = read_text_file(out / "study.log");
  EXPECT_NE(log.find("[1/2] smooth: stopped (a signal, or the study's time budget) (checkpoint written)"),
            std::string::npos) << log;

  o.stop_after_seconds = 3600.0;
  ASSERT_EQ(app::run_study(o), 0);
  log = read_text_file(out / "study.log");
  EXPECT_NE(log.find("[1/2] smooth: resuming from its checkpoint"), std::string::npos) << log;
  EXPECT_NE(log.find("[2/2] rough: running"), std::string::npos) << log;
  EXPECT_EQ(numbers_without_cost(summary_of(out)), numbers_without_cost(summary_of(StudyRun::out())));

  // The budget spent between two runs: the first case, its run.json removed, resumes from its last
  // checkpoint (written when it finished: nothing left to step, so it finishes at once whatever the
  // budget), and the second, removed, is then not started.
  fs::remove(out / "cases" / "smooth" / "run.json");
  fs::remove_all(out / "cases" / "rough");
  o.stop_after_seconds = 1e-9;
  ASSERT_EQ(app::run_study(o), kExitInterrupted);
  EXPECT_TRUE(fs::exists(out / "cases" / "smooth" / "run.json"));
  EXPECT_FALSE(fs::exists(out / "cases" / "rough"));
  log = read_text_file(out / "study.log");
  EXPECT_NE(log.find("[2/2] rough: not started: the study's time budget of 1e-09 s (--stop-after) is spent"),
            std::string::npos) << log;
}

// A budget is for the runs run here, and a number of seconds: refused, before anything is written,
// with --report-only, --status, --collect or --submit, and when negative (from the library: the
// command line's own check refuses it first, tests/bad_input).
TEST_F(StudyRun, StopAfterIsRefusedWithoutRunsOrBelowZero) {
  const ScratchDir scratch("trapdem-study-stop-after-refused");
  const fs::path file = write_study_file(scratch.path()), out = scratch.path() / "out";
  for (int mode = 0; mode < 4; ++mode) {
    app::StudyOptions o = one_thread_study(file, out);
    o.stop_after_seconds = 60.0;
    o.report_only = mode == 0;
    o.status = mode == 1;
    o.collect = mode == 2;
    if (mode == 3) o.submit.submit = "slurm";
    EXPECT_THROW(app::run_study(o), InputError) << mode;
  }
  app::StudyOptions negative = one_thread_study(file, out);
  negative.stop_after_seconds = -1.0;
  EXPECT_THROW(app::run_study(negative), InputError);
  EXPECT_FALSE(fs::exists(out));
}

// --case and --seed: a replicate study (seeds 7 and 8 of each case) run one packing of one case at a
// time into its folder, the other runs left alone; the same folder then takes the rest of a case;
// a case or seed the study does not have is refused with the study's own (tests/bad_input: the
// command line's wording).
TEST(StudyRunSelection, CaseAndSeedRunOnlyTheChosenRunsAndTheRestFollowInTheSameFolder) {
  const ScratchDir scratch("trapdem-study-selection");
  std::string text = kStudy;
  text.insert(text.find('\n') + 1, "replicates = 2\n");
  const fs::path file = write_study_file(scratch.path(), text), out = scratch.path() / "out";
  app::StudyOptions o = one_thread_study(file, out);
  o.cases = {"rough"};
  o.seeds = {8};
  ASSERT_EQ(app::run_study(o), 0);
  EXPECT_TRUE(fs::exists(out / "cases" / "rough" / "seed-8" / "run.json"));
  EXPECT_FALSE(fs::exists(out / "cases" / "rough" / "seed-7"));
  EXPECT_FALSE(fs::exists(out / "cases" / "smooth"));
  EXPECT_TRUE(fs::exists(out / "report" / "summary.json")) << "the report covers the finished runs";
  std::string log = read_text_file(out / "study.log");
  EXPECT_NE(log.find("1 of the study's 4 runs selected (cases rough; seeds 8)"), std::string::npos) << log;
  EXPECT_NE(log.find("[1/1] rough"), std::string::npos) << log;

  o.cases = {"smooth"};
  o.seeds = {};
  ASSERT_EQ(app::run_study(o), 0);
  EXPECT_TRUE(fs::exists(out / "cases" / "smooth" / "seed-7" / "run.json"));
  EXPECT_TRUE(fs::exists(out / "cases" / "smooth" / "seed-8" / "run.json"));
  EXPECT_FALSE(fs::exists(out / "cases" / "rough" / "seed-7"));
  log = read_text_file(out / "study.log");
  EXPECT_NE(log.find("2 of the study's 4 runs selected (cases smooth)"), std::string::npos) << log;
  EXPECT_EQ(summary_of(out)["cases"][0]["runs"].size(), 2u) << "smooth: both seeds in the report";

  // Everything left: the one rough run not yet run; the three finished are skipped.
  o.cases = {};
  ASSERT_EQ(app::run_study(o), 0);
  EXPECT_TRUE(fs::exists(out / "cases" / "rough" / "seed-7" / "run.json"));
  log = read_text_file(out / "study.log");
  EXPECT_NE(log.find("[4/4] rough seed 8: finished before, skipped"), std::string::npos) << log;

  for (const auto& [cases, seeds, expected] :
       {std::tuple<std::vector<std::string>, std::vector<std::uint64_t>, std::string>{
            {"coarse"}, {}, "--case coarse: study 'tiny-pair' has no such case (its cases: smooth, rough)"},
        {{"rough"}, {9}, "--seed 9: no run of case rough packs with it (their packing seeds: 7, 8)"}}) {
    app::StudyOptions bad = one_thread_study(file, out);
    bad.cases = cases;
    bad.seeds = seeds;
    try {
      app::run_study(bad);
      ADD_FAILURE() << expected;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), expected);
    }
  }
}

TEST_F(StudyRun, ACaseWhoseConfigurationChangedIsRefused) {
  std::string text = kStudy;
  text.replace(text.find("kinetic_friction = 0.6"), 22, "kinetic_friction = 0.7");
  const ScratchDir scratch("trapdem-study-changed");
  const fs::path& dir = scratch.path();
  const fs::path out = copy_into(dir);
  const app::StudyOptions o = one_thread_study(write_study_file(dir, text), out);
  try {
    app::run_study(o);
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("another configuration than case 'rough'"), std::string::npos) << what;
    EXPECT_NE(what.find("kinetic_friction"), std::string::npos) << what;
  }
}

// A finished study's folder copied, with `edit` applied to the smooth case's resolved.toml: what
// a finished run made by an older trapdem looks like to this one.
fs::path copy_with_edited_smooth_case(const fs::path& study_out, const fs::path& dir,
                                      const std::function<void(std::string&)>& edit) {
  const fs::path copy = dir / "out";
  fs::copy(study_out, copy, fs::copy_options::recursive);
  const fs::path resolved = copy / "cases" / "smooth" / "resolved.toml";
  std::string text = read_text_file(resolved);
  edit(text);
  std::ofstream(resolved, std::ios::trunc) << text;
  return copy;
}

void erase_line(std::string& text, const std::string& line) {
  const std::size_t at = text.find("\n" + line + "\n");
  ASSERT_NE(at, std::string::npos) << line;
  text.erase(at + 1, line.size() + 1);
}

// A key added to trapdem since the run (absent from its resolved.toml, at its default now) and
// another description: the same run, skipped as finished.
TEST_F(StudyRun, AFinishedRunWithoutANewKeyOrWithAnotherDescriptionIsKept) {
  const ScratchDir scratch("trapdem-study-older");
  const fs::path& dir = scratch.path();
  const fs::path copy = copy_with_edited_smooth_case(out(), dir, [](std::string& text) {
    erase_line(text, "poisson_ratio = 0.3");  // tiny leaves it at its default
    const std::size_t at = text.find("\ndescription = ");
    ASSERT_NE(at, std::string::npos);
    text.replace(at + 1, text.find('\n', at + 1) - at - 1, "description = \"worded otherwise\"");
  });
  const app::StudyOptions o = one_thread_study(write_study_file(dir), copy);
  ASSERT_EQ(app::run_study(o), 0);
  const std::string log = read_text_file(copy / "study.log");
  EXPECT_NE(log.find("[1/2] smooth: finished before, skipped"), std::string::npos) << log;
  EXPECT_NE(log.find("[2/2] rough: finished before, skipped"), std::string::npos) << log;
}

// A value that differs, or a key this trapdem does not read (one removed since): refused, named.
TEST_F(StudyRun, AFinishedRunWithAnotherValueOrAnUnknownKeyIsRefused) {
  const std::vector<std::pair<std::function<void(std::string&)>, std::string>> edits = {
      {[](std::string& t) { t.replace(t.find("poisson_ratio = 0.3"), 19, "poisson_ratio = 0.2"); },
       "contact.poisson_ratio is 0.2 there, 0.3 now"},
      {[](std::string& t) { t.replace(t.find("poisson_ratio = 0.3"), 19, "poisson_ratio = 0.3\nretired_key = 1"); },
       "unknown key contact.retired_key"},
  };
  for (const auto& [edit, expected] : edits) {
    const ScratchDir scratch("trapdem-study-older-refused");
    const fs::path& dir = scratch.path();
    const fs::path copy = copy_with_edited_smooth_case(out(), dir, edit);
    const app::StudyOptions o = one_thread_study(write_study_file(dir), copy);
    try {
      app::run_study(o);
      ADD_FAILURE() << "expected an error for " << expected;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("another configuration than case 'smooth'"), std::string::npos) << what;
      EXPECT_NE(what.find(expected), std::string::npos) << what;
    }
  }
}

TEST_F(StudyRun, AnotherScaleInTheSameFolderIsRefused) {
  std::string text = kStudy;
  text = std::regex_replace(text, std::regex("scales\\.test"), "scales.other");
  const ScratchDir scratch("trapdem-study-scale");
  const fs::path& dir = scratch.path();
  app::StudyOptions o;
  o.out = copy_into(dir).string();
  o.file = write_study_file(dir, text).string();
  o.quiet = true;
  try {
    app::run_study(o);
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("holds study 'tiny-pair' at scale 'test'"), std::string::npos) << e.what();
  }
}
