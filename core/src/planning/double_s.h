// SPDX-License-Identifier: Apache-2.0
// Rest-to-rest jerk-limited "double S" profile of one scalar coordinate: closed-form planning and
// sampling (Biagiotti & Melchiorri, "Trajectory Planning for Automatic Machines and Robots",
// sec. 3.4, with v0 = v1 = a0 = a1 = 0). Every planner of this folder is built on it.
#pragma once

#include <xmate/cart_motion.h>  // planning::DoubleSProfile, the plan these functions fill and read

namespace xmate::planning {

// Position (offset from the start), velocity, acceleration and jerk at one instant.
struct DoubleSSample {
  double p = 0, v = 0, a = 0, j = 0;
};

// The time-optimal profile over `distance` (either sign) that keeps |velocity| <= v_max,
// |acceleration| <= a_max and |jerk| <= j_max. A zero distance gives a zero-duration profile.
// Throws std::invalid_argument for a non-finite distance or limits that are not finite and > 0.
// Allocation-free on success.
DoubleSProfile planDoubleS(double distance, double v_max, double a_max, double j_max);

// The profile at time t, clamped: t <= 0 (or NaN) gives the start at rest, t >= duration gives
// exactly `distance` at rest. Allocation-free.
DoubleSSample sampleDoubleS(const DoubleSProfile& profile, double t);

}  // namespace xmate::planning
