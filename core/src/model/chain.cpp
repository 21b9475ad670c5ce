// SPDX-License-Identifier: Apache-2.0
// DH table -> Chain, and the DH forward kinematics used as an independent reference.
#include "model/chain.h"

#include <string>

namespace xmate::model {
namespace {

Eigen::Isometry3d dhFixedPart(const DhRow& r) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translate(Eigen::Vector3d(0, 0, r.d));
  t.translate(Eigen::Vector3d(r.a, 0, 0));
  t.rotate(Eigen::AngleAxisd(r.alpha, Eigen::Vector3d::UnitX()));
  return t;
}

}  // namespace

Chain chainFromDh(const RobotSpec& spec) {
  Chain c;
  c.name = std::string(spec.name);
  c.dof = spec.dof;
  c.base.name = "base_link";
  for (int i = 0; i < spec.dof; ++i) {
    ChainJoint& j = c.joints[i];
    j.name = "joint" + std::to_string(i + 1);
    // Joint 1 sits on the base frame; joint i+1 follows link i by the fixed part of DH row i.
    j.origin = i == 0 ? Eigen::Isometry3d::Identity() : dhFixedPart(spec.dh[i - 1]);
    j.origin.rotate(Eigen::AngleAxisd(spec.dh[i].theta, Eigen::Vector3d::UnitZ()));
    j.axis = spec.dh[i].axis_sign * Eigen::Vector3d::UnitZ();
    j.lower = spec.q_min[i];
    j.upper = spec.q_max[i];
    j.velocity = spec.dq_max[i];
    j.effort = spec.tau_max[i];
    c.links[i].name = "link" + std::to_string(i + 1);
  }
  c.flange = dhFixedPart(spec.dh[spec.dof - 1]);
  return c;
}

Eigen::Isometry3d dhFlangePose(const RobotSpec& spec, const std::array<double, 7>& q) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  for (int i = 0; i < spec.dof; ++i) {
    const DhRow& r = spec.dh[i];
    t.rotate(Eigen::AngleAxisd(r.theta + r.axis_sign * q[i], Eigen::Vector3d::UnitZ()));
    t = t * dhFixedPart(r);
  }
  return t;
}

}  // namespace xmate::model
