// SPDX-License-Identifier: Apache-2.0
// PlotBuffer (plot_buffer.h): the ring, its window queries, and the state-sample-to-channels copy.
#include "plots/plot_buffer.h"

#include <algorithm>
#include <cmath>

namespace rci::ui::plots {

PlotBuffer::PlotBuffer(double seconds, double rate_hz, const std::vector<int>& kept_channels)
    : PlotBuffer(static_cast<int>(std::max(1.0, std::ceil(seconds * rate_hz))), kept_channels) {}

PlotBuffer::PlotBuffer(int capacity, const std::vector<int>& kept_channels)
    : capacity_(std::max(1, capacity)), times_(static_cast<std::size_t>(capacity_)) {
  column_.fill(-1);
  for (int c : kept_channels)
    if (c >= 0 && c < kChannelCount) column_[static_cast<std::size_t>(c)] = 0;
  for (int c = 0; c < kChannelCount; ++c) {
    if (!kept_channels.empty() && column_[static_cast<std::size_t>(c)] < 0) continue;
    column_[static_cast<std::size_t>(c)] = static_cast<int>(kept_.size());
    kept_.push_back(c);
  }
  values_.resize(static_cast<std::size_t>(capacity_) * kept_.size());
}

void PlotBuffer::clear() {
  size_ = 0;
  head_ = 0;
}

bool PlotBuffer::push(double t, const ChannelValues& values) {
  if (size_ > 0 && t < newestTime()) return false;
  int at = 0;
  if (size_ < capacity_) {
    at = slot(size_);
    ++size_;
  } else {
    at = head_;
    head_ = (head_ + 1) % capacity_;
  }
  times_[static_cast<std::size_t>(at)] = t;
  for (int c : kept_) values_[channelBase(c) + static_cast<std::size_t>(at)] = values[static_cast<std::size_t>(c)];
  return true;
}

int PlotBuffer::slot(int index) const {
  const int s = head_ + index;
  return s >= capacity_ ? s - capacity_ : s;
}

int PlotBuffer::firstAtOrAfter(double t) const {
  int lo = 0, hi = size_;
  while (lo < hi) {
    const int mid = (lo + hi) / 2;
    if (time(mid) < t) lo = mid + 1; else hi = mid;
  }
  return lo;
}

int PlotBuffer::firstAfter(double t) const {
  int lo = 0, hi = size_;
  while (lo < hi) {
    const int mid = (lo + hi) / 2;
    if (time(mid) <= t) lo = mid + 1; else hi = mid;
  }
  return lo;
}

IndexRange PlotBuffer::window(double from, double to) const {
  if (size_ == 0 || to < from) return {};
  const int first = firstAtOrAfter(from);
  return {first, std::max(first, firstAfter(to))};
}

int PlotBuffer::spans(int channel, IndexRange range, std::array<SampleSpan, 2>& out) const {
  const int first = std::clamp(range.first, 0, size_);
  const int last = std::clamp(range.last, first, size_);
  if (last == first || !keeps(channel)) return 0;
  const int start = slot(first);
  const int run = std::min(last - first, capacity_ - start);
  const double* values = values_.data() + channelBase(channel);
  out[0] = {times_.data() + start, values + start, run};
  if (run == last - first) return 1;
  out[1] = {times_.data(), values, last - first - run};
  return 2;
}

PlotBuffer PlotBuffer::copyRange(IndexRange range) const {
  const int first = std::clamp(range.first, 0, size_);
  const int last = std::clamp(range.last, first, size_);
  PlotBuffer copy(last - first, kept_);
  ChannelValues values{};
  for (int i = first; i < last; ++i) {
    for (int c : kept_) values[static_cast<std::size_t>(c)] = value(c, i);
    copy.push(time(i), values);
  }
  return copy;
}

void channelsOf(const xmate::client::StateSample& sample, const std::array<double, 7>& tau_ext,
                ChannelValues& out) {
  const std::array<const std::array<double, 7>*, 6> sources{
      &sample.q, &sample.q_c, &sample.dq_m, &sample.tau_m, &sample.tau_c, &tau_ext};
  for (int s = 0; s < static_cast<int>(sources.size()); ++s)
    for (int j = 0; j < kJointCount; ++j) out[static_cast<std::size_t>(s * kJointCount + j)] = (*sources[s])[j];
}

}  // namespace rci::ui::plots
