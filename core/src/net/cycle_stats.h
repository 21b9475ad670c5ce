// SPDX-License-Identifier: Apache-2.0
// Timing statistics of a periodic loop: period min/mean/max and percentiles from a 1 us histogram,
// late cycles and lost cycles. record() is allocation-free and O(1) (real-time safe); summary()
// is for readers (copy the object or call it on the owning thread).
#pragma once

#include <array>
#include <cstdint>

namespace xmate::net {

struct CycleSummary {
  uint64_t cycles = 0;       // periods recorded
  double min_us = 0, mean_us = 0, max_us = 0;
  double p50_us = 0, p99_us = 0, p999_us = 0;
  double jitter_p99_us = 0;  // p99 of |period - nominal|
  uint64_t late = 0;         // periods longer than the late threshold
  uint64_t lost = 0;         // cycles reported lost (no datagram / no answer)
};

class CycleStats {
 public:
  // nominal_us: the intended period; late_us: a period above this counts as late.
  explicit CycleStats(double nominal_us = 1000.0, double late_us = 1500.0)
      : nominal_us_(nominal_us), late_us_(late_us) {}

  void record(int64_t period_ns);
  void recordLost(uint64_t n = 1) { lost_ += n; }
  void reset();
  CycleSummary summary() const;

 private:
  static constexpr int kBuckets = 20001;  // 0..20000 us in 1 us steps; the last bucket is overflow
  double nominal_us_, late_us_;
  std::array<uint32_t, kBuckets> histogram_{};
  std::array<uint32_t, kBuckets> jitter_{};
  uint64_t count_ = 0, late_ = 0, lost_ = 0;
  double sum_us_ = 0, min_us_ = 0, max_us_ = 0;
};

}  // namespace xmate::net
