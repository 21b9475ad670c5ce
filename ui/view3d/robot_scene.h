// SPDX-License-Identifier: Apache-2.0
// The 3D scene of the robot view, independent of any window: ground grid, lights, the arm (one
// entity + transform per link), TCP frame, safety box, RSI correction envelope, waypoints, planned
// path and the mouse-pull spring. RobotView puts it in a Qt3D window; tests build it bare to check
// poses. GUI thread only.
#pragma once

#include <QColor>
#include <QMatrix4x4>
#include <QString>
#include <QVector3D>

#include <Qt3DCore/QEntity>
#include <Qt3DCore/QTransform>
#include <Qt3DExtras/QPhongAlphaMaterial>
#include <Qt3DExtras/QPhongMaterial>
#include <Qt3DExtras/QCuboidMesh>
#include <Qt3DExtras/QSphereMesh>

#include <array>
#include <memory>
#include <vector>

#include <xmate/types.h>

#include "arm_poser.h"
#include "link_tints.h"
#include "mesh_data.h"
#include "scene_nodes.h"

namespace rci::ui {

class RobotScene {
 public:
  // Builds the static parts (grid, lights, TCP frame, ...) under root. No model yet.
  explicit RobotScene(Qt3DCore::QEntity* root);
  ~RobotScene();

  // Loads the model's URDF and meshes (either family) and rebuilds the arm at its home pose. Throws
  // std::runtime_error (URDF or mesh missing) -- the previous arm stays.
  void setModel(const xmate::model::RobotSpec& spec);
  void setModel(xmate::XmateType type);  // an xMate model
  const ArmPoser* poser() const { return poser_.get(); }

  void setJointPositions(const std::array<double, 7>& q);
  const std::array<double, 7>& jointPositions() const { return q_; }
  // TCP pose in the base frame (the measured toolTobase pose). Until set, the flange pose.
  void setTcpPose(const QMatrix4x4& pose);
  QVector3D tcpPosition() const { return tcp_.column(3).toVector3D(); }
  // Cartesian safety box: size (m) along the axes of frame (its centre, base frame).
  void setSafetyBox(bool enabled, const QVector3D& size, const QMatrix4x4& frame);
  bool safetyBoxVisible() const;
  // The region the RSI corrections may move the flange to (a faint box, base frame, m).
  void setCorrectionEnvelope(bool visible, const QVector3D& min = {}, const QVector3D& max = {});
  bool correctionEnvelopeVisible() const;
  QVector3D correctionEnvelopeMin() const { return envelope_min_; }
  QVector3D correctionEnvelopeMax() const { return envelope_max_; }
  bool springVisible() const { return spring_handle_->isEnabled(); }
  void setWaypoints(const std::vector<QVector3D>& positions);
  int waypointCount() const { return int(waypoints_.size()); }
  void setPlannedPath(const std::vector<QVector3D>& points);
  int plannedPathPointCount() const { return path_->pointCount(); }
  // One tint per moving link (link 1..dof).
  void setLinkTints(const std::vector<LinkTint>& tints);
  // The mouse-pull spring from the TCP to the pointer.
  void setSpring(bool visible, const QVector3D& from, const QVector3D& to);

  // Link entities (base first) and what they show, for tests.
  int linkCount() const { return int(links_.size()); }
  QMatrix4x4 linkTransform(int index) const;
  QColor linkColor(int index) const;
  const MeshCache& meshCache() const { return meshes_; }

  static QColor amber() { return QColor(0xf0, 0xa0, 0x20); }
  static QColor red() { return QColor(0xe0, 0x3a, 0x30); }

 private:
  struct LinkNode {
    Qt3DCore::QEntity* entity = nullptr;     // posed by transform (link frame)
    Qt3DCore::QTransform* transform = nullptr;
    Qt3DExtras::QPhongMaterial* material = nullptr;
    QColor color;  // the URDF material
  };
  void buildGround(double reach);
  void buildLights();
  void buildTcpFrame();
  void buildSafetyBox();
  void buildCorrectionEnvelope();
  void clearArm();
  void updateLinks();

  Qt3DCore::QEntity* root_;
  Qt3DCore::QEntity* arm_ = nullptr;
  MeshCache meshes_;
  std::unique_ptr<ArmPoser> poser_;
  std::vector<LinkNode> links_;
  std::array<double, 7> q_{};
  QMatrix4x4 tcp_;
  bool tcp_set_ = false;

  std::unique_ptr<LineSet> grid_;
  Qt3DCore::QTransform* tcp_frame_ = nullptr;
  Qt3DCore::QEntity* box_ = nullptr;
  Qt3DCore::QTransform* box_transform_ = nullptr;
  Qt3DExtras::QCuboidMesh* box_mesh_ = nullptr;
  std::unique_ptr<LineSet> box_edges_;
  Qt3DCore::QEntity* envelope_ = nullptr;
  Qt3DCore::QTransform* envelope_transform_ = nullptr;
  Qt3DExtras::QCuboidMesh* envelope_mesh_ = nullptr;
  std::unique_ptr<LineSet> envelope_edges_;
  QVector3D envelope_min_, envelope_max_;
  Qt3DExtras::QSphereMesh* waypoint_mesh_ = nullptr;
  Qt3DExtras::QPhongMaterial* waypoint_material_ = nullptr;
  std::vector<Qt3DCore::QEntity*> waypoints_;
  std::unique_ptr<LineSet> path_;
  std::unique_ptr<LineSet> spring_;
  Qt3DCore::QEntity* spring_handle_ = nullptr;  // a ball at the pointer end
  Qt3DCore::QTransform* spring_handle_transform_ = nullptr;
};

}  // namespace rci::ui
