// SPDX-License-Identifier: Apache-2.0
// Comparisons the tests of every area make on joints, poses and states: the largest joint
// difference, the distance between two TCP positions, whether any error bit is set.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include <xmate/rci_types.h>

namespace rci_test {

// The largest |a[i] - b[i]| over the first n elements.
template <size_t N>
double maxAbsDiff(const std::array<double, N>& a, const std::array<double, N>& b, size_t n = N) {
  double m = 0;
  for (size_t i = 0; i < n; ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

// The distance between the positions of two poses (4x4 row-major, m).
inline double distance(const std::array<double, 16>& a, const std::array<double, 16>& b) {
  return std::hypot(a[3] - b[3], a[7] - b[7], a[11] - b[11]);
}

// Whether the state reports any of the controller's error bits.
inline bool anyError(const RCI::robot::RobotState& s) {
  return std::any_of(s.errors.begin(), s.errors.end(), [](bool e) { return e; });
}

}  // namespace rci_test
