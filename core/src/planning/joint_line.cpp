// SPDX-License-Identifier: Apache-2.0
// The joint-space line (joint_line.h).
#include "planning/joint_line.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace xmate::planning {

JointLine planJointLine(const model::RobotSpec& spec, const std::array<double, 7>& q_start,
                        const std::array<double, 7>& q_goal, double speed_ratio) {
  JointLine line;
  line.q_start = q_start;
  constexpr double kNone = std::numeric_limits<double>::infinity();
  double v = kNone, a = kNone, j = kNone;
  for (int i = 0; i < spec.dof; ++i) {
    line.delta[i] = q_goal[i] - q_start[i];
    const double d = std::abs(line.delta[i]);
    if (d == 0) continue;
    v = std::min(v, spec.dq_max[i] * speed_ratio / d);
    a = std::min(a, spec.ddq_max[i] * speed_ratio / d);
    j = std::min(j, spec.jerk_max[i] * speed_ratio / d);
  }
  // A zero move has no limiting joint: its profile has zero duration.
  if (std::isfinite(v)) line.profile = planDoubleS(1.0, v, a, j);
  return line;
}

bool sampleJointLine(const JointLine& line, double t, std::array<double, 7>& q) {
  const bool finished = !(t < line.profile.duration);
  const double s = finished ? 1.0 : sampleDoubleS(line.profile, t).p;
  for (int i = 0; i < 7; ++i) q[i] = line.q_start[i] + line.delta[i] * s;
  return finished;
}

}  // namespace xmate::planning
