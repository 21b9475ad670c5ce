// SPDX-License-Identifier: Apache-2.0
// Spring-damper walls and the hold at the walls while hand guiding (drag_walls.h).
#include "sim/drag_walls.h"

#include <algorithm>
#include <cmath>

namespace xmate::sim {
namespace {

// A spring beginning at `onset` (upper side: x above it; lower: below) follows x back out of the
// wall, but never starts farther out than `width` before the limit.
void followOut(double x, double limit_lower, double limit_upper, double width, double& onset_lower,
               double& onset_upper) {
  onset_upper = std::max(limit_upper - width, std::min(onset_upper, x));
  onset_lower = std::min(limit_lower + width, std::max(onset_lower, x));
}

// Force (or torque) of one wall along its outward direction: depth > 0 inside the wall, velocity
// positive outward. Spring plus damping that grows with the depth, in both directions.
double wallForce(double depth, double velocity, double stiffness, double max_damping, double width) {
  if (depth <= 0) return 0.0;
  const double damping = max_damping * std::min(1.0, depth / width);
  return -stiffness * depth - damping * velocity;
}

// A rigid constraint g . dq <= 0 that is active: the impulse a rigid stop applies along g removes
// the outward rate g . dq with the least kinetic energy (dq -= M^-1 g (g . dq) / (g^T M^-1 g)), and
// `beyond` (how far g . q has passed the stop) is taken back along the same direction.
void stopAlong(PlantState& state, const FrozenDynamics& dynamics, const JointVector& g, double beyond) {
  const JointVector minv_g = dynamics.inertia_ldlt.solve(g);  // unused joints: M is 1 there, g 0
  const double weight = g.dot(minv_g);
  if (weight < 1e-12) return;  // the joints cannot move along g
  const double outward = g.dot(state.dq);
  if (outward > 0) state.dq -= minv_g * (outward / weight);
  if (beyond > 0) state.q -= minv_g * (beyond / weight);
}

// The TCP at or beyond `plane` along `normal` (its coordinate where the hold begins): held there.
void holdAtFace(PlantState& state, const FrozenDynamics& dynamics, const TcpLinearization& tcp,
                const Eigen::Vector3d& normal, double plane) {
  const double beyond = normal.dot(tcp.at(state.q)) - plane;
  if (beyond < 0) return;
  const JointVector g = tcp.jv.transpose() * normal;  // d(normal . p) / dq
  stopAlong(state, dynamics, g, beyond);
}

// The wrist centre at or within the wrist-axis stop's hold radius: held there (g = its rate of
// approach to the J1 axis). Nothing to hold along on the axis itself (no direction).
void holdOffWristAxis(PlantState& state, const FrozenDynamics& dynamics, const WristAxisStop& stop,
                      const ArmAngleLinearization& arm_angle) {
  if (!stop.active || !arm_angle.defined) return;
  const Eigen::Vector2d w = arm_angle.wristAt(state.q);
  const double r = w.norm();
  const double beyond = stop.hold - r;
  if (beyond < 0 || r < 1e-9) return;
  const JointVector g = -(arm_angle.jw.transpose() * (w / r));  // -d r / dq
  stopAlong(state, dynamics, g, beyond);
}

// Joint i at or beyond its allowed limit: held by its brake (the impulse acts on the whole arm).
void holdJoint(PlantState& state, const FrozenDynamics& dynamics, const JointAllowance& joints, int i) {
  const double above = state.q[i] - joints.upper[i], below = joints.lower[i] - state.q[i];
  if (above < 0 && below < 0) return;
  JointVector g = JointVector::Zero();
  g[i] = above >= 0 ? 1.0 : -1.0;  // outward
  stopAlong(state, dynamics, g, std::max(above, below));
}

}  // namespace

void WallOnsets::reset(const JointVector& q, const JointAllowance& joints, const Eigen::Vector3d& box_local,
                       const BoxAllowance& box, int dof) {
  joint_lower = JointVector::Constant(-INFINITY);
  joint_upper = JointVector::Constant(INFINITY);
  box_lower = Eigen::Vector3d::Constant(-INFINITY);
  box_upper = Eigen::Vector3d::Constant(INFINITY);
  ratchet(q, joints, box_local, box, dof);
}

void WallOnsets::ratchet(const JointVector& q, const JointAllowance& joints, const Eigen::Vector3d& box_local,
                         const BoxAllowance& box, int dof) {
  for (int i = 0; i < dof; ++i)
    followOut(q[i], joints.lower[i], joints.upper[i], kJointWallWidth, joint_lower[i], joint_upper[i]);
  for (int a = 0; a < 3; ++a)
    followOut(box_local[a], box.lower[a], box.upper[a], kBoxWallWidth, box_lower[a], box_upper[a]);
}

void WristAxisStop::reset(bool seven_axis, double radius) {
  active = seven_axis;
  hold = std::min(kWristAxisHoldRadius, radius);
  spring = -INFINITY;
  ratchet(radius);
}

void WristAxisStop::ratchet(double radius) {
  if (!active) return;
  hold = std::max(hold, std::min(kWristAxisHoldRadius, radius));
  spring = std::min(hold + kWristAxisWallWidth, std::max(spring, radius));
}

JointVector jointWallTorque(const WallOnsets& onsets, const PlantParams& params, const PlantState& measured) {
  JointVector tau = JointVector::Zero();
  for (int i = 0; i < params.dof; ++i) {
    const double stiffness = params.peak_torque[i] / kJointWallWidth;
    const double damping = params.peak_torque[i] / kJointWallReturnSpeed;
    const double q = measured.q[i], dq = measured.dq[i];
    tau[i] += wallForce(q - onsets.joint_upper[i], dq, stiffness, damping, kJointWallWidth);
    tau[i] -= wallForce(onsets.joint_lower[i] - q, -dq, stiffness, damping, kJointWallWidth);
  }
  return tau;
}

JointVector guidingSpeedTorque(const PlantParams& params, const JointVector& velocity_limits,
                               const TcpLinearization& tcp, const PlantState& measured) {
  JointVector tau = JointVector::Zero();
  for (int i = 0; i < params.dof; ++i) {
    const double onset = kGuidingSpeedOnset * velocity_limits[i];
    const double excess = std::abs(measured.dq[i]) - onset;
    if (excess <= 0) continue;
    const double span = (kGuidingSpeedFull - kGuidingSpeedOnset) * velocity_limits[i];
    tau[i] = -std::copysign(params.peak_torque[i] * std::min(1.0, excess / span), measured.dq[i]);
  }
  const Eigen::Vector3d v = tcp.jv * measured.dq;
  const double speed = v.norm();
  if (speed > kGuidingTcpSpeedOnset) {
    const double share = std::min(1.0, (speed - kGuidingTcpSpeedOnset) / (kGuidingTcpSpeedFull - kGuidingTcpSpeedOnset));
    tau -= tcp.jv.transpose() * (v / speed * (kGuidingTcpForce * share));
  }
  return tau;
}

JointVector armAngleSpeedTorque(const PlantParams& params, double elbow_velocity_limit,
                                const ArmAngleLinearization& arm_angle, const PlantState& measured) {
  JointVector tau = JointVector::Zero();
  if (!arm_angle.defined || arm_angle.wristAt(measured.q).norm() < kArmAngleDefinedRadius) return tau;
  const double rate = arm_angle.jpsi.dot(measured.dq);
  const double excess = std::abs(rate) - kGuidingSpeedOnset * elbow_velocity_limit;
  if (excess <= 0) return tau;
  double strain = 0;  // the largest |jpsi_i| / peak_i: its joint reaches its peak torque first
  for (int i = 0; i < params.dof; ++i) strain = std::max(strain, std::abs(arm_angle.jpsi[i]) / params.peak_torque[i]);
  if (strain <= 0) return tau;
  const double span = (kGuidingSpeedFull - kGuidingSpeedOnset) * elbow_velocity_limit;
  const double share = std::min(1.0, excess / span);
  return -std::copysign(share / strain, rate) * arm_angle.jpsi;
}

JointVector wristAxisWallTorque(const WristAxisStop& stop, const ArmAngleLinearization& arm_angle,
                                const PlantState& measured) {
  constexpr double kStiffness = kWristAxisWallForce / kWristAxisWallWidth;      // N/m
  constexpr double kDamping = kWristAxisWallForce / kWristAxisWallReturnSpeed;  // N s/m at full depth
  JointVector tau = JointVector::Zero();
  if (!stop.active || !arm_angle.defined) return tau;
  const Eigen::Vector2d w = arm_angle.wristAt(measured.q);
  const double r = w.norm();
  if (r < 1e-9) return tau;  // on the axis: no direction to push along
  const JointVector g = arm_angle.jw.transpose() * (w / r);  // d r / dq
  // The wall's limit lies towards the axis: depth and velocity measured that way.
  const double force = -wallForce(stop.spring - r, -g.dot(measured.dq), kStiffness, kDamping, kWristAxisWallWidth);
  return g * force;
}

JointVector boxWallTorque(const WallOnsets& onsets, const SafetyBox& box, const TcpLinearization& tcp,
                          const PlantState& measured) {
  constexpr double kStiffness = kBoxWallForce / kBoxWallWidth;      // N/m
  constexpr double kDamping = kBoxWallForce / kBoxWallReturnSpeed;  // N s/m at full depth
  const Eigen::Matrix3d r = box.frame.linear();
  const Eigen::Vector3d local = boxLocal(box, tcp.at(measured.q));
  const Eigen::Vector3d v_local = r.transpose() * (tcp.jv * measured.dq);
  Eigen::Vector3d f_local = Eigen::Vector3d::Zero();
  for (int a = 0; a < 3; ++a) {
    f_local[a] += wallForce(local[a] - onsets.box_upper[a], v_local[a], kStiffness, kDamping, kBoxWallWidth);
    f_local[a] -= wallForce(onsets.box_lower[a] - local[a], -v_local[a], kStiffness, kDamping, kBoxWallWidth);
  }
  return tcp.jv.transpose() * (r * f_local);
}

void holdAtWalls(PlantState& state, const FrozenDynamics& dynamics, const JointAllowance& joints, bool box_active,
                 const SafetyBox& box, const BoxAllowance& box_allowance, const TcpLinearization& tcp,
                 const WristAxisStop& wrist_stop, const ArmAngleLinearization& arm_angle, int dof) {
  const Eigen::Matrix3d r = box.frame.linear();
  const Eigen::Vector3d centre = box.frame.translation();
  constexpr int kPasses = 2;  // several stops at once: a second pass undoes what one did to another
  for (int pass = 0; pass < kPasses; ++pass) {
    for (int a = 0; box_active && a < 3; ++a) {
      const Eigen::Vector3d n = r.col(a);
      const double c = n.dot(centre);
      holdAtFace(state, dynamics, tcp, n, c + box_allowance.upper[a] - kBoxHoldInset);
      holdAtFace(state, dynamics, tcp, -n, -(c + box_allowance.lower[a] + kBoxHoldInset));
    }
    holdOffWristAxis(state, dynamics, wrist_stop, arm_angle);
    for (int i = 0; i < dof; ++i) holdJoint(state, dynamics, joints, i);
  }
  for (int i = 0; i < dof; ++i) {  // the brakes, last: a joint never passes its allowed limit
    if (state.q[i] >= joints.upper[i]) {
      state.q[i] = joints.upper[i];
      state.dq[i] = std::min(state.dq[i], 0.0);
    } else if (state.q[i] <= joints.lower[i]) {
      state.q[i] = joints.lower[i];
      state.dq[i] = std::max(state.dq[i], 0.0);
    }
  }
}

}  // namespace xmate::sim
