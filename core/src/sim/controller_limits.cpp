// SPDX-License-Identifier: Apache-2.0
// Limits of the simulated controller that must always leave a way back: the joint and safety-box
// allowances (reset when a motion, hand guiding or power-on starts, narrowed every cycle as the arm
// returns), the IK's search range during Cartesian motions, and the walls of hand guiding with the
// brakes that hold the arm at them. docs/simulator_controller.md, "There is always a way back" and
// "Hand guiding (drag)". Allocation-free except placeArm (a scene call, not part of the cycle).
#include <algorithm>

#include "model/inverse_kinematics.h"
#include "model/kinematics.h"
#include "sim/controller_impl.h"

namespace xmate::sim {

void Controller::Impl::resetAllowances() {
  joint_allowance.reset(plant.q, settings.soft_lower, settings.soft_upper, spec.dof);
  box_allowance.reset(settings.safety_box, meas.tcp.translation());
  wall_onsets.reset(plant.q, joint_allowance, boxLocal(settings.safety_box, meas.tcp.translation()), box_allowance,
                    spec.dof);
}

void Controller::Impl::ratchetAllowances() {
  joint_allowance.ratchet(plant.q, settings.soft_lower, settings.soft_upper, spec.dof);
  box_allowance.ratchet(settings.safety_box, meas.tcp.translation());
  wall_onsets.ratchet(plant.q, joint_allowance, boxLocal(settings.safety_box, meas.tcp.translation()), box_allowance,
                      spec.dof);
}

void Controller::Impl::widenIkLimitsToAllowance() {
  for (int i = 0; i < spec.dof; ++i) {
    arm.lower[i] = std::min(arm.hardware_lower[i], joint_allowance.lower[i]);
    arm.upper[i] = std::max(arm.hardware_upper[i], joint_allowance.upper[i]);
  }
}

TcpLinearization Controller::Impl::tcpLinearization() const {
  TcpLinearization tcp;
  tcp.q0 = plant.q;
  tcp.p0 = model::tcpPose(arm, plant.q).translation();
  tcp.jv = model::tcpJacobian(arm, plant.q).topRows<3>();
  return tcp;
}

JointVector Controller::Impl::dragWallTorque(const TcpLinearization& tcp) const {
  JointVector tau = jointWallTorque(wall_onsets, params, plant);
  if (settings.safety_box.active) tau += boxWallTorque(wall_onsets, settings.safety_box, tcp, plant);
  return tau + guidingSpeedTorque(params, limits.velocity, tcp, plant);
}

void Controller::Impl::holdAtDragWalls(const TcpLinearization& tcp, const FrozenDynamics& physical) {
  holdAtWalls(plant, physical, joint_allowance, settings.safety_box.active, settings.safety_box, box_allowance, tcp,
              spec.dof);
}

void Controller::Impl::placeArm(const JointVector& q) {
  if (activity != Activity::kHold) stopFromMeasured();
  plant.q = q;
  plant.dq.setZero();
  ref.ramp.active = false;
  ref.track.resetAt(q, JointVector::Zero(), kCycle);
  ref.joint_filter = ref.hold_target = q;
  ref.rejoin.clear();
  meas.ddq.setZero();
  meas.tcp = model::tcpPose(arm, q);
  meas.jacobian = model::tcpJacobian(arm, q);
  meas.twist.setZero();
  meas.twist_rate.setZero();
  meas.psi = spec.dof == 7 ? model::armAngle(arm, q) : 0.0;
  meas.psi_rate = 0;
  resetAllowances();
  updateCommanded();
  fillState();
}

}  // namespace xmate::sim
