#pragma once
// What `trapdem analyze` writes into DIR/analysis/: fields.h5 (nodes, triangles and their
// strains, the vertical displacement grid, the band traces) with its XDMF companion fields.xmf
// (ParaView opens it as a triangle mesh coloured by strain), metrics.json, and the short metrics
// table printed on the terminal. Layout: docs/analysis.md.
#include <filesystem>
#include <string>

#include "analysis/analysis_run.hpp"
#include "core/json.hpp"

namespace trapdem {

// Every metric with its inputs (at, reference, view, ...). NaN values are written as null.
Json metrics_json(const AnalysisResult& result);

// fields.h5 and fields.xmf in `dir` (created if absent), each written atomically.
void write_fields(const std::filesystem::path& dir, const AnalysisResult& result);
// The XDMF text for fields.h5 (named h5_name relative to the .xmf file).
std::string fields_xdmf(const AnalysisResult& result, const std::string& h5_name);

// metrics.json in `dir`, atomically.
void write_metrics(const std::filesystem::path& dir, const AnalysisResult& result);

// A few lines: bands (angle, base angle, height, width), zone of influence, triangles.
std::string metrics_table(const AnalysisResult& result);

}  // namespace trapdem
