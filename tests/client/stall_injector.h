// SPDX-License-Identifier: Apache-2.0
// Test helper: stalls the client's real-time thread ("rci-rt") for a chosen time, as a preemption
// or a slow callback would, without any hook in the product: a signal sent to that thread runs a
// handler that sleeps (nanosleep is async-signal-safe). One injector per process at a time.
#pragma once

#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

namespace xmate { class Robot; }

namespace client_test {

// The kernel thread ids of this process's threads named `name` (from /proc/self/task/*/comm).
std::vector<int> threadsNamed(const char* name);

class StallInjector {
 public:
  StallInjector();   // installs the SIGUSR2 handler
  ~StallInjector();  // restores the previous one
  StallInjector(const StallInjector&) = delete;
  StallInjector& operator=(const StallInjector&) = delete;

  // Stalls every "rci-rt" thread of this process for `ms` milliseconds (returns at once; the stall
  // happens on those threads). False if there is no such thread.
  bool stallRealtimeThread(int ms);
  // How many stalls the handler has completed.
  uint64_t completed() const;
};

// Stalls the robot's real-time thread for `stall_ms` once `at_cycles` controller cycles (message_ids)
// have passed since the first state of the next motion (robot_mode kMove), watching the session's
// newest state (lock-free; the simulator's own locks are not touched). Joins in the destructor.
class StallDuringMotion {
 public:
  StallDuringMotion(xmate::Robot& robot, StallInjector& injector, int at_cycles, int stall_ms);
  ~StallDuringMotion();
  StallDuringMotion(const StallDuringMotion&) = delete;
  StallDuringMotion& operator=(const StallDuringMotion&) = delete;
  // True once the stall was started while the motion was still running.
  bool firedInMotion() const { return fired_in_motion_.load(); }

 private:
  std::atomic<bool> done_{false};
  std::atomic<bool> fired_in_motion_{false};
  std::thread thread_;
};

}  // namespace client_test
