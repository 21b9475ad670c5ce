// SPDX-License-Identifier: Apache-2.0
// The 3D robot view widget: placeholder or Qt3D window, setters, camera framing and capture
// (robot_view.h); pointer handling is in robot_view_input.cpp.
#include "robot_view.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPixmap>
#include <QPointer>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

#include <Qt3DCore/QEntity>
#include <Qt3DExtras/QForwardRenderer>
#include <Qt3DExtras/Qt3DWindow>
#include <Qt3DRender/QCamera>
#include <Qt3DRender/QRenderCapture>
#include <Qt3DRender/QRenderSettings>

#include <cmath>
#include <stdexcept>

#include "gl_probe.h"
#include "robot_scene.h"

namespace rci::ui {
namespace {

constexpr int kCaptureTimeoutMs = 15000;
constexpr int kCaptureRetries = 8;
constexpr double kReframeShare = 0.3;  // a new model whose reach differs by more than this frames anew
const QColor kBackground(0x2f, 0x34, 0x3b);

}  // namespace

QString RobotView::defaultHint() {
  return tr("Drag: orbit  ·  Right-drag: pan  ·  Wheel: zoom  ·  Shift+drag TCP: pull");
}

RobotView::RobotView(QWidget* parent) : QWidget(parent), spec_(&xmate::model::robotSpec(xmate::XMATE7_PRO)) {
  setMinimumSize(240, 200);
  const GlProbe probe = probeOpenGl();
  software_ = probe.software;
  renderer_ = probe.renderer;
  if (probe.ok) build3D();
  else buildPlaceholder(probe.reason);
}

RobotView::~RobotView() = default;

void RobotView::buildPlaceholder(const QString& reason) {
  reason_ = reason;
  auto* layout = new QVBoxLayout(this);
  auto* label = new QLabel(this);
  label->setObjectName(QStringLiteral("robotViewPlaceholder"));
  label->setAlignment(Qt::AlignCenter);
  label->setWordWrap(true);
  label->setTextFormat(Qt::RichText);
  label->setText(tr("<p style='font-size:large'><b>3D view unavailable</b></p>"
                    "<p>Why: %1.</p>"
                    "<p>What to do: run RCI Studio on a desktop with OpenGL (or under <tt>xvfb-run</tt> with "
                    "Mesa: <tt>LIBGL_ALWAYS_SOFTWARE=1</tt>). Every panel and plot works without it.</p>")
                     .arg(reason.toHtmlEscaped()));
  label->setForegroundRole(QPalette::PlaceholderText);
  label->setMargin(24);
  layout->addWidget(label);
}

void RobotView::build3D() {
  // Qt3D's OpenGL renderer, as the render tests use (docs/architecture.md, "The 3D view"): Qt 6.4's
  // RHI renderer returns QRenderCapture images upside down and draws lines with a different gamma.
  if (qEnvironmentVariableIsEmpty("QT3D_RENDERER")) qputenv("QT3D_RENDERER", "opengl");
  window_ = new Qt3DExtras::Qt3DWindow(nullptr, Qt3DRender::API::OpenGL);
  window_->defaultFrameGraph()->setClearColor(kBackground);
  window_->renderSettings()->setRenderPolicy(Qt3DRender::QRenderSettings::OnDemand);
  capture_ = new Qt3DRender::QRenderCapture;
  window_->activeFrameGraph()->setParent(capture_);
  window_->setActiveFrameGraph(capture_);
  auto* root = new Qt3DCore::QEntity;
  scene_ = std::make_unique<RobotScene>(root);
  window_->setRootEntity(root);
  window_->installEventFilter(this);

  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(0);
  auto* bar = new QWidget(this);
  auto* bar_layout = new QHBoxLayout(bar);
  bar_layout->setContentsMargins(8, 3, 4, 3);
  hint_ = new QLabel(defaultHint(), bar);
  hint_->setObjectName(QStringLiteral("robotViewHint"));
  hint_->setForegroundRole(QPalette::PlaceholderText);
  hint_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);  // may be cut, never widens the view
  hint_->setToolTip(tr("Left drag: orbit. Right or middle drag: pan. Wheel: zoom. Double-click: reset view.\n"
                       "Shift + left drag starting on the TCP: pull the robot with a spring (built-in xMate "
                       "simulator in drag mode, or the built-in KUKA simulator; at most %1 N).")
                        .arg(double(kPullMaxForce), 0, 'f', 0));
  auto* reset = new QToolButton(bar);
  reset->setText(tr("Reset view"));
  reset->setToolTip(tr("Frame the whole arm from the default viewpoint (or double-click the view)"));
  connect(reset, &QToolButton::clicked, this, &RobotView::resetView);
  bar_layout->addWidget(hint_, 1);
  if (software_) {  // why the arm moves in steps: said where it is seen, not only in a tooltip
    auto* note = new QLabel(tr("Software OpenGL: %1 redraws/s").arg(kSoftwareLiveHz), bar);
    note->setObjectName(QStringLiteral("robotViewRenderNote"));
    note->setForegroundRole(QPalette::PlaceholderText);
    note->setToolTip(tr("OpenGL runs on the CPU here (%1), so the live pose is redrawn only %2 times a second to "
                        "leave the CPU to the real-time loop; with a GPU it is redrawn 30 times a second.")
                         .arg(renderer_)
                         .arg(kSoftwareLiveHz));
    bar_layout->addWidget(note);
  }
  bar_layout->addWidget(reset);
  layout->addWidget(bar);
  container_ = QWidget::createWindowContainer(window_, this);
  container_->setFocusPolicy(Qt::StrongFocus);
  container_->setToolTip(hint_->toolTip());
  layout->addWidget(container_, 1);
  setModel(*spec_);
  resetView();
}

