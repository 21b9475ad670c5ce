// SPDX-License-Identifier: Apache-2.0
// Limits of the simulated controller that must always leave a way back: the joint and safety-box
// allowances (reset when a motion, hand guiding or power-on starts, narrowed every cycle as the arm
// returns), the IK's search range during Cartesian motions, and the walls of hand guiding with the
// brakes that hold the arm at them (joints, safety box, and the 7-axis wrist-axis wall and arm-angle
// speed limit). docs/simulator_controller.md, "There is always a way back" and
// "Hand guiding (drag)". Allocation-free except placeArm (a scene call, not part of the cycle).
#include <algorithm>

#include "model/ik_branches.h"
#include "model/inverse_kinematics.h"
#include "model/kinematics.h"
#include "sim/controller_impl.h"
#include "sim/pose_math.h"

namespace xmate::sim {

void Controller::Impl::resetAllowances() {
  joint_allowance.reset(plant.q, settings.soft_lower, settings.soft_upper, spec.dof);
  box_allowance.reset(settings.safety_box, meas.tcp.translation());
  wall_onsets.reset(plant.q, joint_allowance, boxLocal(settings.safety_box, meas.tcp.translation()), box_allowance,
                    spec.dof);
  wrist_stop.reset(spec.dof == 7, wristAxisRadius());
}

void Controller::Impl::ratchetAllowances() {
  joint_allowance.ratchet(plant.q, settings.soft_lower, settings.soft_upper, spec.dof);
  box_allowance.ratchet(settings.safety_box, meas.tcp.translation());
  wall_onsets.ratchet(plant.q, joint_allowance, boxLocal(settings.safety_box, meas.tcp.translation()), box_allowance,
                      spec.dof);
  if (activity == Activity::kDrag && wrist_stop.active) wrist_stop.ratchet(wristAxisRadius());
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

double Controller::Impl::wristAxisRadius() const {
  if (spec.dof != 7) return 0.0;
  return model::shoulderToWrist(arm.geometry, model::flangePose(arm, plant.q)).head<2>().norm();
}

ArmAngleLinearization Controller::Impl::armAngleLinearization() const {
  ArmAngleLinearization a;
  if (spec.dof != 7) return a;
  a.defined = true;
  a.q0 = plant.q;
  // The wrist centre moves with the last link: its velocity is v_tcp + omega x (wrist - tcp).
  const Eigen::Isometry3d tcp = model::tcpPose(arm, plant.q);
  const model::Jacobian j = model::tcpJacobian(arm, plant.q);
  const Eigen::Vector3d shoulder(0, 0, arm.geometry.base_to_shoulder);  // on the J1 axis
  const Eigen::Vector3d wrist = shoulder + model::shoulderToWrist(arm.geometry, tcp * arm.tool_inverse);
  const Eigen::Vector3d lever = wrist - tcp.translation();
  for (int i = 0; i < spec.dof; ++i) {
    const Eigen::Vector3d v = j.block<3, 1>(0, i) + j.block<3, 1>(3, i).cross(lever);
    a.jw.col(i) = v.head<2>();
  }
  a.wrist0 = wrist.head<2>();
  // psi's gradient by central differences (psi depends on the joints before the wrist only).
  constexpr double kStep = 1e-6;  // rad
  JointVector q = plant.q;
  for (int i = 0; i < arm.arm_joint_count; ++i) {
    q[i] = plant.q[i] + kStep;
    const double up = model::armAngle(arm, q);
    q[i] = plant.q[i] - kStep;
    const double down = model::armAngle(arm, q);
    q[i] = plant.q[i];
    a.jpsi[i] = wrapAngle(up - down) / (2 * kStep);
  }
  return a;
}

JointVector Controller::Impl::dragWallTorque(const TcpLinearization& tcp,
                                             const ArmAngleLinearization& arm_angle) const {
  JointVector tau = jointWallTorque(wall_onsets, params, plant);
  if (settings.safety_box.active) tau += boxWallTorque(wall_onsets, settings.safety_box, tcp, plant);
  tau += wristAxisWallTorque(wrist_stop, arm_angle, plant);
  tau += guidingSpeedTorque(params, limits.velocity, tcp, plant);
  return tau + armAngleSpeedTorque(params, model::controllerCartesianLimits().v_elbow, arm_angle, plant);
}

void Controller::Impl::holdAtDragWalls(const TcpLinearization& tcp, const ArmAngleLinearization& arm_angle,
                                       const FrozenDynamics& physical) {
  holdAtWalls(plant, physical, joint_allowance, settings.safety_box.active, settings.safety_box, box_allowance, tcp,
              wrist_stop, arm_angle, spec.dof);
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
