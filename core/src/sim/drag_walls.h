// SPDX-License-Identifier: Apache-2.0
// Limits feel like walls while hand guiding: a stiff spring with damping over the last few degrees
// before each joint's allowed limit and the last few centimetres inside each face of the active
// safety box, added to the drag law; and, when a pull exceeds what the motors can resist, the
// joint's brake (or, for the box, the minimal joint-velocity correction) holds the arm at the wall.
// Also the guiding speed limit: a hard push saturates the arm's speed instead of tripping the
// velocity monitors. Numbers and reasons: docs/simulator_controller.md, "Hand guiding (drag)". Allocation-free.
#pragma once

#include <Eigen/Geometry>

#include "model/arm_model.h"
#include "sim/allowance.h"
#include "sim/controller_settings.h"
#include "sim/plant.h"

namespace xmate::sim {

// Joint walls: width before the allowed limit, and the speed at which a joint released deep in the
// wall is pushed back out (sets the damping, below).
inline constexpr double kJointWallWidth = 5.0 * 3.14159265358979323846 / 180.0;  // rad (5 deg)
inline constexpr double kJointWallReturnSpeed = 0.5;                             // rad/s
// Box walls: width inside each face, the spring's force at the face, the return speed, and how far
// inside the face the hard hold begins (so numerical drift never carries the TCP across it).
inline constexpr double kBoxWallWidth = 0.05;        // m
inline constexpr double kBoxWallForce = 200.0;       // N at the face
inline constexpr double kBoxWallReturnSpeed = 0.2;   // m/s
inline constexpr double kBoxHoldInset = 0.001;       // m

// Guiding speed limit: above kGuidingSpeedOnset of a joint's rated speed a damping sets in that
// reaches the motor's peak torque at kGuidingSpeedFull of it, so a push the motor can resist
// saturates the joint's speed below the velocity monitor's threshold (bit 3, 1.1 x rated) instead of
// stopping the arm. The TCP's speed is limited the same way (bit 4 watches it in Cartesian guiding).
inline constexpr double kGuidingSpeedOnset = 0.6;    // x rated joint speed
inline constexpr double kGuidingSpeedFull = 0.9;     // x rated joint speed
inline constexpr double kGuidingTcpSpeedOnset = 0.5; // m/s
inline constexpr double kGuidingTcpSpeedFull = 1.0;  // m/s
inline constexpr double kGuidingTcpForce = 300.0;    // N at kGuidingTcpSpeedFull

// Where each wall's spring begins. Normally a wall's width before the allowed limit; when hand
// guiding starts deeper inside a wall than that, the spring begins where the arm is (it never
// pushes the arm by itself at startDrag) and follows the arm back out of the wall.
struct WallOnsets {
  JointVector joint_lower = JointVector::Zero(), joint_upper = JointVector::Zero();  // rad
  Eigen::Vector3d box_lower = Eigen::Vector3d::Zero(), box_upper = Eigen::Vector3d::Zero();  // m, box frame

  void reset(const JointVector& q, const JointAllowance& joints, const Eigen::Vector3d& box_local,
             const BoxAllowance& box, int dof);
  void ratchet(const JointVector& q, const JointAllowance& joints, const Eigen::Vector3d& box_local,
               const BoxAllowance& box, int dof);
};

// The TCP position as a linear function of q over one cycle: p(q) = p0 + jv (q - q0).
struct TcpLinearization {
  Eigen::Vector3d p0 = Eigen::Vector3d::Zero();
  Eigen::Matrix<double, 3, model::kMaxDof> jv = Eigen::Matrix<double, 3, model::kMaxDof>::Zero();
  JointVector q0 = JointVector::Zero();

  Eigen::Vector3d at(const JointVector& q) const { return p0 + jv * (q - q0); }
};

// Spring k = peak torque / width (the motor's peak torque at the limit) and damping of both
// directions growing with the depth, c = (peak torque / return speed) * min(1, depth / width).
JointVector jointWallTorque(const WallOnsets& onsets, const PlantParams& params, const PlantState& measured);

// The box walls' force at the TCP, mapped to joint torques (jv^T F). box must be active.
JointVector boxWallTorque(const WallOnsets& onsets, const SafetyBox& box, const TcpLinearization& tcp,
                          const PlantState& measured);

// The guiding speed limit's torque (above): per joint against velocity_limits (rad/s), and along
// the TCP's velocity (tcp.jv dq) mapped to joint torques.
JointVector guidingSpeedTorque(const PlantParams& params, const JointVector& velocity_limits,
                               const TcpLinearization& tcp, const PlantState& measured);

// After an integration sub-step, the arm is held at the walls like at rigid stops. Box faces (the
// TCP at or beyond the plane kBoxHoldInset inside a face) and joints (at or beyond their allowed
// limits: the joint's brake) each get the impulse a rigid stop gives: the outward rate along the
// constraint g (the TCP's velocity along the face normal, g = jv^T n; or the joint's velocity) is
// removed with the least kinetic energy, dq -= M^-1 g (g.dq) / (g^T M^-1 g) -- the minimal joint-
// velocity correction in the arm's inertia metric, so a push along the constraint leaves no motion
// elsewhere -- and an overshoot is taken back along the same direction; two passes for stops
// acting at once. Last, each joint is clamped to its allowed limit with its outward velocity
// zeroed, so no joint ever passes it. dynamics: the arm's (physical) inertia of this cycle.
void holdAtWalls(PlantState& state, const FrozenDynamics& dynamics, const JointAllowance& joints, bool box_active,
                 const SafetyBox& box, const BoxAllowance& box_allowance, const TcpLinearization& tcp, int dof);

}  // namespace xmate::sim
