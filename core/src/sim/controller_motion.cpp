// SPDX-License-Identifier: Apache-2.0
// Motions of the simulated controller: StartMove and its refusals, the streamed commands of each
// cycle (the command rules with their error bits, lost-command handling, instability), the end of
// a motion, and the stops every error, e-stop, guard stop and power-off lead to.
#include <cmath>
#include <string>

#include "model/inverse_kinematics.h"
#include "model/kinematics.h"
#include "sim/controller_impl.h"
#include "sim/pose_math.h"

namespace xmate::sim {
namespace {

using protocol::StartMoveStatus;
using protocol::StopMoveStatus;

constexpr uint8_t code(StartMoveStatus s) { return static_cast<uint8_t>(s); }
constexpr uint8_t code(StopMoveStatus s) { return static_cast<uint8_t>(s); }

// The pairs of modes: joint position/impedance + joint generator, Cartesian position/impedance +
// Cartesian generator, torque + idle generator.
bool validPair(MoveController controller, MoveGenerator generator) {
  switch (controller) {
    case MoveController::kJointPosition:
    case MoveController::kJointImpedance: return generator == MoveGenerator::kJointPosition;
    case MoveController::kCartesianPosition:
    case MoveController::kCartesianImpedance: return generator == MoveGenerator::kCartesianPosition;
    case MoveController::kTorque: return generator == MoveGenerator::kIdle;
  }
  return false;
}

JointVector unbounded() { return JointVector::Constant(INFINITY); }

}  // namespace

uint8_t Controller::Impl::startMove(const uint8_t* p, size_t n) {
  protocol::StartMoveRequestMsg r;
  if (protocol::decodePayload(p, n, r) != protocol::DecodeStatus::kOk)
    return refuse(code(StartMoveStatus::kInvalidArgument), "startMove: malformed request");
  const auto controller = static_cast<MoveController>(r.controller_mode);
  const auto generator = static_cast<MoveGenerator>(r.motion_mode);
  if (r.controller_mode > 4 || r.motion_mode > 2 || !validPair(controller, generator))
    return refuse(code(StartMoveStatus::kInvalidArgument),
                  "startMove: controller mode " + std::to_string(r.controller_mode) + " with motion generator mode " +
                      std::to_string(r.motion_mode) +
                      " is not a valid pair (joint position/impedance + joint position, Cartesian position/impedance "
                      "+ Cartesian position, torque + idle)");
  if (estop) return refuse(code(StartMoveStatus::kEmergencyAborted), "startMove: the emergency stop is pressed");
  if (hasErrors())
    return refuse(code(StartMoveStatus::kReflexAborted),
                  "startMove: error bits are set; call automaticErrorRecovery first");
  const uint8_t not_possible = code(StartMoveStatus::kNotPossible);
  if (!motors_on) return refuse(not_possible, "startMove: the motors are off; call setMotorPower(1) first");
  if (guard_stop) return refuse(not_possible, "startMove: the guard stop is active");
  if (activity == Activity::kDrag) return refuse(not_possible, "startMove: hand guiding is active; call stopDrag first");
  if (activity == Activity::kMotion) return refuse(not_possible, "startMove: a motion is already running");
  if (ref.ramp.active) return refuse(not_possible, "startMove: the robot is still stopping; try again shortly");
  if (reboot_requested) return refuse(not_possible, "startMove: the controller is rebooting");
  if (generator == MoveGenerator::kCartesianPosition) {
    JointVector unused;
    if (model::inverseKinematics(arm, meas.tcp.matrix(), meas.psi, plant.q, unused) == model::IkStatus::kSingular)
      return refuse(code(StartMoveStatus::kStartAtSingularPose),
                    "startMove: the arm is at a singular pose; Cartesian motion cannot start here (move it in "
                    "joint space first)");
  }
  motion = Motion{};
  motion.controller = controller;
  motion.generator = generator;
  motion.origin_id = state.message_id;
  motion.q_command = plant.q;
  motion.pose_command = meas.tcp;
  motion.psi_command = meas.psi;
  motion.joint_target = ref.hold_target;
  motion.pose_target = meas.tcp;
  motion.nullspace_q = plant.q;
  ref.pose_filter = meas.tcp;
  ref.pose_filter_twist.setZero();
  ref.torque_filter.setZero();
  ref.soft_limit_clamp.reset(ref.joint_filter);
  success.clear();
  resetAllowances();  // a joint or the TCP beyond a limit may move back, not further out
  activity = Activity::kMotion;
  return code(StartMoveStatus::kSuccess);
}

uint8_t Controller::Impl::stopMove() {
  if (estop) return refuse(code(StopMoveStatus::kEmergencyAborted), "stopMove: the motion was aborted by the e-stop");
  if (hasErrors())
    return refuse(code(StopMoveStatus::kReflexAborted), "stopMove: the motion was aborted by an error (reflex)");
  if (activity == Activity::kMotion) stopFromMeasured();
  return code(StopMoveStatus::kSuccess);
}

void Controller::Impl::takeCommand(const RobotCommand* command) {
  const uint64_t id = state.message_id;
  const bool arrived = command != nullptr && command->message_id == id;
  success.record(arrived);
  if (!arrived) {
    ++lost_commands;
    if (++motion.consecutive_lost > config.instability_threshold) {
      ErrorBits bits{};
      raise(bits, kInstabilityDetection);
      raiseErrors(bits);
      return;
    }
    extrapolateLostCommand();
    return;
  }
  const int gap = motion.consecutive_lost;
  motion.consecutive_lost = 0;
  const bool follows = jointTargetFollowsCommands() && !motion.awaiting_first_command;
  JointVector extrapolated = motion.joint_target, extrapolated_velocity = JointVector::Zero();
  if (follows && gap > 0) extrapolate(double(gap + 1) * kCycle, extrapolated, extrapolated_velocity);
  const JointVector previous_target = motion.joint_target;
  const double t = double(id - motion.origin_id) * kCycle;
  ErrorBits bits{};
  switch (motion.generator) {
    case MoveGenerator::kJointPosition: acceptJointCommand(*command, t, bits); break;
    case MoveGenerator::kCartesianPosition: acceptCartesianCommand(*command, t, bits); break;
    case MoveGenerator::kIdle: acceptTorqueCommand(*command, t, bits); break;
  }
  motion.awaiting_first_command = false;
  if (anyError(bits)) {
    raiseErrors(bits);
    return;
  }
  if (follows) rejoinAfterGap(gap, extrapolated, extrapolated_velocity, previous_target);
  if (command->motion.motion_generation_finished) finishMotion();
}

void Controller::Impl::acceptJointCommand(const RobotCommand& command, double t, ErrorBits& bits) {
  const JointVector q = toJointVector(command.motion.q_c, spec.dof);
  if (motion.awaiting_first_command) {
    const bool at_start = (q - plant.q).cwiseAbs().maxCoeff() <= kStartTolerance;
    motion.q_command = at_start ? q : plant.q;
    motion.joint_rates.reset(t - kCycle, kCycle);
  }
  motion.joint_rates.push(q - motion.q_command, t);
  checkJointDerivatives(motion.joint_rates, limits, spec.dof, bits);
  if (settings.auto_limit)
    checkJointPosition(q, -unbounded(), unbounded(), spec.dof, bits);  // finite; the servo clamps
  else
    checkJointPosition(q, joint_allowance.lower, joint_allowance.upper, spec.dof, bits);
  if (anyError(bits)) return;
  if (motion.awaiting_first_command) startReferenceAt(q);
  motion.q_command = motion.joint_target = q;
}

void Controller::Impl::acceptCartesianCommand(const RobotCommand& command, double t, ErrorBits& bits) {
  const Eigen::Matrix4d matrix = toMatrix4(command.motion.toolTobase_pos_c);
  if (!model::isRigidTransform(matrix)) {
    raise(bits, kCartesianPositionMotionGeneratorInvalidFrame);
    return;
  }
  const Eigen::Isometry3d pose = toIsometry(command.motion.toolTobase_pos_c);
  const bool seven_axis = spec.dof == 7;
  const double psi = seven_axis && command.motion.psi_valid ? command.motion.psi_c : motion.psi_command;
  if (motion.awaiting_first_command) {
    const bool at_start = (pose.translation() - meas.tcp.translation()).norm() <= kStartTolerance &&
                          rotationLog(pose.linear() * meas.tcp.linear().transpose()).norm() <= kStartTolerance &&
                          std::abs(wrapAngle(psi - meas.psi)) <= kStartTolerance;
    motion.pose_command = at_start ? pose : meas.tcp;
    motion.psi_command = at_start ? psi : meas.psi;
    motion.q_command = plant.q;
    motion.translation_rates.reset(t - kCycle, kCycle);
    motion.rotation_rates.reset(t - kCycle, kCycle);
    motion.psi_rates.reset(t - kCycle, kCycle);
    motion.joint_rates.reset(t - kCycle, kCycle);
  }
  motion.translation_rates.push(pose.translation() - motion.pose_command.translation(), t);
  motion.rotation_rates.push(rotationLog(pose.linear() * motion.pose_command.linear().transpose()), t);
  motion.psi_rates.push(Eigen::Matrix<double, 1, 1>(wrapAngle(psi - motion.psi_command)), t);
  checkCartesianDerivatives(motion.translation_rates, motion.rotation_rates, model::controllerCartesianLimits(), bits);
  if (seven_axis) checkElbowDerivatives(motion.psi_rates, model::controllerCartesianLimits(), bits);

  JointVector q;
  widenIkLimitsToAllowance();
  switch (model::inverseKinematics(arm, matrix, psi, motion.q_command, q)) {
    case model::IkStatus::kOk: break;
    case model::IkStatus::kSingular: raise(bits, kCartesianPositionMotionGeneratorInvalidFrame); return;
    case model::IkStatus::kAboveSoftLimit:
    case model::IkStatus::kBelowSoftLimit: raise(bits, kCommandJointPositionLimitsViolation); return;
    default: raise(bits, kCommandCartesianPositionLimitsViolation); return;  // out of the workspace
  }
  motion.joint_rates.push(q - motion.q_command, t);
  checkJointVelocity(motion.joint_rates, limits, spec.dof, bits);
  if (!settings.auto_limit) checkJointPosition(q, joint_allowance.lower, joint_allowance.upper, spec.dof, bits);
  if (anyError(bits)) return;
  if (motion.awaiting_first_command) startReferenceAt(q);
  motion.pose_command = pose;
  motion.psi_command = psi;
  motion.q_command = q;
  if (motion.controller == MoveController::kCartesianPosition)
    motion.joint_target = q;
  else
    motion.pose_target = pose;
}

void Controller::Impl::acceptTorqueCommand(const RobotCommand& command, double t, ErrorBits& bits) {
  const JointVector tau = toJointVector(command.torque.tau_c, spec.dof);
  if (motion.awaiting_first_command) {
    motion.torque_command.setZero();  // torque commands start from zero, like the motors
    motion.torque_rates.reset(t - kCycle, kCycle);
  }
  motion.torque_rates.push(tau - motion.torque_command, t);
  checkTorque(tau, motion.torque_rates, limits, spec.dof, bits);
  if (anyError(bits)) return;
  motion.torque_command = tau;
}

void Controller::Impl::startReferenceAt(const JointVector& q) {
  // The first command may differ from the servo's hold reference by up to kStartTolerance (the
  // client sent q, a hold error, ...): the reference starts there at rest rather than filtering a
  // step, whose finite differences would feed a spike of acceleration forward.
  ref.track.resetAt(q, JointVector::Zero(), kCycle);
  ref.joint_filter = q;
  ref.soft_limit_clamp.reset(q);
  ref.rejoin.clear();
}

bool Controller::Impl::jointTargetFollowsCommands() const {
  // Position targets follow the commands in joint space; impedance poses and torques do not.
  return motion.controller != MoveController::kCartesianImpedance && motion.controller != MoveController::kTorque;
}

// The last command that arrived continued along its velocity and acceleration (the velocity of the
// divided differences belongs half an interval back) for t seconds; dq is the mean velocity over
// the cycle after t.
void Controller::Impl::extrapolate(double t, JointVector& q, JointVector& dq) const {
  const JointVector& a = motion.joint_rates.acceleration();
  const JointVector v = motion.joint_rates.velocity() + 0.5 * kCycle * a;
  q = motion.q_command + v * t + 0.5 * a * t * t;
  dq = v + a * (t + 0.5 * kCycle);
}

void Controller::Impl::extrapolateLostCommand() {
  if (motion.awaiting_first_command) return;  // nothing to continue yet: hold
  if (!jointTargetFollowsCommands()) return;  // impedance poses and torques hold
  JointVector unused;
  extrapolate(motion.consecutive_lost * kCycle, motion.joint_target, unused);
}

// The first command after a gap: the target stays where the extrapolation has taken it (the
// difference goes into the rejoin offset). The command of the next cycle gives the client's
// velocity; the offset takes the difference to the extrapolation's, so the target's velocity
// carries on too. From then on the offset decays (RejoinBlend).
void Controller::Impl::rejoinAfterGap(int gap, const JointVector& extrapolated,
                                      const JointVector& extrapolated_velocity, const JointVector& previous_target) {
  if (gap > 0) {
    ref.rejoin.add(extrapolated - motion.joint_target, JointVector::Zero());
    motion.rejoin_velocity = extrapolated_velocity;
    motion.rejoin_velocity_pending = true;
    return;
  }
  if (!motion.rejoin_velocity_pending) return;
  motion.rejoin_velocity_pending = false;
  ref.rejoin.add(JointVector::Zero(), motion.rejoin_velocity - (motion.joint_target - previous_target) / kCycle);
}

void Controller::Impl::finishMotion() {
  if (motion.controller == MoveController::kJointPosition || motion.controller == MoveController::kCartesianPosition) {
    activity = Activity::kHold;  // rest at the last command; the filter settles onto it
    ref.ramp.active = false;
    ref.hold_target = motion.joint_target;
    if (settings.auto_limit) {  // a command beyond the soft limits ends at the limit the arm stands at
      ref.hold_target = ref.hold_target.cwiseMax(joint_allowance.lower).cwiseMin(joint_allowance.upper);
      ref.joint_filter = ref.track.current;
    }
  } else {
    stopFromMeasured();  // impedance and torque motions stop where the arm is
  }
}

void Controller::Impl::stopFromMeasured() {
  activity = Activity::kHold;
  ref.ramp.start(plant.q, plant.dq);
  ref.track.resetAt(plant.q, plant.dq, kCycle);
  ref.joint_filter = ref.hold_target = plant.q;
  ref.rejoin.clear();
}

void Controller::Impl::raiseErrors(const ErrorBits& bits) {
  merge(errors, bits);
  recovery_cycles_left = 0;
  if (activity != Activity::kHold) stopFromMeasured();
}

void Controller::Impl::powerOn() {
  if (motors_on) return;
  motors_on = true;
  activity = Activity::kHold;
  ref.ramp.active = false;
  ref.track.resetAt(plant.q, JointVector::Zero(), kCycle);
  ref.joint_filter = ref.hold_target = plant.q;
  ref.rejoin.clear();
  resetAllowances();  // outside a limit or the box: no error for being there, only for going further out
}

void Controller::Impl::powerOff() {
  motors_on = false;
  activity = Activity::kHold;
  ref.ramp.active = false;
}

void Controller::Impl::startGuiding(int space, int type) {
  activity = Activity::kDrag;
  drag.space = space;
  drag.type = type;
  drag.anchor = meas.tcp;
  resetAllowances();
}

}  // namespace xmate::sim
