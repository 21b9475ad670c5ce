// SPDX-License-Identifier: Apache-2.0
// control_command_success_rate: the share of the last 100 expected commands that arrived
// (docs/protocol.md; libfranka uses the same window). Fixed-size ring, no allocation.
#pragma once

#include <array>
#include <cstddef>

namespace xmate::sim {

class SuccessWindow {
 public:
  static constexpr size_t kSize = 100;

  // Forget everything (a new motion starts): the rate reads 1.0 until commands are expected.
  void clear() {
    count_ = 0;
    next_ = 0;
    arrived_ = 0;
  }

  // One expected command: it arrived in time or not.
  void record(bool arrived) {
    if (count_ == kSize) {
      arrived_ -= slots_[next_] ? 1 : 0;
    } else {
      ++count_;
    }
    slots_[next_] = arrived;
    arrived_ += arrived ? 1 : 0;
    next_ = (next_ + 1) % kSize;
  }

  // Arrived / expected over the window; 1.0 when nothing was expected yet.
  double rate() const { return count_ == 0 ? 1.0 : double(arrived_) / double(count_); }

 private:
  std::array<bool, kSize> slots_{};
  size_t count_ = 0;
  size_t next_ = 0;
  size_t arrived_ = 0;
};

}  // namespace xmate::sim
