// SPDX-License-Identifier: Apache-2.0
// After a motion, both robot families wait the same way for the arm to come to rest at its last
// command: the same tolerance, the same time limit, the settle time in controller cycles.
#pragma once

#include <chrono>
#include <cstdint>
#include <thread>

#include "teach/executor.h"

namespace xmate::teach {

inline constexpr double kSettleTolerance = 5e-5;  // rad: the largest joint error "at rest" allows
inline constexpr int kSettleLimitMs = 1000;       // wall time before the instruction reports it did not settle

// What `read` returns each time the executor looks (every ~1 ms).
struct SettleReading {
  bool at_rest = false;  // at the last command (within kSettleTolerance; the xMate also checks speed)
  double error = 0;      // the largest joint error, rad
  uint64_t cycle = 0;    // the controller's cycle counter
};

// Waits (at most kSettleLimitMs) until the arm is at rest; sets report.settle_time (controller
// cycles x `cycle_s`), or report.settled = false and settle_error. The executor's thread.
template <class Read>
void settle(Read read, double cycle_s, InstructionReport& report) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(kSettleLimitMs);
  const uint64_t first = read().cycle;
  for (;;) {
    const SettleReading r = read();
    report.settle_time = double(r.cycle > first ? r.cycle - first : 0) * cycle_s;
    if (r.at_rest) return;
    if (std::chrono::steady_clock::now() >= end) {
      report.settled = false;
      report.settle_error = r.error;
      return;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

}  // namespace xmate::teach
