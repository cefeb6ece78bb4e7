#include "study/slurm_options.hpp"

#include <algorithm>
#include <cctype>
#include <regex>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem {

namespace {

constexpr const char* kTimeForms =
    "MM, MM:SS, HH:MM:SS, D-HH, D-HH:MM or D-HH:MM:SS (as sbatch --time takes it, e.g. 12:00:00 or 2-00:00:00)";

// The options the submission writes itself: given again they would contradict it.
constexpr const char* kOwnOptions[] = {"--array", "--dependency", "--cpus-per-task", "--partition", "--time",
                                       "--output", "--error", "--job-name", "--parsable", "-a", "-d", "-c",
                                       "-p", "-t", "-o", "-e", "-J"};

}  // namespace

std::int64_t slurm_time_seconds(const std::string& text) {
  // days-hours[:minutes[:seconds]], or [hours:]minutes[:seconds] (sbatch(1), "-t, --time").
  static const std::regex with_days(R"(^(\d+)-(\d+)(?::(\d+)(?::(\d+))?)?$)");
  static const std::regex without_days(R"(^(\d+)(?::(\d+)(?::(\d+))?)?$)");
  std::smatch m;
  auto number = [&](std::size_t k) -> std::int64_t {
    if (!m[k].matched) return 0;
    if (m[k].length() > 6) throw InputError(fmt::format("--time '{}': {} is too large", text, m[k].str()));
    return std::stoll(m[k].str());
  };
  auto below_60 = [&](std::size_t k, const char* what) {
    if (m[k].matched && number(k) >= 60)
      throw InputError(fmt::format("--time '{}': {} {} is not below 60; expected {}", text, what, m[k].str(), kTimeForms));
  };
  std::int64_t seconds = 0;
  if (std::regex_match(text, m, with_days)) {
    if (number(2) >= 24)
      throw InputError(fmt::format("--time '{}': hours {} are not below 24 after the days; expected {}", text,
                                   m[2].str(), kTimeForms));
    below_60(3, "minutes");
    below_60(4, "seconds");
    seconds = ((number(1) * 24 + number(2)) * 60 + number(3)) * 60 + number(4);
  } else if (std::regex_match(text, m, without_days)) {
    if (m[3].matched) {  // hours:minutes:seconds
      below_60(2, "minutes");
      below_60(3, "seconds");
      seconds = (number(1) * 60 + number(2)) * 60 + number(3);
    } else {  // minutes[:seconds]
      below_60(2, "seconds");
      seconds = number(1) * 60 + number(2);
    }
  } else {
    throw InputError(fmt::format("--time '{}': expected {}", text, kTimeForms));
  }
  if (seconds <= 0)
    throw InputError(fmt::format("--time '{}': a time limit of zero (Slurm would read it as no limit at all); give "
                                 "the limit, or leave --time out for the partition's default", text));
  return seconds;
}

void check_slurm_options(const SlurmOptions& o) {
  if (o.cpus_per_task < 1 || o.cpus_per_task > 4096)
    throw InputError(fmt::format("--cpus-per-task {}: expected a whole number from 1 to 4096 (each array task's "
                                 "run uses that many threads)", o.cpus_per_task));
  if (!o.time.empty()) slurm_time_seconds(o.time);
  static const std::regex partition_name(R"(^[A-Za-z0-9_.\-]+$)");
  if (!o.partition.empty() && !std::regex_match(o.partition, partition_name))
    throw InputError(fmt::format("--partition '{}': expected a partition's name (letters, digits, '-', '_', '.'; "
                                 "`sinfo` lists them)", o.partition));
  for (const std::string& arg : o.sbatch_args) {
    if (arg.size() < 2 || arg[0] != '-' || arg.find_first_of("\n\r") != std::string::npos)
      throw InputError(fmt::format("--sbatch-arg '{}': expected one sbatch option on one line, e.g. "
                                   "--sbatch-arg=--account=geo or --sbatch-arg=--qos=long", arg));
    const std::string name = arg.substr(0, arg.find('='));
    for (const char* own : kOwnOptions)
      if (name == own || (name.size() > 2 && name[1] != '-' && name.substr(0, 2) == own))
        throw InputError(fmt::format("--sbatch-arg '{}': {} is set by trapdem itself (--partition, --time and "
                                     "--cpus-per-task are options of their own; the array, its output and the "
                                     "report's dependency are the submission's)", arg, own));
  }
}

void check_partition_known(const std::string& partition, const std::vector<std::string>& known) {
  if (partition.empty() || std::find(known.begin(), known.end(), partition) != known.end()) return;
  std::string list;
  for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
  throw InputError(fmt::format("--partition '{}': not a partition of this cluster (sinfo lists: {})", partition,
                               list.empty() ? "none" : list));
}

}  // namespace trapdem
