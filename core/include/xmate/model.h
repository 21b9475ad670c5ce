// SPDX-License-Identifier: Apache-2.0
// Kinematics and dynamics of an xMate arm (docs/api.md, "XmateModel"; docs/kinematics.md).
// The model is built at run time from the robot's URDF (resources/robots/) with urdfdom.
// Poses are 4x4 homogeneous matrices in row-major order, metres and radians.
#pragma once

#include <array>
#include <memory>
#include <string>

#include <xmate/types.h>

namespace xmate {

class Robot;

// Threads: a model belongs to one thread at a time (copy it for another). The constructors load
// the robot's description and allocate: make the model before Control(). GetCartPose, GetJointPos,
// Jacobian, GetTauNoFriction, GetPsi and MassMatrix are real-time safe (no allocation, no lock, no
// system call), so a Control() callback may call them every cycle; the setters are not.
class XmateModel {
 public:
  // Return codes of GetJointPos (0 = success); the vendor manual groups them in pairs. Exact
  // criteria, the order of the checks and the singularity measures: docs/kinematics.md.
  enum IkResult : int {
    kIkOk = 0,
    kIkTooFar = -1,            // wrist centre beyond the stretched arm's reach
    kIkTooClose = -2,          // wrist centre closer to the shoulder than the elbow can fold
    kIkInvalidPose = -3,       // pose is not a rigid transform (NaN/Inf, rotation not orthonormal within
                               // 1e-6, last row not 0 0 0 1), or q_init / psi not finite
    kIkArmJointTooFast = -4,   // an arm joint (J1..J4; 6-axis J1..J3) would exceed its rated speed
    kIkWristJointTooFast = -5, // only a wrist joint would exceed its rated speed
    kIkAboveSoftLimit = -6,    // every solution breaks a soft limit; the nearest first breaks an upper one
    kIkBelowSoftLimit = -7,    // ... a lower one
    kIkSingular = -8,          // the pose is (within 1e-6) a shoulder, elbow or wrist singularity
  };

  // robot may be nullptr: an offline model with no tool and no payload. With a robot, the model
  // starts with the tool and payload last set through that robot (setCoor, setLoad); SetCoor /
  // SetLoad change the model's copy only.
  XmateModel(Robot* robot, XmateType type);
  explicit XmateModel(XmateType type);
  ~XmateModel();
  XmateModel(const XmateModel&);
  XmateModel& operator=(const XmateModel&);
  XmateModel(XmateModel&&) noexcept;
  XmateModel& operator=(XmateModel&&) noexcept;

  // Forward kinematics: flange pose in the base frame, or TCP pose after SetCoor.
  std::array<double, 16> GetCartPose(const std::array<double, 7>& q);

  // Closed-form inverse kinematics of the flange/TCP pose. 7-axis models use the arm angle psi
  // (see GetPsi); 6-axis models ignore it. Of the up to 8 branch solutions, picks the one nearest
  // q_init within the soft limits, then checks that reaching it from q_init within one
  // SetSpeedCheckInterval() step (default 1 ms) keeps every joint within its rated speed.
  // Returns an IkResult; q_out is written only on kIkOk.
  int GetJointPos(const std::array<double, 16>& pose, double psi, const std::array<double, 7>& q_init,
                  std::array<double, 7>& q_out);

  // Geometric Jacobian of the flange/TCP, 6x7 row-major, base frame, rows [v; omega].
  // Column 6 is zero on 6-axis models.
  std::array<double, 42> Jacobian(const std::array<double, 7>& q);

  // Rigid-body inverse dynamics without friction (recursive Newton-Euler), with tool and load:
  // full = inertial + coriolis + gravity.
  void GetTauNoFriction(const std::array<double, 7>& q, const std::array<double, 7>& dq,
                        const std::array<double, 7>& ddq, std::array<double, 7>& full,
                        std::array<double, 7>& inertial, std::array<double, 7>& coriolis,
                        std::array<double, 7>& gravity);

  // Tool centre point relative to the flange (homogeneous, row-major, m and rad).
  void SetCoor(const std::array<double, 16>& F_T_EE);
  // Payload: mass (kg), centre of mass in the flange frame (m), inertia about the centre of mass
  // in the flange frame (kg m^2, row-major 3x3).
  void SetLoad(double mass, const std::array<double, 3>& center, const std::array<double, 9>& inertia);

  // ---- Extensions beyond the vendor API (RCI Studio) ----

  // Arm angle of configuration q (7-axis), as GetJointPos expects it; 0 on 6-axis models. psi is
  // the rotation about the shoulder->wrist line from the reference configuration (q3 = 0, same
  // q4, joint 1 facing the wrist) to q; radians in (-pi, pi].
  double GetPsi(const std::array<double, 7>& q);
  // Joint-space mass matrix M(q), 7x7 row-major (unused rows/columns zero on 6-axis models).
  std::array<double, 49> MassMatrix(const std::array<double, 7>& q);
  // Soft joint limits used by GetJointPos, in degrees (default: the hardware limits, docs/robot_models.md).
  void SetJointLimit(const std::array<double, 7>& upper_deg, const std::array<double, 7>& lower_deg);
  // Time step over which GetJointPos checks the rated joint speed (codes -4/-5): q_init is taken as
  // the position one step earlier. Default 0.001 s (one RCI cycle); 0 turns the check off.
  void SetSpeedCheckInterval(double seconds);
  // Number of joints of this model (6 or 7).
  int Dof() const;
  XmateType Type() const;

 private:
  friend struct XmateModelAccess;  // RCI Studio's own code (not part of this API)
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace xmate
