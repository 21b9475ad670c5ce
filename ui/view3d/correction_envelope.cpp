// SPDX-License-Identifier: Apache-2.0
// The RSI correction envelope of the 3D view (correction_envelope.h).
#include "correction_envelope.h"

#include <algorithm>
#include <cmath>

namespace rci::ui {

namespace {

constexpr double kStepRad = 30.0 * M_PI / 180.0;  // at most this far between sampled values of an axis
constexpr int kMaxLevels = 7;

}  // namespace

CorrectionEnvelope correctionEnvelope(const ArmPoser& poser, const std::array<double, 6>& q_on,
                                      const std::array<double, 6>& lower, const std::array<double, 6>& upper) {
  CorrectionEnvelope out;
  const int dof = std::min(poser.dof(), 6);
  if (dof <= 0) return out;
  std::array<double, 7> start{};
  for (int i = 0; i < dof; ++i) start[size_t(i)] = q_on[size_t(i)];
  const Eigen::Vector3d s = poser.flangePosition(start);
  // Per axis: its reachable range (within the hardware limits) and how many values of it to sample.
  std::array<double, 6> from{}, to{};
  std::array<int, 6> levels{};
  for (int i = 0; i < dof; ++i) {
    const size_t a = size_t(i);
    from[a] = std::clamp(q_on[a] + std::min(lower[a], 0.0), poser.lower(i), poser.upper(i));
    to[a] = std::clamp(q_on[a] + std::max(upper[a], 0.0), poser.lower(i), poser.upper(i));
    const double range = to[a] - from[a];
    levels[a] = range <= 0 ? 1 : std::clamp(1 + int(std::ceil(range / kStepRad)), 3, kMaxLevels);
  }
  // The last axis turns the flange about its own axis: it never moves the flange's position.
  {
    const size_t last = size_t(dof - 1);
    std::array<double, 7> a = start, b = start;
    b[last] = to[last];
    bool moves = (poser.flangePosition(a) - poser.flangePosition(b)).norm() > 1e-9;
    for (int i = 0; i + 1 < dof; ++i) a[size_t(i)] = b[size_t(i)] = to[size_t(i)];
    a[last] = from[last];
    moves = moves || (poser.flangePosition(a) - poser.flangePosition(b)).norm() > 1e-9;
    if (!moves) levels[last] = 1;
  }
  Eigen::Vector3d lo = s, hi = s;
  std::array<int, 6> k{};  // the sample's level per axis (an odometer)
  std::array<double, 7> q = start;
  while (true) {
    for (int i = 0; i < dof; ++i) {
      const size_t a = size_t(i);
      if (levels[a] > 1) q[a] = from[a] + (to[a] - from[a]) * k[a] / (levels[a] - 1);
    }
    const Eigen::Vector3d p = poser.flangePosition(q);
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
    int i = 0;
    while (i < dof && ++k[size_t(i)] == levels[size_t(i)]) k[size_t(i++)] = 0;
    if (i == dof) break;
  }
  out.valid = true;
  out.min = QVector3D(float(lo.x()), float(lo.y()), float(lo.z()));
  out.max = QVector3D(float(hi.x()), float(hi.y()), float(hi.z()));
  out.start = QVector3D(float(s.x()), float(s.y()), float(s.z()));
  return out;
}

}  // namespace rci::ui
