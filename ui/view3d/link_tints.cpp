// SPDX-License-Identifier: Apache-2.0
// Link tints and the mouse-pull spring (link_tints.h).
#include "link_tints.h"

#include <cmath>

namespace rci::ui {

std::vector<LinkTint> linkTints(const TintInputs& in) {
  const double margin = kNearLimitDeg * M_PI / 180.0;
  std::vector<LinkTint> tints(static_cast<size_t>(in.dof), LinkTint::kNone);
  for (size_t i = 0; i < tints.size(); ++i) {
    const bool overload = in.thresholds[i] > 0 && std::abs(in.tau_ext[i]) > in.thresholds[i];
    const bool near_limit = in.q[i] < in.lower[i] + margin || in.q[i] > in.upper[i] - margin;
    if (in.collision || overload) tints[i] = LinkTint::kOverload;
    else if (near_limit) tints[i] = LinkTint::kNearLimit;
  }
  return tints;
}

QVector3D springForce(const QVector3D& tcp, const QVector3D& pointer, float k, float max_force) {
  const QVector3D force = (pointer - tcp) * k;
  const float size = force.length();
  return size > max_force ? force * (max_force / size) : force;
}

}  // namespace rci::ui
