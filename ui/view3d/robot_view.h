// SPDX-License-Identifier: Apache-2.0
// RobotView: the 3D robot view widget. Usable on its own through plain setters (the Program panel
// calls setWaypoints / setPlannedPath); createRobotView (parts.h) wires one to a Session. Without
// OpenGL (e.g. the offscreen platform) it shows a placeholder saying why, and the setters do nothing.
#pragma once

#include <QElapsedTimer>
#include <QImage>
#include <QMatrix4x4>
#include <QPointF>
#include <QVector3D>
#include <QWidget>

#include <array>
#include <functional>
#include <memory>
#include <vector>

#include <xmate/types.h>

#include "link_tints.h"
#include "model/robot_spec.h"
#include "orbit_camera.h"

class QLabel;

namespace Qt3DExtras {
class Qt3DWindow;
}
namespace Qt3DRender {
class QRenderCapture;
}

namespace rci::ui {

class RobotScene;

class RobotView : public QWidget {
  Q_OBJECT
 public:
  explicit RobotView(QWidget* parent = nullptr);
  ~RobotView() override;

  // False when the view is the placeholder (no OpenGL); unavailableReason() says why.
  bool is3D() const { return window_ != nullptr; }
  QString unavailableReason() const { return reason_; }
  // OpenGL runs on the CPU (Mesa llvmpipe: no GPU, a VM, xvfb). Each Qt3D frame then costs tens of
  // milliseconds of CPU on every core, so live poses are shown at most kSoftwareLiveHz times a
  // second, which keeps the CPU for the real-time loop; a GPU redraws at the session's 30 Hz.
  bool softwareRendered() const { return software_; }
  static constexpr int kSoftwareLiveHz = 5;
  // Whether a live update (pose, TCP, tints) should be drawn now; true at most kSoftwareLiveHz
  // times a second with software OpenGL, always otherwise. Updates skipped are superseded by the
  // next one (the session keeps ticking at rest, so the final pose is always drawn).
  bool liveUpdateDue();

  // The robot model drawn, of either family (xMate7 Pro until set). Loads its URDF and meshes; on
  // failure shows the error in the view and keeps the previous model. GUI thread, as every setter.
  void setModel(const xmate::model::RobotSpec& spec);
  void setModel(xmate::XmateType type);  // an xMate model
  const xmate::model::RobotSpec& spec() const { return *spec_; }
  // The xMate model drawn (meaningless for another family's model: see spec()).
  xmate::XmateType model() const { return spec_->type; }
  void setJointPositions(const std::array<double, 7>& q);  // rad
  void setTcpPose(const std::array<double, 16>& row_major);  // base frame, row-major (ArmState::tcp)
  void setSafetyBox(bool enabled, const QVector3D& size, const QMatrix4x4& frame);  // m; frame = centre
  // The region the RSI corrections may move a KUKA's flange to in this RSI session (base frame, m);
  // hidden when !visible.
  void setCorrectionEnvelope(bool visible, const QVector3D& min = {}, const QVector3D& max = {});
  // Taught waypoints, as 4x4 TCP poses (column-major QMatrix4x4) or as positions, base frame, m.
  void setWaypoints(const std::vector<QMatrix4x4>& poses);
  void setWaypoints(const std::vector<QVector3D>& positions);
  void setPlannedPath(const std::vector<QVector3D>& points);
  void setLinkTints(const std::vector<LinkTint>& tints);  // link 1..dof
  // Mouse pull (Shift + left-drag from the TCP) is offered only when enabled (the xMate simulator in
  // drag mode, the KUKA simulator); disabling it during a pull releases it. why_not: what a Shift+drag
  // says while it is disabled ("" = how to enable it on the xMate simulator).
  void setPullEnabled(bool enabled, const QString& why_not = QString());
  bool pullEnabled() const { return pull_enabled_; }
  bool pulling() const { return pulling_; }

  // Camera back to the default framing of the whole arm.
  void resetView();
  const OrbitCamera& camera() const { return camera_; }
  // Renders the 3D area and calls done on the GUI thread with the image (null if the view is a
  // placeholder or the capture failed).
  void capture(std::function<void(const QImage&)> done);
  // The whole widget as on screen (tool strip + 3D area), same size as grab(); null as above.
  void captureWidget(std::function<void(const QImage&)> done);
  // The scene (nullptr for the placeholder).
  RobotScene* scene() const { return scene_.get(); }

  // Mouse pull as if the pointer were at pixel (window coordinates of the 3D area).
  bool beginPull(const QPointF& pixel);
  void movePull(const QPointF& pixel);
  void endPull();

  static constexpr float kPullStiffness = 150.0f;  // N/m
  static constexpr float kPullMaxForce = 60.0f;    // N

 signals:
  // Mouse pull: the spring force on the TCP (N, base frame); zero when released.
  void pullForceChanged(const QVector3D& force);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void buildPlaceholder(const QString& reason);
  void build3D();
  void applyCamera();
  void updatePull();
  void requestCapture(const std::function<void(const QImage&)>& finish, int retries);
  void showHint(const QString& text);
  static QString defaultHint();
  QSizeF viewport() const;

  Qt3DExtras::Qt3DWindow* window_ = nullptr;
  Qt3DRender::QRenderCapture* capture_ = nullptr;
  QWidget* container_ = nullptr;  // holds window_
  std::unique_ptr<RobotScene> scene_;
  QLabel* hint_ = nullptr;
  QString reason_;
  bool software_ = false;
  QString renderer_;  // GL_RENDERER
  QElapsedTimer last_live_update_;
  const xmate::model::RobotSpec* spec_;
  const xmate::model::RobotSpec* failed_model_ = nullptr;  // the last model that could not be loaded
  OrbitCamera camera_;
  // Pointer drag state.
  enum class Drag { kNone, kOrbit, kPan, kPull };
  Drag drag_ = Drag::kNone;
  QPointF last_pixel_;
  bool pull_enabled_ = false;
  QString pull_why_not_;
  bool pulling_ = false;
  QVector3D pull_point_;
  QPointF pull_pixel_;
};

}  // namespace rci::ui
