#include "plot/figure_format.hpp"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem::plot {

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool named(const std::string& text, FigureFormat& format) {
  const std::string t = lower(text);
  if (t == "png") format = FigureFormat::png;
  else if (t == "svg") format = FigureFormat::svg;
  else if (t == "pdf") format = FigureFormat::pdf;
  else return false;
  return true;
}

}  // namespace

FigureFormat parse_figure_format(const std::string& text, const std::string& what) {
  FigureFormat f{};
  if (!named(text, f)) throw InputError(fmt::format("{} '{}': expected png, svg or pdf", what, text));
  return f;
}

FigureFormat figure_format_of(const std::filesystem::path& path) {
  const std::string ext = path.extension().string();
  FigureFormat f{};
  if (ext.size() < 2 || !named(ext.substr(1), f)) {
    throw InputError(fmt::format("{}: a figure file ends in .png, .svg or .pdf (the extension picks the format)",
                                 path.string()));
  }
  return f;
}

std::string extension_of(FigureFormat format) {
  switch (format) {
    case FigureFormat::svg: return ".svg";
    case FigureFormat::pdf: return ".pdf";
    case FigureFormat::png: break;
  }
  return ".png";
}

std::filesystem::path with_format(std::filesystem::path path, FigureFormat format) {
  return path.replace_extension(extension_of(format));
}

}  // namespace trapdem::plot
