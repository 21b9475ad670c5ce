// SPDX-License-Identifier: Apache-2.0
// rci-cli's commands and the small argument helpers they share. Each command returns the process
// exit code: 0 success, 1 failure at run time, 2 bad arguments (UsageError).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <xmate/types.h>

namespace rci_cli {

// Bad command-line arguments: main() prints the message and the usage text, and exits with 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The arguments after the command words, consumed left to right.
class Args {
 public:
  explicit Args(std::vector<std::string> items) : items_(std::move(items)) {}
  bool done() const { return next_ >= items_.size(); }
  std::string take() { return items_[next_++]; }
  // The value after option `name`; UsageError if missing.
  std::string value(const std::string& name);

 private:
  std::vector<std::string> items_;
  size_t next_ = 0;
};

struct HostPort {
  std::string host;
  uint16_t port = 1337;
};
// "HOST:PORT" or "HOST" (port 1337); UsageError naming `option` when malformed.
HostPort parseHostPort(const std::string& option, const std::string& text);
// An integer in [lo, hi]; UsageError naming `option` otherwise.
long parseInteger(const std::string& option, const std::string& text, long lo, long hi);
// "xmate7_pro" -> XMATE7_PRO; UsageError listing the four names otherwise.
xmate::XmateType parseModel(const std::string& option, const std::string& text);

std::string usage();

int runModel(Args args);        // rci-cli [model NAME]
int runState(Args args);        // rci-cli state --robot HOST:PORT [--count N]
int runDoctor(Args args);       // rci-cli doctor
int runBenchLoop(Args args);    // rci-cli bench loop [--robot sim|HOST:PORT] [--cycles N] [--lockstep]
int runBenchClient(Args args);  // rci-cli bench client [--cycles N]
int runRun(Args args);          // rci-cli run PROGRAM.json --robot sim|HOST:PORT [--model NAME] [--speed R] [--report FILE] [--fast]

}  // namespace rci_cli
