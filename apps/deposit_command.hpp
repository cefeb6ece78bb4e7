#pragma once
// `trapdem deposit DIR`: the deposit of a run's fill (solid fraction, coordination, surface) at each
// snapshot before the trapdoor moves; prints a table and writes DIR/deposit.json.
#include <string>

namespace trapdem::app {

struct DepositOptions {
  std::string dir;  // a run folder
};

int run_deposit(const DepositOptions& options);

}  // namespace trapdem::app
