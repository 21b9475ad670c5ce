// SPDX-License-Identifier: Apache-2.0
// AutoScale: a value-axis range that follows the data with hysteresis (grows at once, shrinks only when
// the data use less than a third of it), so the axis does not jitter from frame to frame.
#pragma once

namespace rci::ui::plots {

class AutoScale {
 public:
  // min_span: the smallest range shown (a constant signal gets this much around it).
  explicit AutoScale(double min_span = 0.02) : min_span_(min_span) {}

  // Feeds the data range of this frame; returns true if the axis range changed.
  bool update(double data_min, double data_max);
  void reset() { valid_ = false; }
  double lower() const { return lower_; }
  double upper() const { return upper_; }

 private:
  void fit(double data_min, double data_max);

  double min_span_;
  double lower_ = -1, upper_ = 1;
  bool valid_ = false;
};

}  // namespace rci::ui::plots
