// SPDX-License-Identifier: Apache-2.0
// The robot as the 3D view draws it: each link's mesh, colour and visual offset from the model's
// URDF, and every link pose at joint angles q from the core's forward kinematics.
#pragma once

#include <QColor>
#include <QMatrix4x4>
#include <QString>
#include <QVector3D>

#include <array>
#include <vector>

#include <xmate/types.h>

#include "model/arm_model.h"
#include "model/robot_spec.h"

namespace rci::ui {

struct LinkVisual {
  QString name;        // "base_link", "link1", ...
  QString mesh;        // absolute mesh path ("" if the link has no visual mesh)
  QVector3D scale{1, 1, 1};
  QMatrix4x4 visual_origin;  // link frame -> mesh frame (URDF <visual><origin>)
  QColor color;        // URDF material colour (light housings, dark flange)
};

// Eigen pose -> QMatrix4x4 (single precision, for drawing).
QMatrix4x4 toMatrix(const Eigen::Isometry3d& pose);
// Row-major 4x4 (RobotState poses) -> QMatrix4x4.
QMatrix4x4 toMatrix(const std::array<double, 16>& row_major);

class ArmPoser {
 public:
  // Loads the model's URDF (resources/robots/<spec.name>.urdf), for a model of either family.
  // Throws std::runtime_error saying what is missing and what to do. GUI thread (reads files).
  explicit ArmPoser(const xmate::model::RobotSpec& spec);
  // The same for an xMate model.
  explicit ArmPoser(xmate::XmateType type);

  const xmate::model::RobotSpec& spec() const { return *spec_; }
  int dof() const { return arm_.dof; }
  // The base first, then link 1..dof.
  const std::vector<LinkVisual>& links() const { return links_; }
  // Pose of every link frame in the base frame (same order as links()). Any thread (const).
  std::vector<QMatrix4x4> linkPoses(const std::array<double, 7>& q) const;
  QMatrix4x4 flangePose(const std::array<double, 7>& q) const;
  // The flange position only, in double precision (for sampling many poses). Any thread (const).
  Eigen::Vector3d flangePosition(const std::array<double, 7>& q) const;
  // Hardware joint limits, rad.
  double lower(int joint) const { return arm_.hardware_lower[joint]; }
  double upper(int joint) const { return arm_.hardware_upper[joint]; }
  // Sum of the DH lengths: the arm's reach, m (for framing the camera).
  double reach() const { return reach_; }
  // A comfortable pose to show before any state arrives: where the family's built-in simulator
  // starts (an xMate's power-up pose, a KUKA's A1..A6 = 0, -90, 90, 0, 90, 0 deg). Any thread.
  static std::array<double, 7> homePose(const xmate::model::RobotSpec& spec);

 private:
  const xmate::model::RobotSpec* spec_;
  xmate::model::ArmModel arm_;
  std::vector<LinkVisual> links_;
  double reach_ = 1.0;
};

}  // namespace rci::ui
