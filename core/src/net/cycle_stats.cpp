// SPDX-License-Identifier: Apache-2.0
// Histogram bookkeeping and percentile read-out for CycleStats.
#include "net/cycle_stats.h"

#include <algorithm>
#include <cmath>

namespace xmate::net {
namespace {

template <size_t N>
double percentile(const std::array<uint32_t, N>& h, uint64_t count, double fraction) {
  if (count == 0) return 0;
  const uint64_t rank = uint64_t(std::ceil(fraction * double(count)));
  uint64_t seen = 0;
  for (size_t i = 0; i < N; ++i) {
    seen += h[i];
    if (seen >= rank) return double(i);
  }
  return double(N - 1);
}

}  // namespace

void CycleStats::record(int64_t period_ns) {
  const double us = double(period_ns) / 1000.0;
  const int bucket = std::clamp(int(std::lround(us)), 0, kBuckets - 1);
  const int jitter = std::clamp(int(std::lround(std::abs(us - nominal_us_))), 0, kBuckets - 1);
  ++histogram_[bucket];
  ++jitter_[jitter];
  if (count_ == 0) min_us_ = max_us_ = us;
  min_us_ = std::min(min_us_, us);
  max_us_ = std::max(max_us_, us);
  sum_us_ += us;
  ++count_;
  if (us > late_us_) ++late_;
}

void CycleStats::reset() {
  histogram_.fill(0);
  jitter_.fill(0);
  count_ = late_ = lost_ = 0;
  sum_us_ = min_us_ = max_us_ = 0;
}

CycleSummary CycleStats::summary() const {
  CycleSummary s;
  s.cycles = count_;
  s.min_us = min_us_;
  s.max_us = max_us_;
  s.mean_us = count_ ? sum_us_ / double(count_) : 0;
  s.p50_us = percentile(histogram_, count_, 0.5);
  s.p99_us = percentile(histogram_, count_, 0.99);
  s.p999_us = percentile(histogram_, count_, 0.999);
  s.jitter_p99_us = percentile(jitter_, count_, 0.99);
  s.late = late_;
  s.lost = lost_;
  return s;
}

}  // namespace xmate::net
