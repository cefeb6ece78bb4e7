#pragma once
// What `trapdem analyze` writes into DIR/analysis/: fields.h5 (nodes, triangles and their
// strains, the vertical displacement grid, the band traces) with its XDMF companion fields.xmf
// (ParaView opens it as a triangle mesh coloured by strain), metrics.json, and the short metrics
// table printed on the terminal. Layout: docs/analysis.md; the files' names:
// src/experiment/analysis_folder.hpp (the writers here take paths).
#include <filesystem>
#include <string>

#include "analysis/analysis_run.hpp"
#include "core/json.hpp"

namespace trapdem {

// Every metric with its inputs (at, reference, view, ...). NaN values are written as null.
Json metrics_json(const AnalysisResult& result);

// The fields (HDF5) at `h5` and their XDMF companion at `xmf` in the same folder (it names `h5` by
// its file name; std::invalid_argument otherwise), each written atomically, the folder created if
// absent. The file names are the caller's (src/experiment/analysis_folder.hpp).
void write_fields(const std::filesystem::path& h5, const std::filesystem::path& xmf, const AnalysisResult& result);
// The XDMF text for the fields file (named h5_name relative to the .xmf file).
std::string fields_xdmf(const AnalysisResult& result, const std::string& h5_name);

// metrics_json(result) at `path`, atomically.
void write_metrics(const std::filesystem::path& path, const AnalysisResult& result);

// A few lines: bands (angle, base angle, height, width), zone of influence, triangles.
std::string metrics_table(const AnalysisResult& result);

}  // namespace trapdem
