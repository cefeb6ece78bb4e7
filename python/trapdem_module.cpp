// trapdem from Python (issue 40): the library's workflows as calls, the GIL released while they run.
// The Python package (python/trapdem/__init__.py) wraps these in the names users call; this module
// (_trapdem) only converts: options in, plain values and numpy arrays out, the library's errors as
// Python exceptions (InputError -> ValueError, FileError -> OSError, SimulationError -> RuntimeError).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <optional>

#include <fmt/format.h>
#include <string>
#include <vector>

#include "analysis/analysis_output.hpp"
#include "analysis/field_history.hpp"
#include "core/build_info.hpp"
#include "core/errors.hpp"
#include "experiment/folder_run.hpp"
#include "piv/piv_folder.hpp"
#include "piv/synthetic_sequence.hpp"
#include "study/element_folder.hpp"
#include "study/ground_reaction_overlay.hpp"
#include "study/run_analysis.hpp"
#include "study/study_definition.hpp"
#include "study/strain_panel_of_runs.hpp"
#include "study/study_runner.hpp"

namespace py = pybind11;
namespace fs = std::filesystem;
using namespace trapdem;

namespace {

// A numpy array that owns a copy of `values` laid out as `shape` (row-major).
py::array_t<double> array_of(const std::vector<double>& values, std::vector<py::ssize_t> shape) {
  py::array_t<double> a(shape);
  std::copy(values.begin(), values.end(), a.mutable_data());
  return a;
}

// The terminal of a call from Python: sys.stdout and sys.stderr as they are when a line comes (a
// notebook's kernel points them at the running cell; the process's file descriptors are not the
// notebook's). The GIL is taken for each line; a stream that fails to write is reported as
// unraisable and never stops a run (run.log has every line).
LineSink python_terminal() {
  auto writer = [](const char* stream) {
    return [stream](const std::string& line) {
      py::gil_scoped_acquire acquire;
      try {
        const py::object target = py::module_::import("sys").attr(stream);
        target.attr("write")(line + "\n");
        target.attr("flush")();
      } catch (py::error_already_set& e) {
        e.discard_as_unraisable(fmt::format("trapdem writing a line to sys.{}", stream).c_str());
      }
    };
  };
  return LineSink{writer("stdout"), writer("stderr")};
}

py::array_t<double> points_array(const std::vector<Point2>& points) {
  std::vector<double> flat;
  flat.reserve(2 * points.size());
  for (const Point2& p : points) {
    flat.push_back(p.x);
    flat.push_back(p.z);
  }
  return array_of(flat, {py::ssize_t(points.size()), 2});
}

// One PIV strain field (piv_strain.hpp) as arrays: the nodes (subset centres in image 1) and
// their displacement (N, 2: x, z in the result's unit, z up), the kept triangles (M, 3 node
// indices), gamma_max and the volumetric strain per triangle (compression positive). None for an
// image without a field (image 1, or too few valid subsets).
py::object strain_field(const PivStrainField& f) {
  if (f.mesh.size() == 0) return py::none();
  std::vector<std::int64_t> triangles, subsets;
  for (const auto& t : f.mesh.triangles)
    for (std::size_t c : t) triangles.push_back(std::int64_t(c));
  for (std::size_t k : f.subset) subsets.push_back(std::int64_t(k));
  py::dict d;
  d["subset"] = py::array_t<std::int64_t>({py::ssize_t(subsets.size())}, subsets.data());
  d["position"] = points_array(f.position);
  d["displacement"] = points_array(f.displacement);
  d["triangles"] = py::array_t<std::int64_t>({py::ssize_t(f.mesh.size()), py::ssize_t(3)}, triangles.data());
  d["gamma_max"] = array_of(f.max_shear, {py::ssize_t(f.max_shear.size())});
  d["volumetric"] = array_of(f.volumetric, {py::ssize_t(f.volumetric.size())});
  return d;
}

bool run(const std::string& config_text, const std::string& config_name, const std::string& config_file,
         const std::vector<std::string>& overrides, const std::string& out, const std::string& resume,
         const std::vector<std::string>& allowed_changes, int threads, bool quiet, double stop_after_seconds) {
  FolderRunOptions o;
  o.config_text = config_text;
  o.config_name = config_name;
  o.config_file = config_file;
  o.overrides = overrides;
  o.out_dir = out;
  o.resume_dir = resume;
  o.allowed_changes = allowed_changes;
  o.threads = threads;
  o.quiet = quiet;
  o.terminal = python_terminal();
  o.stop_after_seconds = stop_after_seconds;
  py::gil_scoped_release release;  // the run's own SIGINT handler stops it with a checkpoint
  return run_in_folder(o);
}

py::dict analyze(const std::string& dir, const std::string& at, const std::string& reference, const std::string& view,
                 bool incremental, double smoothing, bool write, bool figures, const std::string& format) {
  AnalyzeOptions a;
  a.dir = dir;
  a.at = at;
  a.reference = reference;
  a.view = view;
  a.incremental = incremental;
  a.smoothing = smoothing;
  a.no_figures = !figures;
  a.format = format;
  a.quiet = true;
  AnalysisResult r;
  std::vector<fs::path> written;
  {
    py::gil_scoped_release release;
    r = write ? analyze_and_write(a, &written) : analyze_directory(a);
  }
  py::dict d;
  d["metrics_json"] = metrics_json(r).dump();
  d["ids"] = py::array_t<std::int64_t>(py::ssize_t(r.id.size()), r.id.data());
  d["reference_positions"] = points_array(r.points.position);
  d["displacements"] = points_array(r.points.displacement);
  std::vector<std::int64_t> triangles;
  for (const auto& t : r.mesh.mesh.triangles)
    for (std::size_t c : t) triangles.push_back(std::int64_t(c));
  d["triangles"] = py::array_t<std::int64_t>({py::ssize_t(r.mesh.mesh.size()), py::ssize_t(3)}, triangles.data());
  d["gamma_max"] = array_of(r.gamma_max, {py::ssize_t(r.gamma_max.size())});
  d["gamma_max_smoothed"] = array_of(r.gamma_max_smoothed, {py::ssize_t(r.gamma_max_smoothed.size())});
  d["volumetric"] = array_of(r.volumetric, {py::ssize_t(r.volumetric.size())});
  const GridField& w = r.vertical_displacement;
  d["settlement_grid"] = array_of(w.value, {py::ssize_t(w.grid.nz), py::ssize_t(w.grid.nx)});
  d["grid_x0"] = w.grid.x0;
  d["grid_z0"] = w.grid.z0;
  d["grid_spacing"] = w.grid.spacing;
  std::vector<std::string> files;
  for (const fs::path& f : written) files.push_back(f.string());
  d["written"] = files;
  return d;
}

// A float stack as a (layers, rows, columns) float32 array.
py::array_t<float> stack_array(const FloatStack& stack) {
  py::array_t<float> a(std::vector<py::ssize_t>{py::ssize_t(stack.layers), py::ssize_t(stack.rows),
                                                py::ssize_t(stack.columns)});
  std::copy(stack.value.begin(), stack.value.end(), a.mutable_data());
  return a;
}

py::dict field_history_file(const std::string& file) {
  FieldHistory h;
  {
    py::gil_scoped_release release;
    h = read_field_history(file);
  }
  std::vector<double> x(h.grid.nx), z(h.grid.nz);
  for (std::size_t i = 0; i < h.grid.nx; ++i) x[i] = h.grid.x(i);
  for (std::size_t j = 0; j < h.grid.nz; ++j) z[j] = h.grid.z(j);
  py::dict d;
  d["case"] = h.case_name;
  d["view"] = h.view;
  d["mean_diameter"] = h.mean_diameter;
  d["reference_snapshot"] = h.reference_label;
  d["reference_displacement"] = h.reference_displacement;
  d["snapshot"] = h.labels;
  d["trapdoor_displacement"] = array_of(h.trapdoor_displacement, {py::ssize_t(h.layers())});
  d["x"] = array_of(x, {py::ssize_t(x.size())});
  d["z"] = array_of(z, {py::ssize_t(z.size())});
  d["vertical_displacement"] = stack_array(h.vertical_displacement);
  d["gamma_max"] = stack_array(h.gamma_max);
  d["volumetric_strain"] = stack_array(h.volumetric_strain);
  return d;
}

py::dict element(const std::string& config_file, const std::vector<std::string>& overrides, const std::string& out,
                 int threads) {
  ElementFolderOptions o;
  o.config_file = config_file;
  o.overrides = overrides;
  o.out_dir = out;
  o.threads = threads;
  ElementFolderResult r;
  {
    py::gil_scoped_release release;
    r = run_element_in_folder(o);
  }
  py::list angles;
  for (const ElementAngles& a : r.angles) {
    py::dict one;
    one["confining_pa"] = a.confining;
    one["phi_peak_deg"] = a.phi_peak;
    one["phi_cs_deg"] = a.phi_cs;
    one["phi_cs_gap_deg"] = a.phi_cs_gap;
    angles.append(one);
  }
  py::dict d;
  d["out"] = r.out.string();
  d["angles"] = angles;
  return d;
}

py::dict piv(const std::vector<std::string>& images, const std::string& out, int subset, int step, int threads,
             std::optional<double> scale, std::vector<double> origin, bool figures) {
  PivFolderOptions o;
  o.images.assign(images.begin(), images.end());
  o.out = out;
  o.settings.subset_size = subset;
  o.settings.step = step;
  o.settings.threads = threads;
  o.scale_mm_per_px = scale;
  if (origin.size() == 2) o.origin_mm = {origin[0], origin[1]};
  else if (!origin.empty()) throw InputError("origin: two numbers, x and z of pixel (0, 0) in mm");
  o.figures = figures;
  PivFolderResult r;
  {
    py::gil_scoped_release release;
    r = run_piv_into_folder(o);
  }
  // u, v (px, image axes) and the correlation of every subset of every image: (images, subsets).
  const std::size_t n = r.result.image_count(), m = r.subsets;
  std::vector<double> x(m), y(m), u(n * m), v(n * m), zncc(n * m);
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t s = 0; s < m && s < r.result.image[k].subset.size(); ++s) {
      const SubsetMeasurement& q = r.result.image[k].subset[s];
      u[k * m + s] = q.u;
      v[k * m + s] = q.v;
      zncc[k * m + s] = q.zncc;
    }
  for (std::size_t s = 0; s < m; ++s) {
    x[s] = r.result.grid.centre[s].x;
    y[s] = r.result.grid.centre[s].y;
  }
  py::dict d;
  d["x_px"] = array_of(x, {py::ssize_t(m)});
  d["y_px"] = array_of(y, {py::ssize_t(m)});
  d["u_px"] = array_of(u, {py::ssize_t(n), py::ssize_t(m)});
  d["v_px"] = array_of(v, {py::ssize_t(n), py::ssize_t(m)});
  d["zncc"] = array_of(zncc, {py::ssize_t(n), py::ssize_t(m)});
  d["unit"] = r.unit;
  py::list total, incremental;
  for (std::size_t k = 0; k < n; ++k) {
    total.append(k < r.strain.total.size() ? strain_field(r.strain.total[k]) : py::none());
    incremental.append(k < r.strain.incremental.size() ? strain_field(r.strain.incremental[k]) : py::none());
  }
  d["total_strain"] = total;
  d["incremental_strain"] = incremental;
  std::vector<std::string> files;
  for (const fs::path& f : r.written) files.push_back(f.string());
  d["written"] = files;
  return d;
}

