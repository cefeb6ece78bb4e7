#include "deposit_command.hpp"

#include <fmt/format.h>

#include "study/deposit_report.hpp"

namespace trapdem::app {

int run_deposit(const DepositOptions& options) {
  const auto deposits = measure_run_deposit(options.dir);
  fmt::print("{}", deposit_table(deposits));
  fmt::print("wrote {}\n", write_deposit_json(options.dir, deposits).string());
  return 0;
}

}  // namespace trapdem::app
