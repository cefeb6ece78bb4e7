#include "experiment/run_folder.hpp"

#include <fmt/format.h>

#include "core/errors.hpp"
#include "io/config.hpp"

namespace trapdem {

ExperimentConfig RunFolder::read_specimen(const std::filesystem::path& toml, std::string_view needed_for) {
  if (!std::filesystem::exists(toml)) throw InputError(fmt::format("{}: not found; {}", toml.string(), needed_for));
  Config config = Config::load_file(toml.string());
  return ExperimentConfig::specimen_from(config);
}

}  // namespace trapdem
