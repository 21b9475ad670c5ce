// SPDX-License-Identifier: Apache-2.0
// The time scaling's limits at the plan's current point (time_scaling.h): the plan's velocity and
// acceleration by central differences over 1 ms of plan time, per group of coordinates (a joint;
// a Cartesian translation or rotation), against the group's acceleration and jerk reserve. Used
// every cycle by the executor's motions on both robot families; real-time safe.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "client/stall_bridge.h"
#include "model/robot_spec.h"
#include "teach/time_scaling.h"

namespace xmate::teach {

// The jerk a change of the scaling's rate may add: half the plan's unused share.
inline constexpr double kRateChangeJerkShare = 0.5;

// The smallest acceleration-to-velocity ratio (1/s) of what a motion is limited by: the joints'
// rated limits for a joint motion, the planner's Cartesian limits for a Cartesian one.
inline double accelOverVelocity(bool joint_motion, const model::RobotSpec& spec) {
  double ratio = 1e9;
  if (joint_motion) {
    for (int i = 0; i < spec.dof; ++i) ratio = std::min(ratio, spec.ddq_max[size_t(i)] / spec.dq_max[size_t(i)]);
    return ratio;
  }
  const model::CartesianLimits& c = model::plannerCartesianLimits();
  return std::min({c.a_trans / c.v_trans, c.a_rot / c.v_rot, c.a_elbow / c.v_elbow});
}

// How hard a pause or stop may brake: a joint motion at the rated joint accelerations; a Cartesian
// one at half the controller's Cartesian accelerations, since braking the TCP near a singular pose
// takes more of the joints than the path's own acceleration did (the plan was checked against the
// joint limits, the braking is not).
inline constexpr double kCartesianBrakingShare = 0.5;

// plan_at(t) returns the plan's coordinates (client::StallBridge::Vec) at plan time t.
template <class PlanAt>
void limitScalingAtPlan(TimeScaling& scaling, double plan_time, const PlanAt& plan_at,
                        const client::StallBridge::Limits& limits, int dims, double braking_share) {
  constexpr double h = 1e-3;
  const double t = plan_time;
  const client::StallBridge::Vec p = plan_at(t), before = plan_at(std::max(0.0, t - h)), after = plan_at(t + h);
  std::array<GroupMotion, client::StallBridge::kMaxDims> groups{};
  int count = 0;
  for (int g = 0; g < dims; ++g) {
    double v2 = 0, a2 = 0;
    bool member = false;
    for (int i = 0; i < dims; ++i) {
      if (limits.group[size_t(i)] != g) continue;
      member = true;
      const double v = (after[size_t(i)] - before[size_t(i)]) / (2 * h);
      const double a = (after[size_t(i)] - 2 * p[size_t(i)] + before[size_t(i)]) / (h * h);
      v2 += v * v;
      a2 += a * a;
    }
    if (!member) continue;
    groups[size_t(count++)] = {std::sqrt(v2), std::sqrt(a2), braking_share * limits.acceleration[size_t(g)],
                               kRateChangeJerkShare * limits.jerk_reserve[size_t(g)]};
  }
  const ScalingLimits l = planScalingLimits(groups.data(), count, scaling.value());
  scaling.setLimits(l.rate, l.rate_change);
}

}  // namespace xmate::teach
