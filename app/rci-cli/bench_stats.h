// SPDX-License-Identifier: Apache-2.0
// What rci-cli's per-cycle benchmarks share (bench client, bench rsi): median / p99 / max of the
// measured cycle times, the table's rows, and the loopback sink their sends go to.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "net/udp_socket.h"

namespace rci_cli {

struct Percentiles {
  double median = 0, p99 = 0, max = 0;  // us
};

// Sorts `ns` (nanoseconds per cycle) and returns its median, p99 and max in microseconds.
inline Percentiles percentilesOf(std::vector<int64_t>& ns) {
  if (ns.empty()) return {};
  std::sort(ns.begin(), ns.end());
  auto at = [&](double f) { return double(ns[std::min(ns.size() - 1, size_t(f * double(ns.size())))]) / 1000.0; };
  return {at(0.5), at(0.99), double(ns.back()) / 1000.0};
}

// The table: a header line, then one row per measurement ("  LABEL  median  p99  max").
inline void printPercentilesHeader() { std::printf("  %-52s %9s %9s %9s\n", "(us)", "median", "p99", "max"); }
inline void printPercentilesRow(const char* label, const Percentiles& p) {
  std::printf("  %-52s %9.3f %9.3f %9.3f\n", label, p.median, p.p99, p.max);
}

// Empties the sink socket so the sends never meet a full buffer (outside the timed sections).
inline void drain(xmate::net::UdpSocket& sink) {
  uint8_t buf[2048];
  while (sink.receiveFrom(buf, sizeof buf, nullptr, 0) > 0) {
  }
}

}  // namespace rci_cli
