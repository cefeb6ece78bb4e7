// The field history (src/analysis/field_history.hpp): every snapshot's settlement and strain on one
// grid. Analytic: a deformation whose gradient grows linearly with the trapdoor travel, so each
// layer's fields are known exactly; the file written and read back; bad files refused.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "analysis_test_support.hpp"
#include "analysis/field_history.hpp"
#include "core/errors.hpp"
#include "io/hdf5_file.hpp"
#include "../scratch_dir.hpp"

using namespace trapdem;
namespace fs = std::filesystem;

namespace {

// Per metre of trapdoor travel: simple shear du/dz and vertical compression -dw/dz.
constexpr double kShearPerTravel = 0.5;
constexpr double kCompressionPerTravel = 0.2;
const std::vector<double> kTravel{0.0, 0.002, 0.004, 0.006};  // m, one snapshot each

// A jittered lattice of 2 mm particles, ids 1000, 1001, ..., at travel delta: u = s z, w = -c z with
// s and c proportional to delta, a uniform deformation (constant-strain triangles are exact for it).
AnalysisFrame frame(std::size_t k) {
  static const auto nodes = test::jittered_hex_lattice(0.001, 0.099, 0.001, 0.06, 0.002, 0.2, 11);
  const double delta = kTravel[k];
  AnalysisFrame f{"00000" + std::to_string(k), delta, {}};
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    const double x = nodes[n].x, z = nodes[n].z;
    f.snapshot.id.push_back(1000 + static_cast<std::int64_t>(n));
    f.snapshot.position.push_back({x + kShearPerTravel * delta * z, 0.009, z - kCompressionPerTravel * delta * z});
    f.snapshot.radius.push_back(0.001);
  }
  return f;
}

const SpecimenGeometry kGeometry{"history", 0.1, 0.01, 0.07, {0.05, 0.03, 0.0}};

// Largest |value - expected(x, z)| over the defined (finite) nodes of one layer, and their count.
struct LayerError {
  double worst = 0.0;
  std::size_t defined = 0;
};
LayerError layer_error(const FieldHistory& h, const FloatStack& stack, std::size_t layer,
                       const std::function<double(double, double)>& expected) {
  LayerError e;
  for (std::size_t j = 0; j < h.grid.nz; ++j)
    for (std::size_t i = 0; i < h.grid.nx; ++i) {
      const double v = stack.value[(layer * stack.rows + j) * stack.columns + i];
      if (!std::isfinite(v)) continue;
      ++e.defined;
      e.worst = std::max(e.worst, std::fabs(v - expected(h.grid.x(i), h.grid.z(j))));
    }
  return e;
}

FieldHistory history_from(double reference, double spacing = 0.0) {
  AnalysisSettings settings;
  settings.reference = reference;
  return field_history(kTravel, frame, kGeometry, settings, spacing);
}

}  // namespace

// Each layer holds the deformation from the reference to its snapshot: w = -c z exactly (linear
// inside each triangle), gamma_max = sqrt(c^2 + s^2) and e_vol = c in every triangle (White &
// Bolton 2004, eq. 3; compression positive). Tolerances: float32 storage (6e-8 relative) of values
// up to 1e-3, so 1e-9 absolute; the strains are exact to rounding for a uniform field.
TEST(FieldHistory, EachLayerHoldsTheUniformDeformationSinceTheReference) {
  const FieldHistory h = history_from(0.0);
  ASSERT_EQ(h.layers(), 3u);
  EXPECT_EQ(h.reference_label, "000000");
  EXPECT_EQ(h.labels, (std::vector<std::string>{"000001", "000002", "000003"}));
  EXPECT_EQ(h.trapdoor_displacement, (std::vector<double>{0.002, 0.004, 0.006}));
  EXPECT_DOUBLE_EQ(h.grid.spacing, h.mean_diameter);  // default: one mean diameter
  EXPECT_NEAR(h.mean_diameter, 0.002, 1e-12);
  for (std::size_t layer = 0; layer < h.layers(); ++layer) {
    const double s = kShearPerTravel * h.trapdoor_displacement[layer];
    const double c = kCompressionPerTravel * h.trapdoor_displacement[layer];
    const LayerError w = layer_error(h, h.vertical_displacement, layer, [&](double, double z) { return -c * z; });
    const LayerError g =
        layer_error(h, h.gamma_max, layer, [&](double, double) { return std::sqrt(c * c + s * s); });
    const LayerError e = layer_error(h, h.volumetric_strain, layer, [&](double, double) { return c; });
    test::report("vertical displacement (m)", w.worst, 1e-9);
    EXPECT_LT(w.worst, 1e-9);
    EXPECT_LT(g.worst, 1e-9);
    EXPECT_LT(e.worst, 1e-9);
    // Most of the grid lies inside the kept triangles (the lattice spans the grid's bounding box).
    EXPECT_GT(w.defined, h.grid.nx * h.grid.nz * 8 / 10);
    EXPECT_EQ(g.defined, w.defined);
  }
}

