// SPDX-License-Identifier: Apache-2.0
// Builds the drawable arm from the URDF and poses its links with forwardKinematics (arm_poser.h).
#include "arm_poser.h"

#include <urdf_parser/urdf_parser.h>

#include <cmath>
#include <stdexcept>

#include "model/kinematics.h"
#include "model/resource_locator.h"
#include "model/urdf_loader.h"
#include "sim/controller.h"
#include "sim/krc.h"

namespace rci::ui {
namespace model = xmate::model;

QMatrix4x4 toMatrix(const Eigen::Isometry3d& pose) {
  QMatrix4x4 m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m(r, c) = static_cast<float>(pose.matrix()(r, c));
  return m;
}

QMatrix4x4 toMatrix(const std::array<double, 16>& row_major) {
  QMatrix4x4 m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m(r, c) = static_cast<float>(row_major[static_cast<size_t>(r * 4 + c)]);
  return m;
}

namespace {

// Colours of the URDF's <material> per link name (urdfdom keeps them; the core's Chain does not).
QColor materialColor(const urdf::ModelInterfaceSharedPtr& urdf, const std::string& link) {
  const QColor fallback = QColor::fromRgbF(0.92f, 0.93f, 0.94f);
  if (!urdf) return fallback;
  auto it = urdf->links_.find(link);
  if (it == urdf->links_.end() || !it->second->visual || !it->second->visual->material) return fallback;
  const urdf::Color& c = it->second->visual->material->color;
  if (c.a <= 0) return fallback;
  return QColor::fromRgbF(c.r, c.g, c.b, 1.0f);
}

LinkVisual makeVisual(const model::ChainLink& link, const urdf::ModelInterfaceSharedPtr& urdf) {
  LinkVisual v;
  v.name = QString::fromStdString(link.name);
  v.mesh = QString::fromStdString(link.mesh);
  v.scale = QVector3D(float(link.mesh_scale.x()), float(link.mesh_scale.y()), float(link.mesh_scale.z()));
  v.visual_origin = toMatrix(link.visual_origin);
  v.color = materialColor(urdf, link.name);
  return v;
}

}  // namespace

ArmPoser::ArmPoser(xmate::XmateType type) : ArmPoser(model::robotSpec(type)) {}

ArmPoser::ArmPoser(const model::RobotSpec& spec) : spec_(&spec) {
  const model::Chain chain = model::loadRobotChain(spec);
  arm_ = model::makeArmModel(chain, spec);
  const urdf::ModelInterfaceSharedPtr urdf = urdf::parseURDFFile(model::robotDescriptionPath(spec).string());
  links_.push_back(makeVisual(chain.base, urdf));
  for (int i = 0; i < chain.dof; ++i) links_.push_back(makeVisual(chain.links[static_cast<size_t>(i)], urdf));
  reach_ = 0;
  for (const model::DhRow& row : spec.dh) reach_ += std::abs(row.a) + std::abs(row.d);
}

std::vector<QMatrix4x4> ArmPoser::linkPoses(const std::array<double, 7>& q) const {
  model::JointVector jq = model::JointVector::Zero();
  for (int i = 0; i < arm_.dof; ++i) jq[i] = q[static_cast<size_t>(i)];
  model::LinkFrames frames;
  model::forwardKinematics(arm_, jq, frames);
  std::vector<QMatrix4x4> poses{QMatrix4x4()};
  for (int i = 0; i < arm_.dof; ++i) poses.push_back(toMatrix(frames.links[static_cast<size_t>(i)]));
  return poses;
}

QMatrix4x4 ArmPoser::flangePose(const std::array<double, 7>& q) const {
  model::JointVector jq = model::JointVector::Zero();
  for (int i = 0; i < arm_.dof; ++i) jq[i] = q[static_cast<size_t>(i)];
  return toMatrix(model::flangePose(arm_, jq));
}

Eigen::Vector3d ArmPoser::flangePosition(const std::array<double, 7>& q) const {
  model::JointVector jq = model::JointVector::Zero();
  for (int i = 0; i < arm_.dof; ++i) jq[i] = q[static_cast<size_t>(i)];
  return model::flangePose(arm_, jq).translation();
}

std::array<double, 7> ArmPoser::homePose(const model::RobotSpec& spec) {
  if (spec.family == model::RobotFamily::kXmate) return xmate::sim::SimConfig{}.initial_q;
  std::array<double, 7> q{};
  const std::array<double, 6> start_deg = xmate::sim::KrcConfig{}.start_deg;
  for (size_t i = 0; i < start_deg.size(); ++i) q[i] = start_deg[i] * M_PI / 180.0;
  return q;
}

}  // namespace rci::ui
