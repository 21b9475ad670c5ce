// SPDX-License-Identifier: Apache-2.0
// One 1 ms cycle of the simulated controller: take the client's command, advance the servo
// reference, run the servo and integrate the arm in sub-steps, estimate the external torque, and
// supervise (collision, safety box, measured-motion limits). Allocation-free.
#include "model/dynamics.h"
#include "model/inverse_kinematics.h"
#include "model/kinematics.h"
#include "sim/controller_impl.h"
#include "sim/low_pass.h"
#include "sim/pose_math.h"
#include "sim/safety.h"

namespace xmate::sim {

void Controller::Impl::step(const RobotCommand* command) {
  ++cycles;
  if (activity == Activity::kMotion) takeCommand(command);
  advanceReference();
  simulateCycle();
  ratchetAllowances();
  supervise();
  if (recovery_cycles_left > 0) --recovery_cycles_left;
  ++state.message_id;
  updateCommanded();
  fillState();
}

void Controller::Impl::advanceReference() {
  if (!motors_on) return;
  if (activity == Activity::kHold) {
    if (ref.ramp.active) {
      ref.ramp.step(limits.acceleration, kCycle);
      ref.joint_filter = ref.hold_target = ref.ramp.q;
    } else {
      ref.rejoin.step(limits.acceleration, kCycle);  // a motion that ended while rejoining
      const JointVector target = ref.hold_target + ref.rejoin.offset;
      lowPassStep(ref.joint_filter, target, alpha(settings.joint_filter_hz));
    }
    ref.track.advanceTo(ref.joint_filter, kCycle);
    return;
  }
  if (activity != Activity::kMotion) return;
  switch (motion.controller) {
    case MoveController::kJointPosition:
    case MoveController::kJointImpedance:
    case MoveController::kCartesianPosition: {
      const bool cartesian = motion.controller == MoveController::kCartesianPosition;
      ref.rejoin.step(limits.acceleration, kCycle);
      const JointVector target = motion.joint_target + ref.rejoin.offset;
      lowPassStep(ref.joint_filter, target,
                  alpha(cartesian ? settings.cartesian_filter_hz : settings.joint_filter_hz));
      // auto_limit brakes towards the soft limits at half the rated deceleration.
      const JointVector next =
          settings.auto_limit ? ref.soft_limit_clamp.next(ref.track, ref.joint_filter, joint_allowance.lower,
                                                          joint_allowance.upper, 0.5 * limits.acceleration, spec.dof,
                                                          kCycle)
                              : ref.joint_filter;
      ref.track.advanceTo(next, kCycle);
      break;
    }
    case MoveController::kCartesianImpedance: {
      const Eigen::Isometry3d previous = ref.pose_filter;
      const double a = alpha(settings.cartesian_filter_hz);
      const Eigen::Isometry3d& target = motion.pose_target;
      ref.pose_filter.translation() += a * (target.translation() - previous.translation());
      ref.pose_filter.linear() =
          rotationExp(a * rotationLog(target.linear() * previous.linear().transpose())) * previous.linear();
      ref.pose_filter_twist = poseError(ref.pose_filter, previous) / kCycle;
      break;
    }
    case MoveController::kTorque:
      lowPassStep(ref.torque_filter, motion.torque_command, alpha(settings.torque_filter_hz));
      break;
  }
}

bool Controller::Impl::positionControlled() const {
  if (activity == Activity::kHold) return true;
  return activity == Activity::kMotion && (motion.controller == MoveController::kJointPosition ||
                                           motion.controller == MoveController::kCartesianPosition);
}

bool Controller::Impl::cartesianLawActive() const {
  return (activity == Activity::kMotion && motion.controller == MoveController::kCartesianImpedance) ||
         (activity == Activity::kDrag && drag.space == 1);
}

CartesianImpedance Controller::Impl::cartesianLaw() const {
  const OperationalSpace os = operationalSpace(model_dynamics, meas.jacobian);
  CartesianImpedance law;
  law.nullspace_projector = os.nullspace_projector;
  law.nullspace_damping = kNullspaceDamping;
  if (activity == Activity::kMotion) {
    law.target = ref.pose_filter;
    law.target_twist = ref.pose_filter_twist;
    law.stiffness = settings.cartesian_stiffness;
    law.damping = cartesianDamping(law.stiffness, os.inertia_diagonal, Vector6d::Constant(kMinCartesianDamping));
    // setCartImpDesiredTau's wrench is given in the force-control frame (setFcCoor).
    const Eigen::Matrix3d r = settings.force_frame_type == 0 ? Eigen::Matrix3d(settings.force_frame.linear())
                                                             : Eigen::Matrix3d(meas.tcp.linear() * settings.force_frame.linear());
    law.wrench.head<3>() = r * settings.desired_wrench.head<3>();
    law.wrench.tail<3>() = r * settings.desired_wrench.tail<3>();
    law.nullspace_q = motion.nullspace_q;
    law.nullspace_stiffness = kNullspaceStiffness;
    return law;
  }
  // Cartesian hand guiding: the constrained directions held stiffly at the pose guiding started
  // from, the free ones only damped. Wire drag type: 0 translation only, 1 rotation only, 2 free.
  law.target = drag.anchor;
  const Vector6d stiff = toVector6(model::kCartesianStiffnessMax);
  for (int i = 0; i < 6; ++i) {
    const bool translation_axis = i < 3;
    const bool free = drag.type == 2 || (drag.type == 0 && translation_axis) || (drag.type == 1 && !translation_axis);
    law.stiffness[i] = free ? 0.0 : stiff[i];
  }
  Vector6d free_damping;
  free_damping << Eigen::Vector3d::Constant(kDragTranslationDamping), Eigen::Vector3d::Constant(kDragRotationDamping);
  law.damping = cartesianDamping(law.stiffness, os.inertia_diagonal, free_damping);
  return law;
}

JointVector Controller::Impl::servoTorque(double fraction, const CartesianImpedance& cartesian,
                                          const JointVector& gravity, const JointVector& joint_damping) const {
  const JointSetpoint setpoint{ref.track.at(fraction), ref.track.velocity, ref.track.acceleration};
  if (cartesianLawActive()) {
    const Eigen::Isometry3d tcp = model::tcpPose(arm, plant.q);
    const model::Jacobian jacobian = model::tcpJacobian(arm, plant.q);
    return cartesianImpedanceTorque(model_dynamics, params, plant, tcp, jacobian, cartesian);
  }
  if (activity == Activity::kDrag) return jointDragTorque(model_dynamics, params, plant, joint_damping);
  if (activity == Activity::kMotion) {
    if (motion.controller == MoveController::kJointImpedance)
      return jointImpedanceTorque(model_dynamics, params, plant, setpoint, settings.joint_stiffness, joint_damping);
    if (motion.controller == MoveController::kTorque) return torqueModeTorque(ref.torque_filter, gravity, params, plant);
  }
  return positionControlTorque(model_dynamics, params, plant, setpoint);
}

void Controller::Impl::simulateCycle() {
  freezeDynamics(arm, params, plant, model_dynamics);
  const FrozenDynamics* physical = &model_dynamics;
  if (!plant_follows_load) {
    freezeDynamics(plant_arm, params, plant, plant_dynamics);
    physical = &plant_dynamics;
  }
  const JointVector scene_torque = model::wrenchToJointTorques(arm, plant.q, scene_wrench);

  // What the control law needs once per cycle.
  CartesianImpedance cartesian;
  JointVector gravity = JointVector::Zero();
  JointVector joint_damping = JointVector::Zero();
  if (motors_on) {
    if (cartesianLawActive()) cartesian = cartesianLaw();
    if (activity == Activity::kMotion && motion.controller == MoveController::kTorque)
      gravity = model::gravityTorques(arm, plant.q);
    if (activity == Activity::kMotion && motion.controller == MoveController::kJointImpedance)
      joint_damping = jointImpedanceDamping(model_dynamics, settings.joint_stiffness, spec.dof);
    if (activity == Activity::kDrag)
      for (int i = 0; i < spec.dof; ++i)
        joint_damping[i] = params.armature[i] >= 0.1 ? kDragJointDampingLarge : kDragJointDampingSmall;
  }

  // Hand guiding: the limits are walls (drag_walls.h); the TCP, the wrist centre and the arm angle
  // are linearised over the cycle for them.
  const bool dragging = motors_on && activity == Activity::kDrag;
  const TcpLinearization tcp = dragging ? tcpLinearization() : TcpLinearization{};
  const ArmAngleLinearization arm_angle = dragging ? armAngleLinearization() : ArmAngleLinearization{};

  const JointVector dq_before = plant.dq;
  JointVector motor_sum = JointVector::Zero();
  JointVector drive_sum = JointVector::Zero();  // motor torque minus friction
  for (int s = 1; s <= kSubsteps; ++s) {
    if (!motors_on) {
      advanceBraked(plant, params, kSubstep);
      continue;
    }
    JointVector demand = servoTorque(double(s - 1) / kSubsteps, cartesian, gravity, joint_damping);
    if (dragging) demand += dragWallTorque(tcp, arm_angle);
    const JointVector tau = saturateTorque(params, demand);
    motor_sum += tau;
    drive_sum += tau - frictionTorque(params, plant.dq);
    advancePowered(plant, *physical, params, tau, scene_torque, kSubstep);
    if (dragging) holdAtDragWalls(tcp, arm_angle, *physical);  // the brakes hold what the motors cannot
  }
  measure(dq_before, motor_sum, drive_sum, scene_torque, physical->bias);
}

void Controller::Impl::measure(const JointVector& dq_before, const JointVector& motor_sum,
                               const JointVector& drive_sum, const JointVector& scene_torque,
                               const JointVector& physical_bias) {
  meas.ddq = (plant.dq - dq_before) / kCycle;
  meas.motor_torque = motor_sum / kSubsteps;
  const JointVector drive = drive_sum / kSubsteps;
  // Link-side torque sensors: what the motors pass on, or, braked, what the brakes carry.
  meas.joint_torque = motors_on ? JointVector(drive - params.armature.cwiseProduct(meas.ddq))
                                : JointVector(physical_bias - scene_torque);
  // Momentum balance of the controller's own model: whatever the motors and the model's
  // inertia, Coriolis and gravity do not explain is an external torque (or a wrong load).
  const JointVector estimate =
      motors_on ? JointVector(model_dynamics.inertia * meas.ddq + model_dynamics.bias - drive) : scene_torque;
  lowPassStep(meas.external_torque, estimate, alpha(kObserverCutoffHz));
  const double a_torque = alpha(settings.measured_torque_filter_hz);
  lowPassStep(meas.motor_torque_filtered, meas.motor_torque, a_torque);
  lowPassStep(meas.joint_torque_filtered, meas.joint_torque, a_torque);

  const Vector6d twist_before = meas.twist;
  const double psi_before = meas.psi;
  meas.tcp = model::tcpPose(arm, plant.q);
  meas.jacobian = model::tcpJacobian(arm, plant.q);
  meas.twist = meas.jacobian * plant.dq;
  meas.twist_rate = (meas.twist - twist_before) / kCycle;
  meas.psi = spec.dof == 7 ? model::armAngle(arm, plant.q) : 0.0;
  meas.psi_rate = wrapAngle(meas.psi - psi_before) / kCycle;
  // The wrench at the TCP that explains the estimated joint torques (damped least squares).
  const model::Jacobian& j = meas.jacobian;
  const Eigen::Matrix<double, 6, 6> jjt = j * j.transpose() + 1e-6 * Eigen::Matrix<double, 6, 6>::Identity();
  meas.external_wrench = jjt.ldlt().solve(j * meas.external_torque);
}

void Controller::Impl::supervise() {
  if (!motors_on) return;
  ErrorBits bits{};
  bool power_off = false;
  if (settings.safety_box.active && !box_allowance.contains(settings.safety_box, meas.tcp.translation())) {
    raise(bits, kActualCartesianPositionLimitsViolation);
    power_off = true;
  }
  if (positionControlled() && collisionDetected(meas.external_torque, settings.collision_thresholds, spec.dof)) {
    raise(bits, kCollision);
    power_off = true;
  }
  if (activity != Activity::kHold) {
    const bool cartesian_motion = activity == Activity::kMotion && motion.generator == MoveGenerator::kCartesianPosition;
    const bool cartesian_drag = activity == Activity::kDrag && drag.space == 1;
    const bool torque_motion = activity == Activity::kMotion && motion.controller == MoveController::kTorque;
    ActualChecks checks;
    checks.cartesian = cartesian_motion || cartesian_drag || torque_motion;
    checks.elbow = cartesian_motion || cartesian_drag;
    checks.accelerations = activity == Activity::kMotion;
    const MeasuredMotion measured{plant.q, plant.dq, meas.ddq, meas.twist, meas.twist_rate, meas.psi_rate};
    checkActualMotion(measured, joint_allowance.lower, joint_allowance.upper, limits,
                      model::controllerCartesianLimits(), checks, spec.dof, bits);
  }
  if (!anyError(bits)) return;
  raiseErrors(bits);
  if (power_off) powerOff();
}

}  // namespace xmate::sim
