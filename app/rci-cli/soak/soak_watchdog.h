// SPDX-License-Identifier: Apache-2.0
// The soak's guard against a motion that never ends: past its deadline the robot's session is
// closed, which ends any Control() run with the library's own "session closed" exception (docs/
// client.md, "Threads"); the soak then reconnects and goes on. Never fires for motions that end.
#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <thread>

#include <xmate/robot.h>

namespace rci_cli::soak {

class Watchdog {
 public:
  explicit Watchdog(xmate::Robot& robot);
  ~Watchdog();
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;

  void arm(std::chrono::seconds limit);  // from now
  // Stops watching; true if it fired since arm().
  bool disarm();

 private:
  void run();

  xmate::Robot& robot_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::optional<std::chrono::steady_clock::time_point> deadline_;  // guarded by mutex_
  bool fired_ = false;                                              // guarded by mutex_
  bool stop_ = false;                                               // guarded by mutex_
  std::thread thread_;
};

}  // namespace rci_cli::soak