int synth(const std::string& field, const std::string& out, int width, int height, int images, double noise,
          std::optional<double> magnitude, std::uint64_t seed) {
  SyntheticSequenceOptions o;
  o.field = parse_synthetic_field(field, "field");
  o.out = out;
  o.width = width;
  o.height = height;
  o.images = images;
  o.noise = noise;
  o.magnitude = magnitude;
  o.seed = seed;
  py::gil_scoped_release release;
  return write_synthetic_sequence(o).images;
}

// Several runs in one figure, as `trapdem figure`: their gamma_max maps on one colour scale, or
// (grc) their ground reaction curves on one chart. Returns the scale drawn (None for the curves)
// and the curves' legend entries (None for the maps).
py::dict figure(const std::vector<std::string>& folders, const std::string& out, bool grc,
                const std::vector<std::string>& labels, const std::string& at, const std::string& reference,
                const std::string& view, double max_strain) {
  const std::vector<fs::path> dirs(folders.begin(), folders.end());
  py::dict d;
  if (grc) {
    std::vector<std::string> legend;
    {
      py::gil_scoped_release release;
      legend = write_ground_reaction_overlay(out, dirs, labels);
    }
    d["max_strain"] = py::none();
    d["legend"] = legend;
    return d;
  }
  RunPanelOptions o;
  o.at = at;
  o.reference = reference;
  o.view = view;
  o.labels = labels;
  o.max_strain = max_strain;
  RunPanel panel;
  {
    py::gil_scoped_release release;
    panel = write_strain_panel_of_runs(out, dirs, o);
  }
  d["max_strain"] = panel.max_strain;
  d["legend"] = py::none();
  return d;
}

