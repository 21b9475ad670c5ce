// SPDX-License-Identifier: Apache-2.0
// Monotonic time in nanoseconds and absolute sleeps: the time base of both 1 kHz loops.
#pragma once

#include <cstdint>
#include <ctime>

namespace xmate::net {

inline int64_t monotonicNs() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return int64_t(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

// Sleeps until the absolute monotonic time deadline_ns (returns at once if it has passed).
inline void sleepUntilNs(int64_t deadline_ns) {
  timespec ts{};
  ts.tv_sec = deadline_ns / 1'000'000'000;
  ts.tv_nsec = deadline_ns % 1'000'000'000;
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) != 0) {
  }
}

}  // namespace xmate::net
