// SPDX-License-Identifier: Apache-2.0
// PlotBuffer: the time-indexed ring of recorded samples (docs/architecture.md, "Live plots at 1 kHz"): one time
// column and kChannelCount value columns, preallocated for a number of seconds; push() never allocates.
#pragma once

#include <array>
#include <vector>

#include "client/state_sample.h"
#include "plots/plot_signals.h"

namespace rci::ui::plots {

using ChannelValues = std::array<double, kChannelCount>;

// Logical sample indices [first, last), 0 = the oldest sample held.
struct IndexRange {
  int first = 0;
  int last = 0;
  int count() const { return last - first; }
};

// A contiguous run of one channel's samples in storage.
struct SampleSpan {
  const double* time = nullptr;
  const double* value = nullptr;
  int count = 0;
};

class PlotBuffer {
 public:
  // Room for seconds * rate_hz samples (at least one).
  PlotBuffer(double seconds, double rate_hz);

  int capacity() const { return capacity_; }
  int size() const { return size_; }
  bool empty() const { return size_ == 0; }
  void clear();

  // Appends one sample, overwriting the oldest when full. Times must not decrease: a sample older
  // than the newest is refused (returns false) so the window queries stay binary searches.
  bool push(double time, const ChannelValues& values);

  double time(int index) const { return times_[slot(index)]; }
  double value(int channel, int index) const { return values_[channelBase(channel) + slot(index)]; }
  double oldestTime() const { return time(0); }
  double newestTime() const { return time(size_ - 1); }

  // The samples with from <= time <= to.
  IndexRange window(double from, double to) const;
  // The range as at most two contiguous runs of storage (the ring may wrap); returns how many.
  int spans(int channel, IndexRange range, std::array<SampleSpan, 2>& out) const;
  // A new buffer holding exactly the samples of range (capacity = range.count(), at least 1).
  PlotBuffer copyRange(IndexRange range) const;

 private:
  explicit PlotBuffer(int capacity);
  int slot(int index) const;
  int firstAtOrAfter(double t) const;
  int firstAfter(double t) const;
  std::size_t channelBase(int channel) const { return static_cast<std::size_t>(channel) * capacity_; }

  int capacity_ = 1;
  int size_ = 0;
  int head_ = 0;  // storage slot of the oldest sample
  std::vector<double> times_;
  std::vector<double> values_;  // channel-major: channel c's ring starts at c * capacity_
};

// The channel values of one state sample; tau_ext are the external joint torques (J^T F).
void channelsOf(const xmate::client::StateSample& sample, const std::array<double, 7>& tau_ext,
                ChannelValues& out);

}  // namespace rci::ui::plots