void RobotView::setModel(xmate::XmateType type) { setModel(xmate::model::robotSpec(type)); }

void RobotView::setModel(const xmate::model::RobotSpec& spec) {
  if (!scene_) {
    spec_ = &spec;
    return;
  }
  if (scene_->poser() && scene_->poser()->spec().name == spec.name) return;  // already drawn
  if (failed_model_ && failed_model_->name == spec.name) return;  // said so already; do not retry each tick
  try {
    const double framed_reach = scene_->poser() ? scene_->poser()->reach() : 0;
    scene_->setModel(spec);
    spec_ = &spec;
    failed_model_ = nullptr;
    showHint(defaultHint());
    // A much larger or smaller arm (an xMate after a KR 16) would not fit or be lost in the old framing.
    const double reach = scene_->poser()->reach();
    if (framed_reach > 0 && std::abs(reach - framed_reach) > kReframeShare * framed_reach) resetView();
  } catch (const std::exception& e) {
    failed_model_ = &spec;
    showHint(tr("Cannot show the robot: %1").arg(QString::fromStdString(e.what())));
  }
}

bool RobotView::liveUpdateDue() {
  if (!software_) return true;
  if (last_live_update_.isValid() && last_live_update_.elapsed() < 1000 / kSoftwareLiveHz) return false;
  last_live_update_.start();
  return true;
}

void RobotView::setJointPositions(const std::array<double, 7>& q) {
  if (scene_) scene_->setJointPositions(q);
}

void RobotView::setTcpPose(const std::array<double, 16>& row_major) {
  if (!scene_) return;
  scene_->setTcpPose(toMatrix(row_major));
  if (pulling_) updatePull();
}

void RobotView::setSafetyBox(bool enabled, const QVector3D& size, const QMatrix4x4& frame) {
  if (scene_) scene_->setSafetyBox(enabled, size, frame);
}

void RobotView::setCorrectionEnvelope(bool visible, const QVector3D& min, const QVector3D& max) {
  if (!scene_) return;
  const bool was_visible = scene_->correctionEnvelopeVisible();
  scene_->setCorrectionEnvelope(visible, min, max);
  if (visible == was_visible || !container_ || !hint_) return;
  QString tip = hint_->toolTip();
  if (visible) {
    tip += tr("\nThe faint violet box: where the flange can go within the RSI correction limits of this RSI "
              "session (around where the robot stood when RSI started).");
  }
  container_->setToolTip(tip);
}

