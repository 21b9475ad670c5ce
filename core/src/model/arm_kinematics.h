// SPDX-License-Identifier: Apache-2.0
// model::ArmKinematics: the XmateModel calls (xmate/model.h) for any robot model of any family --
// the xMates and the KUKA arms alike -- on std::array values. XmateModel is a thin shell over one;
// the teach layer and the planners' joint-limit checks use it directly, so they work on every
// RobotSpec. Copyable; one object per thread (not synchronised). Set-up (constructor, SetCoor, ...)
// allocates; the queries do not and are real-time safe.
#pragma once

#include <array>

#include "model/arm_model.h"
#include "model/robot_spec.h"

namespace xmate::model {

class ArmKinematics {
 public:
  // Loads the model's URDF (resources/robots/NAME.urdf). Throws std::runtime_error if it cannot.
  explicit ArmKinematics(const RobotSpec& spec);

  // The meaning of each call is XmateModel's (xmate/model.h); GetJointPos returns an IkStatus as int.
  std::array<double, 16> GetCartPose(const std::array<double, 7>& q) const;
  int GetJointPos(const std::array<double, 16>& pose, double psi, const std::array<double, 7>& q_init,
                  std::array<double, 7>& q_out) const;
  std::array<double, 42> Jacobian(const std::array<double, 7>& q) const;
  void GetTauNoFriction(const std::array<double, 7>& q, const std::array<double, 7>& dq,
                        const std::array<double, 7>& ddq, std::array<double, 7>& full,
                        std::array<double, 7>& inertial, std::array<double, 7>& coriolis,
                        std::array<double, 7>& gravity) const;
  double GetPsi(const std::array<double, 7>& q) const;
  std::array<double, 49> MassMatrix(const std::array<double, 7>& q) const;
  // Set-up. Each throws std::invalid_argument naming `who` (the caller's API name, e.g.
  // "XmateModel::SetCoor") and what to pass instead.
  void SetCoor(const std::array<double, 16>& F_T_EE, const char* who = "SetCoor");
  void SetLoad(double mass, const std::array<double, 3>& center, const std::array<double, 9>& inertia);
  void SetJointLimit(const std::array<double, 7>& upper_deg, const std::array<double, 7>& lower_deg);
  void SetSpeedCheckInterval(double seconds);
  int Dof() const { return arm_.dof; }

  const RobotSpec& spec() const { return *spec_; }
  const ArmModel& arm() const { return arm_; }

 private:
  const RobotSpec* spec_;
  ArmModel arm_;
};

}  // namespace xmate::model
