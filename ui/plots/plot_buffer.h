// SPDX-License-Identifier: Apache-2.0
// PlotBuffer: the time-indexed ring of recorded samples (docs/architecture.md, "Live plots at 1 kHz"): one time
// column and up to kChannelCount value columns (those of the signals the arm offers), preallocated for a
// number of seconds; push() never allocates.
#pragma once

#include <array>
#include <limits>
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
  // Room for seconds * rate_hz samples (at least one), of the channels given (empty: every channel).
  // A channel not kept reads NaN and has no spans. Any thread (allocates).
  PlotBuffer(double seconds, double rate_hz, const std::vector<int>& kept_channels = {});

  int capacity() const { return capacity_; }
  int size() const { return size_; }
  bool empty() const { return size_ == 0; }
  void clear();

  // Appends one sample, overwriting the oldest when full. Times must not decrease: a sample older
  // than the newest is refused (returns false) so the window queries stay binary searches.
  // The owner's thread; real-time safe (no allocation, no lock).
  bool push(double time, const ChannelValues& values);

  bool keeps(int channel) const { return column_[static_cast<std::size_t>(channel)] >= 0; }
  double time(int index) const { return times_[slot(index)]; }
  double value(int channel, int index) const {
    return keeps(channel) ? values_[channelBase(channel) + slot(index)] : std::numeric_limits<double>::quiet_NaN();
  }
  double oldestTime() const { return time(0); }
  double newestTime() const { return time(size_ - 1); }

  // The samples with from <= time <= to.
  IndexRange window(double from, double to) const;
  // The range as at most two contiguous runs of storage (the ring may wrap); returns how many.
  int spans(int channel, IndexRange range, std::array<SampleSpan, 2>& out) const;
  // A new buffer holding exactly the samples of range (capacity = range.count(), at least 1).
  PlotBuffer copyRange(IndexRange range) const;

 private:
  PlotBuffer(int capacity, const std::vector<int>& kept_channels);
  int slot(int index) const;
  int firstAtOrAfter(double t) const;
  int firstAfter(double t) const;
  std::size_t channelBase(int channel) const {
    return static_cast<std::size_t>(column_[static_cast<std::size_t>(channel)]) * capacity_;
  }

  int capacity_ = 1;
  int size_ = 0;
  int head_ = 0;  // storage slot of the oldest sample
  std::vector<double> times_;
  std::array<int, kChannelCount> column_{};  // channel -> its column in values_, -1: not kept
  std::vector<int> kept_;                     // the kept channels, ascending
  std::vector<double> values_;  // column-major: channel c's ring starts at column_[c] * capacity_
};

// The channel values of one state sample; tau_ext are the external joint torques (J^T F). Fills the
// xMate's signals only. Any thread, real-time safe.
void channelsOf(const xmate::client::StateSample& sample, const std::array<double, 7>& tau_ext,
                ChannelValues& out);

}  // namespace rci::ui::plots
