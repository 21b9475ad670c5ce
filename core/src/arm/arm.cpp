// SPDX-License-Identifier: Apache-2.0
// What every arm::Arm does unless its backend does more (arm.h): no Cartesian control of its own,
// and the model's joint range as the range a motion can reach.
#include "arm/arm.h"

#include <stdexcept>

#include "model/robot_spec.h"

namespace xmate::arm {

void Arm::runCartesianMotion(CartesianMotion&) {
  throw std::runtime_error("the " + std::string(spec().display_name) +
                           " has no Cartesian control of its own here; move it joint by joint");
}

MotionBounds Arm::motionBounds() const {
  MotionBounds bounds;
  const model::RobotSpec& s = spec();
  for (int i = 0; i < s.dof; ++i) {
    bounds.lower[size_t(i)] = s.q_min[size_t(i)];
    bounds.upper[size_t(i)] = s.q_max[size_t(i)];
  }
  return bounds;
}

}  // namespace xmate::arm
