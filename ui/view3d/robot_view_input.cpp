// SPDX-License-Identifier: Apache-2.0
// The 3D robot view's pointer handling (robot_view.h): orbit, pan, zoom and reset on the Qt3D
// window, and the mouse pull (Shift + left-drag from the TCP) with its spring force.
#include <QLineF>
#include <QMouseEvent>
#include <QTimer>
#include <QWheelEvent>

#include <Qt3DExtras/Qt3DWindow>

#include "robot_scene.h"
#include "robot_view.h"

namespace rci::ui {
namespace {

constexpr double kPullPickRadiusPx = 40;

}  // namespace

bool RobotView::beginPull(const QPointF& pixel) {
  if (!scene_) return false;
  if (!pull_enabled_) {
    showHint(!pull_why_not_.isEmpty()
                 ? pull_why_not_
                 : tr("Mouse pull needs the built-in simulator in drag mode (start hand guiding in the Drag panel)."));
    return false;
  }
  QPointF tcp_pixel;
  if (!camera_.project(scene_->tcpPosition(), viewport(), tcp_pixel) ||
      QLineF(tcp_pixel, pixel).length() > kPullPickRadiusPx) {
    showHint(tr("Start the pull on the TCP (the red-green-blue axes) while holding Shift."));
    return false;
  }
  pulling_ = true;
  pull_pixel_ = pixel;
  updatePull();
  return true;
}

void RobotView::movePull(const QPointF& pixel) {
  if (!pulling_) return;
  pull_pixel_ = pixel;
  updatePull();
}

void RobotView::endPull() {
  if (!pulling_) return;
  pulling_ = false;
  scene_->setSpring(false, {}, {});
  showHint(defaultHint());
  emit pullForceChanged(QVector3D());
}

void RobotView::updatePull() {
  const QVector3D tcp = scene_->tcpPosition();
  pull_point_ = intersectPlane(camera_.ray(pull_pixel_, viewport()), tcp, camera_.forward());
  const QVector3D force = springForce(tcp, pull_point_, kPullStiffness, kPullMaxForce);
  scene_->setSpring(true, tcp, pull_point_);
  showHint(tr("Pulling the TCP: %1 N (release the mouse to let go)").arg(double(force.length()), 0, 'f', 1));
  emit pullForceChanged(force);
}

bool RobotView::eventFilter(QObject* watched, QEvent* event) {
  if (watched != window_) return QWidget::eventFilter(watched, event);
  switch (event->type()) {
    case QEvent::MouseButtonPress: {
      auto* e = static_cast<QMouseEvent*>(event);
      last_pixel_ = e->position();
      if (!failed_model_) showHint(defaultHint());  // clear an earlier pull message
      if (e->button() == Qt::LeftButton && (e->modifiers() & Qt::ShiftModifier)) {
        drag_ = beginPull(e->position()) ? Drag::kPull : Drag::kNone;
      } else if (e->button() == Qt::LeftButton) {
        drag_ = Drag::kOrbit;
      } else if (e->button() == Qt::RightButton || e->button() == Qt::MiddleButton) {
        drag_ = Drag::kPan;
      }
      return true;
    }
    case QEvent::MouseMove: {
      auto* e = static_cast<QMouseEvent*>(event);
      const QPointF delta = e->position() - last_pixel_;
      last_pixel_ = e->position();
      if (!failed_model_) showHint(defaultHint());  // clear an earlier pull message
      if (drag_ == Drag::kOrbit) camera_.rotate(float(delta.x()), float(delta.y()));
      else if (drag_ == Drag::kPan) camera_.pan(float(delta.x()), float(delta.y()), float(viewport().height()));
      else if (drag_ == Drag::kPull) movePull(e->position());
      if (drag_ == Drag::kOrbit || drag_ == Drag::kPan) applyCamera();
      return true;
    }
    case QEvent::MouseButtonRelease:
      if (drag_ == Drag::kPull) endPull();
      drag_ = Drag::kNone;
      return true;
    case QEvent::MouseButtonDblClick:
      resetView();
      return true;
    case QEvent::Wheel: {
      camera_.zoom(float(static_cast<QWheelEvent*>(event)->angleDelta().y()) / 120.0f);
      applyCamera();
      return true;
    }
    case QEvent::Resize:
      QTimer::singleShot(0, this, &RobotView::applyCamera);
      return false;
    default:
      return false;
  }
}

}  // namespace rci::ui
