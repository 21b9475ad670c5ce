// SPDX-License-Identifier: Apache-2.0
// ExternalTorqueMap (external_torque.h): the core's J^T mapping on the model loaded from its URDF.
#include "plots/external_torque.h"

#include "model/kinematics.h"
#include "model/robot_spec.h"
#include "model/urdf_loader.h"

namespace rci::ui::plots {

namespace {
xmate::model::ArmModel loadArm(xmate::XmateType type) {
  const xmate::model::RobotSpec& spec = xmate::model::robotSpec(type);
  return xmate::model::makeArmModel(xmate::model::loadRobotChain(spec), spec);
}
}  // namespace

ExternalTorqueMap::ExternalTorqueMap(xmate::XmateType type) : arm_(loadArm(type)) {}

void ExternalTorqueMap::setTool(const std::array<double, 16>& flange_to_tcp) {
  Eigen::Isometry3d tool;
  tool.matrix() = Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(flange_to_tcp.data());
  xmate::model::setTool(arm_, tool);
}

std::array<double, 7> ExternalTorqueMap::jointTorques(const std::array<double, 7>& q,
                                                      const std::array<double, 6>& wrench) const {
  xmate::model::JointVector joints = xmate::model::JointVector::Zero();
  for (int i = 0; i < arm_.dof; ++i) joints[i] = q[static_cast<std::size_t>(i)];
  const xmate::model::Vector6d w = Eigen::Map<const xmate::model::Vector6d>(wrench.data());
  const xmate::model::JointVector tau = xmate::model::wrenchToJointTorques(arm_, joints, w);
  std::array<double, 7> out{};
  for (int i = 0; i < arm_.dof; ++i) out[static_cast<std::size_t>(i)] = tau[i];
  return out;
}

}  // namespace rci::ui::plots