void RobotView::setWaypoints(const std::vector<QMatrix4x4>& poses) {
  std::vector<QVector3D> positions;
  for (const QMatrix4x4& pose : poses) positions.push_back(pose.column(3).toVector3D());
  setWaypoints(positions);
}

void RobotView::setWaypoints(const std::vector<QVector3D>& positions) {
  if (scene_) scene_->setWaypoints(positions);
}

void RobotView::setPlannedPath(const std::vector<QVector3D>& points) {
  if (scene_) scene_->setPlannedPath(points);
}

void RobotView::setLinkTints(const std::vector<LinkTint>& tints) {
  if (scene_) scene_->setLinkTints(tints);
}

void RobotView::setPullEnabled(bool enabled, const QString& why_not) {
  pull_enabled_ = enabled;
  pull_why_not_ = why_not;
  if (!enabled && pulling_) endPull();
}

void RobotView::resetView() {
  camera_ = OrbitCamera::framing(scene_ && scene_->poser() ? scene_->poser()->reach() : 1.0);
  applyCamera();
}

void RobotView::applyCamera() {
  if (!window_) return;
  Qt3DRender::QCamera* camera = window_->camera();
  const QSizeF size = viewport();
  camera->lens()->setPerspectiveProjection(camera_.fov_deg, float(size.width() / std::max(1.0, size.height())),
                                           0.02f, 100.0f);
  camera->setUpVector(QVector3D(0, 0, 1));
  camera->setPosition(camera_.position());
  camera->setViewCenter(camera_.target);
}

QSizeF RobotView::viewport() const {
  if (!window_ || window_->width() <= 0 || window_->height() <= 0) return QSizeF(640, 480);
  return QSizeF(window_->width(), window_->height());
}

void RobotView::showHint(const QString& text) {
  if (hint_) hint_->setText(text);
}

namespace {

// True when every sampled pixel has one colour: the frame was rendered before the scene reached
// the renderer (the grid alone always draws lines).
bool looksEmpty(const QImage& image) {
  if (image.isNull()) return true;
  const QRgb first = image.pixel(0, 0);
  for (int y = 0; y < image.height(); y += 7)
    for (int x = 0; x < image.width(); x += 7)
      if (image.pixel(x, y) != first) return false;
  return true;
}

}  // namespace

void RobotView::capture(std::function<void(const QImage&)> done) {
  if (!capture_) {
    done(QImage());
    return;
  }
  auto finished = std::make_shared<bool>(false);
  auto finish = [finished, done](const QImage& image) {
    if (*finished) return;
    *finished = true;
    done(image);
  };
  requestCapture(finish, kCaptureRetries);
  // A hidden or never-exposed window renders nothing: give up rather than leave the caller waiting.
  QTimer::singleShot(kCaptureTimeoutMs, this, [finish] { finish(QImage()); });
}

void RobotView::captureWidget(std::function<void(const QImage&)> done) {
  QPointer<RobotView> self(this);
  capture([self, done](const QImage& scene) {
    if (!self || scene.isNull()) {
      done(QImage());
      return;
    }
    // grab() draws the tool strip but not the native 3D window: paint the render into its place.
    const QPixmap grab = self->grab();
    QImage image = grab.toImage().convertToFormat(QImage::Format_RGB32);
    image.setDevicePixelRatio(grab.devicePixelRatio());
    QPainter painter(&image);
    painter.drawImage(QRectF(self->container_->geometry()), scene);
    painter.end();
    done(image);
  });
}

void RobotView::requestCapture(const std::function<void(const QImage&)>& finish, int retries) {
  QPointer<Qt3DRender::QRenderCaptureReply> reply(capture_->requestCapture());
  connect(reply, &Qt3DRender::QRenderCaptureReply::completed, this, [this, reply, finish, retries] {
    if (!reply) return;
    const QImage image = reply->image();
    reply->deleteLater();
    if (looksEmpty(image) && retries > 0) requestCapture(finish, retries - 1);  // the first frames after show
    else finish(image);
  });
}

}  // namespace rci::ui
