// SPDX-License-Identifier: Apache-2.0
// The RobotState the simulated controller sends: measured values from the last cycle, the
// commanded values of the current activity (with the Cartesian ones derived by forward kinematics
// where the command was in joint space), modes and error bits. Allocation-free.
#include "model/inverse_kinematics.h"
#include "model/kinematics.h"
#include "sim/controller_impl.h"
#include "sim/pose_math.h"

namespace xmate::sim {
namespace {

using RCI::robot::ControllerMode;
using RCI::robot::MotionGeneratorMode;
using RCI::robot::RobotMode;

Vector6d stack(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  Vector6d v;
  v << a, b;
  return v;
}

}  // namespace

void Controller::Impl::updateCommanded() {
  const Commanded before = commanded;
  Commanded& c = commanded;
  if (activity == Activity::kMotion && motion.generator == MoveGenerator::kCartesianPosition) {
    c.q = motion.q_command;
    c.dq = motion.joint_rates.velocity();
    c.ddq = motion.joint_rates.acceleration();
    c.pose = motion.pose_command;
    c.twist = stack(motion.translation_rates.velocity(), motion.rotation_rates.velocity());
    c.twist_rate = stack(motion.translation_rates.acceleration(), motion.rotation_rates.acceleration());
    c.psi = motion.psi_command;
    c.psi_rate = motion.psi_rates.velocity()[0];
    c.psi_acceleration = motion.psi_rates.acceleration()[0];
  } else {
    if (activity == Activity::kMotion && motion.generator == MoveGenerator::kJointPosition) {
      c.q = motion.joint_target;  // the last command, continued at its velocity while commands are lost
      c.dq = motion.joint_rates.velocity();
      c.ddq = motion.joint_rates.acceleration();
    } else if (motors_on && activity == Activity::kHold) {
      c.q = ref.track.current;
      c.dq = ref.track.velocity;
      c.ddq = ref.track.acceleration;
    } else {  // torque mode, hand guiding, brakes: no position is commanded; report the measured one
      c.q = plant.q;
      c.dq = plant.dq;
      c.ddq = meas.ddq;
    }
    c.pose = model::tcpPose(arm, c.q);
    c.twist = model::tcpJacobian(arm, c.q) * c.dq;
    c.twist_rate = (c.twist - before.twist) / kCycle;
    c.psi = spec.dof == 7 ? model::armAngle(arm, c.q) : 0.0;
    c.psi_rate = wrapAngle(c.psi - before.psi) / kCycle;
    c.psi_acceleration = (c.psi_rate - before.psi_rate) / kCycle;
  }
  c.torque = meas.motor_torque;
  c.torque_rate = (c.torque - before.torque) / kCycle;
}

RobotMode Controller::Impl::robotMode() const {
  if (estop || guard_stop) return RobotMode::kUserStopped;
  if (hasErrors()) return RobotMode::kReflex;
  if (activity == Activity::kDrag) return RobotMode::kGuiding;
  if (activity == Activity::kMotion) return RobotMode::kMove;
  if (recovery_cycles_left > 0) return RobotMode::kAutomaticErrorRecovery;
  return RobotMode::kIdle;
}

void Controller::Impl::fillState() {
  RobotState& s = state;
  const Commanded& c = commanded;
  s.q = s.theta_m = toArray7(plant.q);
  s.dq_m = s.theta_vel_m = toArray7(plant.dq);
  s.q_c = toArray7(c.q);
  s.dq_c = toArray7(c.dq);
  s.ddq_c = toArray7(c.ddq);
  s.toolTobase_pos_m = toRowMajor(meas.tcp);
  s.toolTobase_pos_c = toRowMajor(c.pose);
  s.toolTobase_vel_c = toArray6(c.twist);
  s.toolTobase_acc_c = toArray6(c.twist_rate);
  s.psi_m = meas.psi;
  s.psi_c = c.psi;
  s.psi_vel_c = c.psi_rate;
  s.psi_acc_c = c.psi_acceleration;
  s.tau_m = toArray7(meas.joint_torque);
  s.tau_m_filtered = toArray7(meas.joint_torque_filtered);
  s.tau_c = toArray7(c.torque);
  s.tau_vel_c = toArray7(c.torque_rate);
  s.motor_tau = toArray7(meas.motor_torque);
  s.motor_tau_filtered = toArray7(meas.motor_torque_filtered);
  s.tau_ext_in_base = toArray6(meas.external_wrench);
  // The same wrench in the force-control frame (setFcCoor): world frames are fixed in the base,
  // tool and path frames move with the TCP. The moment stays about the TCP.
  const Eigen::Matrix3d r = settings.force_frame_type == 0
                                ? Eigen::Matrix3d(settings.force_frame.linear())
                                : Eigen::Matrix3d(meas.tcp.linear() * settings.force_frame.linear());
  s.tau_ext_in_stiff = toArray6(stack(r.transpose() * meas.external_wrench.head<3>(),
                                      r.transpose() * meas.external_wrench.tail<3>()));
  s.errors = errors;
  s.control_command_success_rate = activity == Activity::kMotion ? success.rate() : 1.0;
  s.robot_mode = robotMode();
  if (activity == Activity::kMotion) {
    s.motion_generator_mode = motion.generator == MoveGenerator::kJointPosition ? MotionGeneratorMode::kJointPosition
                              : motion.generator == MoveGenerator::kCartesianPosition
                                  ? MotionGeneratorMode::kCartesianPosition
                                  : MotionGeneratorMode::kIdle;
    s.controller_mode = static_cast<ControllerMode>(static_cast<uint8_t>(motion.controller));
  } else {
    s.motion_generator_mode = MotionGeneratorMode::kIdle;
    s.controller_mode = motors_on && activity == Activity::kHold ? ControllerMode::kJointPosition : ControllerMode::kOther;
  }
}

}  // namespace xmate::sim
