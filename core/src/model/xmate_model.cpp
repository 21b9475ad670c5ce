// SPDX-License-Identifier: Apache-2.0
// xmate::XmateModel (xmate/model.h): the vendor-compatible model API as std::array conversions
// around the internal ArmModel (kinematics.h, inverse_kinematics.h, dynamics.h). The arm is loaded
// from the model's URDF with urdfdom when the XmateModel is constructed.
#include <xmate/model.h>
#include <xmate/robot.h>

#include <cmath>
#include <stdexcept>

#include "model/arm_model.h"
#include "model/dynamics.h"
#include "model/inverse_kinematics.h"
#include "model/kinematics.h"
#include "model/robot_spec.h"
#include "model/urdf_loader.h"

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

namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

model::JointVector toJointVector(const std::array<double, 7>& a, int dof) {
  model::JointVector v = model::JointVector::Zero();
  for (int i = 0; i < dof; ++i) v[i] = a[i];
  return v;
}

std::array<double, 7> toArray(const model::JointVector& v) {
  std::array<double, 7> a{};
  for (int i = 0; i < 7; ++i) a[i] = v[i];
  return a;
}

Eigen::Matrix4d toMatrix(const std::array<double, 16>& row_major) {
  return Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(row_major.data());
}

std::array<double, 16> toRowMajor(const Eigen::Isometry3d& pose) {
  std::array<double, 16> a{};
  Eigen::Map<Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(a.data()) = pose.matrix();
  return a;
}

model::ArmModel loadArm(XmateType type) {
  const model::RobotSpec& spec = model::robotSpec(type);
  return model::makeArmModel(model::loadRobotChain(spec), spec);
}

}  // namespace

struct XmateModel::Impl {
  XmateType type;
  model::ArmModel arm;
};

// With a robot, the model starts with the tool and payload last set through it (setCoor, setLoad).
XmateModel::XmateModel(Robot* robot, XmateType type) : XmateModel(type) {
  if (robot == nullptr) return;
  SetCoor(robot->toolFrame());
  double mass = 0;
  std::array<double, 3> center{};
  std::array<double, 9> inertia{};
  robot->load(mass, center, inertia);
  SetLoad(mass, center, inertia);
}
XmateModel::XmateModel(XmateType type) : impl_(std::make_unique<Impl>(Impl{type, loadArm(type)})) {}
XmateModel::~XmateModel() = default;
XmateModel::XmateModel(const XmateModel& other) : impl_(std::make_unique<Impl>(*other.impl_)) {}
XmateModel& XmateModel::operator=(const XmateModel& other) {
  if (this != &other) *impl_ = *other.impl_;
  return *this;
}
XmateModel::XmateModel(XmateModel&&) noexcept = default;
XmateModel& XmateModel::operator=(XmateModel&&) noexcept = default;

std::array<double, 16> XmateModel::GetCartPose(const std::array<double, 7>& q) {
  return toRowMajor(model::tcpPose(impl_->arm, toJointVector(q, impl_->arm.dof)));
}

int XmateModel::GetJointPos(const std::array<double, 16>& pose, double psi, const std::array<double, 7>& q_init,
                            std::array<double, 7>& q_out) {
  model::JointVector q;
  const IkStatus status =
      model::inverseKinematics(impl_->arm, toMatrix(pose), psi, toJointVector(q_init, impl_->arm.dof), q);
  if (status == IkStatus::kOk) q_out = toArray(q);
  return static_cast<int>(status);
}

std::array<double, 42> XmateModel::Jacobian(const std::array<double, 7>& q) {
  std::array<double, 42> a{};
  Eigen::Map<Eigen::Matrix<double, 6, 7, Eigen::RowMajor>>(a.data()) =
      model::tcpJacobian(impl_->arm, toJointVector(q, impl_->arm.dof));
  return a;
}

void XmateModel::GetTauNoFriction(const std::array<double, 7>& q, const std::array<double, 7>& dq,
                                  const std::array<double, 7>& ddq, std::array<double, 7>& full,
                                  std::array<double, 7>& inertial, std::array<double, 7>& coriolis,
                                  std::array<double, 7>& gravity) {
  const int dof = impl_->arm.dof;
  const model::TorqueTerms t = model::torqueTerms(impl_->arm, toJointVector(q, dof), toJointVector(dq, dof),
                                                  toJointVector(ddq, dof));
  full = toArray(t.full);
  inertial = toArray(t.inertial);
  coriolis = toArray(t.coriolis);
  gravity = toArray(t.gravity);
}

void XmateModel::SetCoor(const std::array<double, 16>& F_T_EE) {
  const Eigen::Matrix4d m = toMatrix(F_T_EE);
  if (!model::isRigidTransform(m))
    throw std::invalid_argument(
        "XmateModel::SetCoor: F_T_EE is not a homogeneous rigid transform (NaN/Inf, last row not 0 0 0 1, or "
        "rotation not orthonormal within 1e-6); pass a row-major 4x4 pose of the TCP in the flange frame");
  Eigen::Isometry3d tool = Eigen::Isometry3d::Identity();
  tool.linear() = m.topLeftCorner<3, 3>();
  tool.translation() = m.topRightCorner<3, 1>();
  model::setTool(impl_->arm, tool);
}

void XmateModel::SetLoad(double mass, const std::array<double, 3>& center, const std::array<double, 9>& inertia) {
  model::Payload p;
  p.mass = mass;
  p.com = Eigen::Vector3d(center[0], center[1], center[2]);
  p.inertia = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(inertia.data());
  model::setPayload(impl_->arm, p);
}

double XmateModel::GetPsi(const std::array<double, 7>& q) {
  return model::armAngle(impl_->arm, toJointVector(q, impl_->arm.dof));
}

std::array<double, 49> XmateModel::MassMatrix(const std::array<double, 7>& q) {
  std::array<double, 49> a{};
  Eigen::Map<Eigen::Matrix<double, 7, 7, Eigen::RowMajor>>(a.data()) =
      model::massMatrix(impl_->arm, toJointVector(q, impl_->arm.dof));
  return a;
}

void XmateModel::SetJointLimit(const std::array<double, 7>& upper_deg, const std::array<double, 7>& lower_deg) {
  model::JointVector lower = model::JointVector::Zero(), upper = model::JointVector::Zero();
  for (int i = 0; i < impl_->arm.dof; ++i) {
    lower[i] = lower_deg[i] * kDegToRad;
    upper[i] = upper_deg[i] * kDegToRad;
  }
  model::setSoftLimits(impl_->arm, lower, upper);
}

void XmateModel::SetSpeedCheckInterval(double seconds) { model::setSpeedCheckInterval(impl_->arm, seconds); }

int XmateModel::Dof() const { return impl_->arm.dof; }

XmateType XmateModel::Type() const { return impl_->type; }

}  // namespace xmate
