#pragma once
// The element test's files: element.csv (one row per interval of axial strain, per specimen) and
// element.json (settings, each specimen's isotropic state and angles, and per confining stress
// the material's phi'_peak and phi'_cs). docs/element.md lists every column and member.
#include <filesystem>
#include <string>

#include "experiment/element_test.hpp"

namespace trapdem {

std::string element_csv(const ElementResult& result);
std::string element_json(const ElementResult& result);

// The material's angles at one confining stress: phi'_peak of the dense specimen, phi'_cs the
// mean of the dense and loose specimens' (the critical state is where they meet).
struct ElementAngles {
  double confining = 0.0;  // Pa
  double phi_peak = 0.0;   // degrees
  double phi_cs = 0.0;     // degrees
  double phi_cs_gap = 0.0; // degrees, |dense - loose| at the critical state: how far they met
};
std::vector<ElementAngles> element_angles(const ElementResult& result);

// Writes element.csv and element.json into `dir` (atomically).
void write_element_files(const std::filesystem::path& dir, const ElementResult& result);

}  // namespace trapdem
