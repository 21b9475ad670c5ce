// SPDX-License-Identifier: Apache-2.0
// First-order low-pass filter y += alpha (x - y), the filter the simulated controller applies to
// commands (setFilters) and to measured torques (SetTorqueFilterCutOffFrequency).
#pragma once

#include <cmath>

namespace xmate::sim {

// Smoothing factor of a first-order low-pass with cut-off `hz` sampled every `dt` seconds
// (exact discretisation of 1 / (1 + s / (2 pi hz))): 1 means no filtering.
inline double lowPassAlpha(double hz, double dt) {
  constexpr double kTwoPi = 6.283185307179586;
  return 1.0 - std::exp(-kTwoPi * hz * dt);
}

// One filter step on any Eigen vector (or double): y <- y + alpha (x - y).
template <class T>
void lowPassStep(T& y, const T& x, double alpha) {
  y = y + alpha * (x - y);
}

}  // namespace xmate::sim
