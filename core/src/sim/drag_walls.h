// SPDX-License-Identifier: Apache-2.0
// Limits feel like walls while hand guiding: a stiff spring with damping over the last few degrees
// before each joint's allowed limit and the last few centimetres inside each face of the active
// safety box, added to the drag law; and, when a pull exceeds what the motors can resist, the
// joint's brake (or, for the box, the minimal joint-velocity correction) holds the arm at the wall.
// Also the guiding speed limit: a hard push saturates the arm's speed (and the 7-axis arm angle's
// rate) instead of tripping the velocity monitors; and, 7-axis, the wrist-axis wall that keeps the
// wrist centre off the J1 axis, where the arm angle is not defined and turns over by pi.
// Numbers and reasons: docs/simulator_controller.md, "Hand guiding (drag)". Allocation-free.
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

// Arm angle (7-axis). psi is the angle of the elbow plane about the shoulder-wrist line, measured
// from the vertical plane through the J1 axis and the wrist centre: it is not defined with the wrist
// centre on the J1 axis and turns over by pi when the wrist centre crosses it, and near it a small
// sideways motion of the wrist turns it fast (rate ~ sideways speed / distance). The wrist-axis wall
// keeps the wrist centre at least kWristAxisHoldRadius from the J1 axis: a spring over the
// kWristAxisWallWidth before that cylinder, kWristAxisWallForce at it, with damping like the box
// walls', and a hold at it. The arm angle's rate is limited like the joints' speeds, against
// v_elbow (bit 2 watches 1.1 x v_elbow): kGuidingSpeedOnset .. kGuidingSpeedFull of it.
inline constexpr double kWristAxisHoldRadius = 0.05;     // m from the J1 axis
inline constexpr double kWristAxisWallWidth = 0.05;      // m: the spring begins 0.1 m from the axis
inline constexpr double kWristAxisWallForce = 200.0;     // N at the hold radius
inline constexpr double kWristAxisWallReturnSpeed = 0.2;  // m/s
// Closer to the J1 axis than this (only when guiding started there) psi's rate is not limited:
// psi's Jacobian, and with it the limit's loop gain, grows as 1 / distance, and below about 2 mm
// the 4 kHz integration no longer follows it stably (psi has hardly a meaning there anyway).
inline constexpr double kArmAngleDefinedRadius = 0.002;  // m

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

// The wrist-axis wall of the 7-axis arm: the radius (distance of the wrist centre from the J1 axis)
// where its hold stands, normally kWristAxisHoldRadius, and where its spring begins, normally
// kWristAxisWallWidth farther out. Guiding that starts closer to the axis is held where it started
// and the spring begins there, both following the wrist centre back out (the joint walls' rule).
struct WristAxisStop {
  bool active = false;  // 7-axis
  double hold = 0;      // m
  double spring = 0;    // m

  void reset(bool seven_axis, double radius);
  void ratchet(double radius);
};

// The arm angle psi and the wrist centre's horizontal offset from the J1 axis (base x, y) as linear
// functions of q over one cycle (7-axis; `defined` false otherwise).
struct ArmAngleLinearization {
  bool defined = false;
  JointVector q0 = JointVector::Zero();
  JointVector jpsi = JointVector::Zero();  // d psi / dq
  Eigen::Vector2d wrist0 = Eigen::Vector2d::Zero();
  Eigen::Matrix<double, 2, model::kMaxDof> jw = Eigen::Matrix<double, 2, model::kMaxDof>::Zero();

  Eigen::Vector2d wristAt(const JointVector& q) const { return wrist0 + jw * (q - q0); }
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

// The arm angle's guiding speed limit: above kGuidingSpeedOnset x elbow_velocity_limit (rad/s) a
// damping against psi's rate (jpsi dq) that reaches, at kGuidingSpeedFull x it, the strongest torque
// along jpsi the motors have (the joint with the largest |jpsi_i| / peak_i at its peak torque).
// Zero where psi is not defined (6-axis, or closer than kArmAngleDefinedRadius to the J1 axis).
JointVector armAngleSpeedTorque(const PlantParams& params, double elbow_velocity_limit,
                                const ArmAngleLinearization& arm_angle, const PlantState& measured);

// The wrist-axis wall's force on the wrist centre, radially away from the J1 axis, mapped to joint
// torques: spring kWristAxisWallForce / kWristAxisWallWidth, damping growing with the depth up to
// kWristAxisWallForce / kWristAxisWallReturnSpeed (like the box walls).
JointVector wristAxisWallTorque(const WristAxisStop& stop, const ArmAngleLinearization& arm_angle,
                                const PlantState& measured);

// After an integration sub-step, the arm is held at the walls like at rigid stops. Box faces (the
// TCP at or beyond the plane kBoxHoldInset inside a face) and joints (at or beyond their allowed
// limits: the joint's brake) each get the impulse a rigid stop gives: the outward rate along the
// constraint g (the TCP's velocity along the face normal, g = jv^T n; or the joint's velocity) is
// removed with the least kinetic energy, dq -= M^-1 g (g.dq) / (g^T M^-1 g) -- the minimal joint-
// velocity correction in the arm's inertia metric, so a push along the constraint leaves no motion
// elsewhere -- and an overshoot is taken back along the same direction; two passes for stops
// acting at once. The wrist centre at or within the wrist-axis stop's hold radius is held the same
// way (g = the rate at which it approaches the J1 axis). Last, each joint is clamped to its allowed
// limit with its outward velocity zeroed, so no joint ever passes it. dynamics: the arm's
// (physical) inertia of this cycle.
void holdAtWalls(PlantState& state, const FrozenDynamics& dynamics, const JointAllowance& joints, bool box_active,
                 const SafetyBox& box, const BoxAllowance& box_allowance, const TcpLinearization& tcp,
                 const WristAxisStop& wrist_stop, const ArmAngleLinearization& arm_angle, int dof);

}  // namespace xmate::sim