// A study (docs/study.md) run, resumed or reported into `out`, as `trapdem study`.
py::dict study(const std::string& file, const std::string& scale_name, const std::string& out_dir,
               const std::string& presets, int threads, bool quiet, bool report_only, double stop_after_seconds,
               const std::vector<std::string>& cases, const std::vector<std::uint64_t>& seeds) {
  const StudyDefinition definition = load_study(file);
  const StudyScale& scale = definition.scale(scale_name.empty() ? definition.default_scale : scale_name);
  const fs::path out = out_dir.empty() ? fs::path("trapdem-out") / (definition.name + "-" + scale.name) : fs::path(out_dir);
  const LineSink terminal = python_terminal();
  py::dict d;
  d["out"] = out.string();
  {
    py::gil_scoped_release release;
    if (report_only) {
      if (!holds_study(out)) throw InputError(fmt::format("report only: {} holds no study", out.string()));
      claim_study_folder(definition, scale, out);
    } else if (StudyRunSettings settings{presets, threads, quiet, terminal, stop_after_seconds, {cases, seeds}};
               !run_study_in_folder(definition, scale, out, settings)) {
      py::gil_scoped_acquire acquire;
      d["finished"] = false;
      return d;
    }
    const fs::path page = write_study_outputs(definition, scale, out, quiet, presets, plot::FigureFormat::png, terminal);
    py::gil_scoped_acquire acquire;
    d["report"] = page.string();
  }
  d["finished"] = true;
  return d;
}

}  // namespace

