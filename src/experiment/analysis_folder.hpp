#pragma once
// An analysis folder: every file `trapdem analyze` (and `trapdem compare`'s default figure) writes
// there (docs/analysis.md), named in one place. A run folder's is DIR/analysis (RunFolder::analysis);
// `trapdem analyze --out` puts one anywhere. The writers in src/analysis take these paths.
#include <filesystem>

namespace trapdem {

class AnalysisFolder {
 public:
  explicit AnalysisFolder(std::filesystem::path dir) : dir_(std::move(dir)) {}

  const std::filesystem::path& path() const { return dir_; }

  std::filesystem::path fields_h5() const { return dir_ / "fields.h5"; }    // nodes, triangles, strains, grids
  std::filesystem::path fields_xmf() const { return dir_ / "fields.xmf"; }  // its XDMF companion (ParaView)
  // Every snapshot's fields on one grid (analysis/field_history.hpp).
  std::filesystem::path field_history_h5() const { return dir_ / "field_history.h5"; }
  std::filesystem::path metrics_json() const { return dir_ / "metrics.json"; }
  std::filesystem::path shear_strain_png() const { return dir_ / "shear_strain.png"; }
  std::filesystem::path volumetric_strain_png() const { return dir_ / "volumetric_strain.png"; }
  std::filesystem::path shear_strain_incremental_png() const { return dir_ / "shear_strain_incremental.png"; }
  std::filesystem::path vertical_displacement_png() const { return dir_ / "vertical_displacement.png"; }
  std::filesystem::path particles_png() const { return dir_ / "particles.png"; }
  std::filesystem::path ground_reaction_png() const { return dir_ / "ground_reaction.png"; }
  // `trapdem compare`'s overlay at a trapdoor displacement (m): compare_<mm>mm.png, to 0.1 mm.
  std::filesystem::path compare_png(double trapdoor_displacement) const;

 private:
  std::filesystem::path dir_;
};

}  // namespace trapdem
