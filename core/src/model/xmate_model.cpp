// SPDX-License-Identifier: Apache-2.0
// xmate::XmateModel (xmate/model.h): the vendor-compatible model API, a shell over one
// model::ArmKinematics of the xMate model (arm_kinematics.h). The arm is loaded from the model's
// URDF with urdfdom when the XmateModel is constructed.
#include <xmate/model.h>

#include "model/arm_kinematics.h"
#include "model/inverse_kinematics.h"
#include "model/robot_spec.h"
#include "model/xmate_model_access.h"

namespace xmate {

using model::IkStatus;
static_assert(XmateModel::kIkOk == static_cast<int>(IkStatus::kOk) &&
              XmateModel::kIkTooFar == static_cast<int>(IkStatus::kBeyondReach) &&
              XmateModel::kIkTooClose == static_cast<int>(IkStatus::kTooClose) &&
              XmateModel::kIkInvalidPose == static_cast<int>(IkStatus::kInvalidPose) &&
              XmateModel::kIkArmJointTooFast == static_cast<int>(IkStatus::kArmJointTooFast) &&
              XmateModel::kIkWristJointTooFast == static_cast<int>(IkStatus::kWristJointTooFast) &&
              XmateModel::kIkAboveSoftLimit == static_cast<int>(IkStatus::kAboveSoftLimit) &&
              XmateModel::kIkBelowSoftLimit == static_cast<int>(IkStatus::kBelowSoftLimit) &&
              XmateModel::kIkSingular == static_cast<int>(IkStatus::kSingular),
              "XmateModel::IkResult and model::IkStatus must agree");

struct XmateModel::Impl {
  XmateType type;
  model::ArmKinematics kinematics;
};

// XmateModel(Robot*, XmateType) reads the robot: it is the client's (client/model_of_robot.cpp).
XmateModel::XmateModel(XmateType type)
    : impl_(std::make_unique<Impl>(Impl{type, model::ArmKinematics(model::robotSpec(type))})) {}
XmateModel::~XmateModel() = default;
XmateModel::XmateModel(const XmateModel& other) : impl_(std::make_unique<Impl>(*other.impl_)) {}
XmateModel& XmateModel::operator=(const XmateModel& other) {
  if (this != &other) *impl_ = *other.impl_;
  return *this;
}
XmateModel::XmateModel(XmateModel&&) noexcept = default;
XmateModel& XmateModel::operator=(XmateModel&&) noexcept = default;

std::array<double, 16> XmateModel::GetCartPose(const std::array<double, 7>& q) {
  return impl_->kinematics.GetCartPose(q);
}

int XmateModel::GetJointPos(const std::array<double, 16>& pose, double psi, const std::array<double, 7>& q_init,
                            std::array<double, 7>& q_out) {
  return impl_->kinematics.GetJointPos(pose, psi, q_init, q_out);
}

std::array<double, 42> XmateModel::Jacobian(const std::array<double, 7>& q) { return impl_->kinematics.Jacobian(q); }

void XmateModel::GetTauNoFriction(const std::array<double, 7>& q, const std::array<double, 7>& dq,
                                  const std::array<double, 7>& ddq, std::array<double, 7>& full,
                                  std::array<double, 7>& inertial, std::array<double, 7>& coriolis,
                                  std::array<double, 7>& gravity) {
  impl_->kinematics.GetTauNoFriction(q, dq, ddq, full, inertial, coriolis, gravity);
}

void XmateModel::SetCoor(const std::array<double, 16>& F_T_EE) { impl_->kinematics.SetCoor(F_T_EE, "XmateModel::SetCoor"); }

void XmateModel::SetLoad(double mass, const std::array<double, 3>& center, const std::array<double, 9>& inertia) {
  impl_->kinematics.SetLoad(mass, center, inertia);
}

double XmateModel::GetPsi(const std::array<double, 7>& q) { return impl_->kinematics.GetPsi(q); }

std::array<double, 49> XmateModel::MassMatrix(const std::array<double, 7>& q) { return impl_->kinematics.MassMatrix(q); }

void XmateModel::SetJointLimit(const std::array<double, 7>& upper_deg, const std::array<double, 7>& lower_deg) {
  impl_->kinematics.SetJointLimit(upper_deg, lower_deg);
}

void XmateModel::SetSpeedCheckInterval(double seconds) { impl_->kinematics.SetSpeedCheckInterval(seconds); }

int XmateModel::Dof() const { return impl_->kinematics.Dof(); }

XmateType XmateModel::Type() const { return impl_->type; }

model::ArmKinematics& XmateModelAccess::kinematics(XmateModel& model) { return model.impl_->kinematics; }

}  // namespace xmate
