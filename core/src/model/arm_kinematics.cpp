// SPDX-License-Identifier: Apache-2.0
// model::ArmKinematics (arm_kinematics.h): the XmateModel calls as std::array conversions around
// the internal ArmModel (kinematics.h, inverse_kinematics.h, dynamics.h).
#include "model/arm_kinematics.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "model/dynamics.h"
#include "model/inverse_kinematics.h"
#include "model/kinematics.h"
#include "model/urdf_loader.h"

namespace xmate::model {
namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

JointVector toJointVector(const std::array<double, 7>& a, int dof) {
  JointVector v = JointVector::Zero();
  for (int i = 0; i < dof; ++i) v[i] = a[i];
  return v;
}

std::array<double, 7> toArray(const JointVector& v) {
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

}  // namespace

ArmKinematics::ArmKinematics(const RobotSpec& spec) : spec_(&spec), arm_(makeArmModel(loadRobotChain(spec), spec)) {}

std::array<double, 16> ArmKinematics::GetCartPose(const std::array<double, 7>& q) const {
  return toRowMajor(tcpPose(arm_, toJointVector(q, arm_.dof)));
}

int ArmKinematics::GetJointPos(const std::array<double, 16>& pose, double psi, const std::array<double, 7>& q_init,
                               std::array<double, 7>& q_out) const {
  JointVector q;
  const IkStatus status = inverseKinematics(arm_, toMatrix(pose), psi, toJointVector(q_init, arm_.dof), q);
  if (status == IkStatus::kOk) q_out = toArray(q);
  return static_cast<int>(status);
}

std::array<double, 42> ArmKinematics::Jacobian(const std::array<double, 7>& q) const {
  std::array<double, 42> a{};
  Eigen::Map<Eigen::Matrix<double, 6, 7, Eigen::RowMajor>>(a.data()) = tcpJacobian(arm_, toJointVector(q, arm_.dof));
  return a;
}

void ArmKinematics::GetTauNoFriction(const std::array<double, 7>& q, const std::array<double, 7>& dq,
                                     const std::array<double, 7>& ddq, std::array<double, 7>& full,
                                     std::array<double, 7>& inertial, std::array<double, 7>& coriolis,
                                     std::array<double, 7>& gravity) const {
  const int dof = arm_.dof;
  const TorqueTerms t = torqueTerms(arm_, toJointVector(q, dof), toJointVector(dq, dof), toJointVector(ddq, dof));
  full = toArray(t.full);
  inertial = toArray(t.inertial);
  coriolis = toArray(t.coriolis);
  gravity = toArray(t.gravity);
}

double ArmKinematics::GetPsi(const std::array<double, 7>& q) const { return armAngle(arm_, toJointVector(q, arm_.dof)); }

std::array<double, 49> ArmKinematics::MassMatrix(const std::array<double, 7>& q) const {
  std::array<double, 49> a{};
  Eigen::Map<Eigen::Matrix<double, 7, 7, Eigen::RowMajor>>(a.data()) = massMatrix(arm_, toJointVector(q, arm_.dof));
  return a;
}

void ArmKinematics::SetCoor(const std::array<double, 16>& F_T_EE, const char* who) {
  const Eigen::Matrix4d m = toMatrix(F_T_EE);
  if (!isRigidTransform(m))
    throw std::invalid_argument(
        std::string(who) +
        ": F_T_EE is not a homogeneous rigid transform (NaN/Inf, last row not 0 0 0 1, or rotation not orthonormal "
        "within 1e-6); pass a row-major 4x4 pose of the TCP in the flange frame");
  Eigen::Isometry3d tool = Eigen::Isometry3d::Identity();
  tool.linear() = m.topLeftCorner<3, 3>();
  tool.translation() = m.topRightCorner<3, 1>();
  setTool(arm_, tool);
}

void ArmKinematics::SetLoad(double mass, const std::array<double, 3>& center, const std::array<double, 9>& inertia) {
  Payload p;
  p.mass = mass;
  p.com = Eigen::Vector3d(center[0], center[1], center[2]);
  p.inertia = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(inertia.data());
  setPayload(arm_, p);
}

void ArmKinematics::SetJointLimit(const std::array<double, 7>& upper_deg, const std::array<double, 7>& lower_deg) {
  JointVector lower = JointVector::Zero(), upper = JointVector::Zero();
  for (int i = 0; i < arm_.dof; ++i) {
    lower[i] = lower_deg[i] * kDegToRad;
    upper[i] = upper_deg[i] * kDegToRad;
  }
  setSoftLimits(arm_, lower, upper);
}

void ArmKinematics::SetSpeedCheckInterval(double seconds) { setSpeedCheckInterval(arm_, seconds); }

}  // namespace xmate::model
