// SPDX-License-Identifier: Apache-2.0
// Watchdog (soak_watchdog.h): a thread that waits for the armed deadline and closes the session.
#include "soak/soak_watchdog.h"

#include "client/connection.h"

namespace rci_cli::soak {

Watchdog::Watchdog(xmate::Robot& robot) : robot_(robot), thread_([this] { run(); }) {}

Watchdog::~Watchdog() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void Watchdog::arm(std::chrono::seconds limit) {
  {
    std::lock_guard lock(mutex_);
    deadline_ = std::chrono::steady_clock::now() + limit;
    fired_ = false;
  }
  changed_.notify_all();
}

bool Watchdog::disarm() {
  std::lock_guard lock(mutex_);
  deadline_.reset();
  return fired_;
}

void Watchdog::run() {
  std::unique_lock lock(mutex_);
  while (!stop_) {
    if (!deadline_) {
      changed_.wait(lock);
      continue;
    }
    const auto deadline = *deadline_;
    if (changed_.wait_until(lock, deadline) == std::cv_status::no_timeout) continue;
    if (deadline_ != deadline) continue;  // disarmed or armed again meanwhile
    deadline_.reset();
    fired_ = true;
    lock.unlock();
    robot_.connection().close();  // the motion ends with "the session was closed"
    lock.lock();
  }
}

}  // namespace rci_cli::soak
