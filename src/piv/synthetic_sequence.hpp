#pragma once
// A synthetic speckle sequence under a known displacement field, with its truth, in a folder: what
// `trapdem synth` writes (image_001.png ..., truth.csv; docs/piv.md), for testing PIV against a
// known answer from any front end.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace trapdem {

// The prescribed fields: a rigid shift (u, 0.6 u) px; a uniform strain (exx, -exx) and a simple
// shear gamma about the image centre; a trapdoor-like settlement trough (px).
enum class SyntheticField { rigid, strain, shear, trapdoor };

// "rigid", "strain", "shear" or "trapdoor"; InputError naming `what` otherwise.
SyntheticField parse_synthetic_field(const std::string& text, const std::string& what);
const char* synthetic_field_name(SyntheticField field);

struct SyntheticSequenceOptions {
  SyntheticField field = SyntheticField::rigid;
  std::filesystem::path out;
  int width = 512, height = 512;   // px, at least 16 each
  int images = 2;                  // including the undeformed image 1
  double noise = 2.0;              // grey levels (standard deviation)
  std::optional<double> magnitude;  // of the last image: px (rigid, trapdoor) or strain (strain, shear);
                                    // default 2.5 px, 0.01, 0.01, 8 px
  std::uint64_t seed = 1;
};

struct SyntheticSequence {
  int images = 0;
  double magnitude = 0.0;  // of the last image, as used
};

// Throws InputError for options out of range, FileError when the folder cannot be written.
SyntheticSequence write_synthetic_sequence(const SyntheticSequenceOptions& options);

}  // namespace trapdem
