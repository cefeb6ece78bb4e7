#pragma once
// displacements.csv of issue 5: one row per image and subset, header
//   image,x_px,y_px,u_px,v_px,zncc,valid
// image numbered from 1 (image 1 is the first photograph, with zero displacement), x and y the
// subset centre in image 1 (px), u and v its total displacement from image 1 (px, x right, y
// down; "nan" where not measured), zncc against the reference image in use, valid 1 or 0.
#include <filesystem>
#include <ostream>

#include "piv/piv_result.hpp"

namespace trapdem {

void write_displacements_csv(const PivResult& result, std::ostream& out);

// Throws InputError if the file cannot be written.
void write_displacements_csv(const PivResult& result, const std::filesystem::path& file);

}  // namespace trapdem