TEST(FieldHistory, ALaterReferenceAndAGivenSpacing) {
  const FieldHistory h = history_from(0.002, 0.003);
  ASSERT_EQ(h.layers(), 2u);  // 4 and 6 mm, each against 2 mm
  EXPECT_EQ(h.reference_label, "000001");
  EXPECT_DOUBLE_EQ(h.grid.spacing, 0.003);
  for (std::size_t layer = 0; layer < h.layers(); ++layer) {
    const double travel = h.trapdoor_displacement[layer] - 0.002;
    const double c = kCompressionPerTravel * travel, s = kShearPerTravel * travel;
    // The gradient with respect to the reference's positions is A (delta - delta_ref) (I + A
    // delta_ref)^-1, A the gradient per metre of travel: the increment's strain to within a
    // relative |A delta_ref| ~ 1e-3, so 1 %.
    const LayerError g = layer_error(h, h.gamma_max, layer, [&](double, double) { return std::sqrt(c * c + s * s); });
    EXPECT_LT(g.worst, 0.01 * std::sqrt(c * c + s * s));
  }
}

TEST(FieldHistory, WrittenAndReadBackUnchanged) {
  const test::ScratchDir dir("trapdem-field-history");
  const FieldHistory h = history_from(0.0);
  const fs::path file = dir / "analysis" / "field_history.h5";
  write_field_history(file, h);
  const FieldHistory back = read_field_history(file);
  EXPECT_EQ(back.case_name, "history");
  EXPECT_EQ(back.view, h.view);
  EXPECT_EQ(back.labels, h.labels);
  EXPECT_EQ(back.trapdoor_displacement, h.trapdoor_displacement);
  EXPECT_EQ(back.matched_particles, h.matched_particles);
  EXPECT_EQ(back.grid.nx, h.grid.nx);
  EXPECT_EQ(back.grid.nz, h.grid.nz);
  EXPECT_DOUBLE_EQ(back.grid.x0, h.grid.x0);
  EXPECT_DOUBLE_EQ(back.grid.spacing, h.grid.spacing);
  ASSERT_EQ(back.gamma_max.value.size(), h.gamma_max.value.size());
  for (std::size_t k = 0; k < h.gamma_max.value.size(); ++k) {
    const float a = h.vertical_displacement.value[k], b = back.vertical_displacement.value[k];
    ASSERT_TRUE((std::isnan(a) && std::isnan(b)) || a == b) << "node " << k;
  }
}

TEST(FieldHistory, NoSnapshotAfterTheReferenceIsAnInputError) {
  AnalysisSettings settings;
  settings.reference = 0.006;
  EXPECT_THROW(field_history(kTravel, frame, kGeometry, settings), InputError);
  EXPECT_THROW(field_history({0.0}, frame, kGeometry, AnalysisSettings{}), InputError);
}

TEST(FieldHistory, AFileOfAnotherKindOrShapeIsRefusedByName) {
  const test::ScratchDir dir("trapdem-field-history");
  const fs::path other = dir / "other.h5";
  {
    Hdf5File f = Hdf5File::create(other);
    f.set_string_attribute("format", "trapdem-analysis-fields");
    f.close();
  }
  try {
    read_field_history(other);
    FAIL() << "a file of another format was read";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find(other.string() + ": not a field history"), std::string::npos) << e.what();
  }
  // A layer stack that does not fit the grid.
  FieldHistory h = history_from(0.0);
  h.gamma_max.layers = 1;
  h.gamma_max.value.resize(h.grid.nx * h.grid.nz);
  const fs::path bad = dir / "bad.h5";
  write_field_history(bad, h);
  try {
    read_field_history(bad);
    FAIL() << "a stack of the wrong shape was read";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("/gamma_max is 1 x"), std::string::npos) << e.what();
  }
}
