// SPDX-License-Identifier: Apache-2.0
// AutoScale (auto_scale.h): grow at once, shrink late, keep a margin.
#include "plots/auto_scale.h"

#include <algorithm>
#include <cmath>

namespace rci::ui::plots {

namespace {
constexpr double kMargin = 0.08;         // fraction of the data span added on each side
constexpr double kShrinkBelow = 1.0 / 3;  // shrink when the data use less than this of the axis
}  // namespace

bool AutoScale::update(double data_min, double data_max) {
  if (!std::isfinite(data_min) || !std::isfinite(data_max) || data_max < data_min) return false;
  const bool outside = !valid_ || data_min < lower_ || data_max > upper_;
  const bool too_loose = valid_ && (data_max - data_min) < kShrinkBelow * (upper_ - lower_) &&
                         (upper_ - lower_) > min_span_ * 1.5;
  if (!outside && !too_loose) return false;
  fit(data_min, data_max);
  valid_ = true;
  return true;
}

void AutoScale::fit(double data_min, double data_max) {
  const double span = std::max(data_max - data_min, min_span_);
  const double centre = 0.5 * (data_min + data_max);
  const double half = 0.5 * span * (1 + 2 * kMargin);
  lower_ = centre - half;
  upper_ = centre + half;
}

}  // namespace rci::ui::plots