PYBIND11_MODULE(_trapdem, m) {
  m.doc() = "trapdem's library calls (use the trapdem package, which wraps them)";
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<FileError>(m, "FileError", PyExc_OSError);
  py::register_exception<SimulationError>(m, "SimulationError", PyExc_RuntimeError);
  m.def("run", &run, py::arg("config_text"), py::arg("config_name"), py::arg("config_file"), py::arg("overrides"),
        py::arg("out"), py::arg("resume"), py::arg("allowed_changes"), py::arg("threads"), py::arg("quiet"),
        py::arg("stop_after_seconds"));
  m.def("analyze", &analyze, py::arg("dir"), py::arg("at"), py::arg("reference"), py::arg("view"),
        py::arg("incremental"), py::arg("smoothing"), py::arg("write"), py::arg("figures"), py::arg("format"));
  m.def("field_history", &field_history_file, py::arg("file"));
  m.def("element", &element, py::arg("config_file"), py::arg("overrides"), py::arg("out"), py::arg("threads"));
  m.def("piv", &piv, py::arg("images"), py::arg("out"), py::arg("subset"), py::arg("step"), py::arg("threads"),
        py::arg("scale"), py::arg("origin"), py::arg("figures"));
  m.def("figure", &figure, py::arg("folders"), py::arg("out"), py::arg("grc"), py::arg("labels"), py::arg("at"),
        py::arg("reference"), py::arg("view"), py::arg("max_strain"));
  m.def("study", &study, py::arg("file"), py::arg("scale"), py::arg("out"), py::arg("presets"), py::arg("threads"),
        py::arg("quiet"), py::arg("report_only"), py::arg("stop_after_seconds"), py::arg("cases"), py::arg("seeds"));
  m.def("build_info", [] {
    const BuildInfo& build = trapdem::build_info();
    py::dict d;
    d["commit"] = std::string(build.commit);
    d["modified"] = build.modified;
    d["description"] = describe_build();
    d["cpu"] = describe_cpu();
    return d;
  });
  m.def("synth", &synth, py::arg("field"), py::arg("out"), py::arg("width"), py::arg("height"), py::arg("images"),
        py::arg("noise"), py::arg("magnitude"), py::arg("seed"));
}
