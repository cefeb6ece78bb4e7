#include "piv/piv_result.hpp"

namespace trapdem {

std::string_view to_string(SubsetStatus status) {
  switch (status) {
    case SubsetStatus::valid: return "valid";
    case SubsetStatus::low_texture: return "low_texture";
    case SubsetStatus::low_correlation: return "low_correlation";
    case SubsetStatus::not_converged: return "not_converged";
    case SubsetStatus::left_image: return "left_image";
    case SubsetStatus::lost: return "lost";
  }
  return "unknown";
}

std::size_t count_valid(const PivResult& result, std::size_t k) {
  std::size_t n = 0;
  for (const auto& s : result.image.at(k).subset) n += s.is_valid() ? 1 : 0;
  return n;
}

}  // namespace trapdem
