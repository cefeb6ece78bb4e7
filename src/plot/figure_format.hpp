#pragma once
// The file formats a figure is written in: PNG (a raster image), SVG and PDF (vector: lines and
// text stay sharp at any size; photographs inside a figure stay raster images, embedded). One rule
// for every command: a command that writes one figure file takes the format from that file's
// extension (`trapdem figure --out panel.pdf`, `trapdem compare --out overlay.svg`); a command that
// writes a folder of figures takes `--format png|svg|pdf` (`trapdem analyze`, `trapdem piv`).
#include <filesystem>
#include <string>

namespace trapdem::plot {

enum class FigureFormat { png, svg, pdf };

// "png", "svg" or "pdf" (case-insensitive); InputError naming `what` (e.g. "--format") otherwise.
FigureFormat parse_figure_format(const std::string& text, const std::string& what = "--format");

// The format a path's extension names (.png, .svg, .pdf, any case); InputError naming the path
// otherwise.
FigureFormat figure_format_of(const std::filesystem::path& path);

// ".png", ".svg" or ".pdf".
std::string extension_of(FigureFormat format);

// `path` with the format's extension (replacing any).
std::filesystem::path with_format(std::filesystem::path path, FigureFormat format);

}  // namespace trapdem::plot
