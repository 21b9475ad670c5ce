// SPDX-License-Identifier: Apache-2.0
// The 3D view drawing for real (xvfb-run + Mesa): the robot is visible and upright in a capture, a
// different pose changes the picture, every model (xMate and KUKA) renders, pointer events
// orbit/pan/zoom/pull, a Session with the xMate or the KUKA simulator drives it (the KUKA: pose from
// the arm state, RSI correction envelope, Shift+drag pushes the simulated KRC's flange), and
// software OpenGL gets a live-update budget.
// Set RCI_VIEW3D_PNG_DIR to keep the captures as PNG files.
#include <QElapsedTimer>
#include <QLabel>
#include <QScreen>
#include <QSignalSpy>
#include <QtTest>

#include <cmath>
#include <functional>

#include "model/robot_spec.h"
#include "../gui/gui_test_support.h"
#include "session/session.h"
#include "sim/krc_server.h"
#include "view3d/arm_poser.h"
#include "view3d/robot_scene.h"
#include "view3d/robot_view.h"
#include "window/parts.h"

using namespace rci::ui;

namespace {

QImage captureNow(const std::function<void(std::function<void(const QImage&)>)>& capture) {
  QImage result;
  bool done = false;
  capture([&](const QImage& image) {
    result = image;
    done = true;
  });
  for (int i = 0; i < 600 && !done; ++i) QTest::qWait(50);
  return result.convertToFormat(QImage::Format_RGB32);
}

bool differs(QRgb a, QRgb b) {
  return std::abs(qRed(a) - qRed(b)) + std::abs(qGreen(a) - qGreen(b)) + std::abs(qBlue(a) - qBlue(b)) > 30;
}

// Share of pixels in the centre third that differ from the background colour (by default the
// top-left corner's).
double centreCoverage(const QImage& image, QPoint background_at = QPoint(2, 2)) {
  const QRgb background = image.pixel(background_at);
  int count = 0, total = 0;
  for (int y = image.height() / 3; y < 2 * image.height() / 3; ++y)
    for (int x = image.width() / 3; x < 2 * image.width() / 3; ++x, ++total)
      count += differs(image.pixel(x, y), background);
  return double(count) / total;
}

// Share of pixels in rows [y0, y1) that differ from the corner (background) colour.
double rowCoverage(const QImage& image, int y0, int y1) {
  const QRgb background = image.pixel(2, 2);
  int count = 0, total = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = 0; x < image.width(); ++x, ++total) count += differs(image.pixel(x, y), background);
  return double(count) / total;
}

double changedShare(const QImage& a, const QImage& b) {
  if (a.size() != b.size()) return 1.0;
  int count = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) count += differs(a.pixel(x, y), b.pixel(x, y));
  return double(count) / (a.width() * a.height());
}

// Share of pixels in the orange of a KUKA housing, lit or shaded (the grid is grey, the axes red or
// green, the spring yellow).
double housingShare(const QImage& image) {
  if (image.isNull()) return 0;
  int count = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const QRgb p = image.pixel(x, y);
      count += qRed(p) > 60 && qRed(p) > 1.5 * qGreen(p) && qGreen(p) > 1.5 * qBlue(p);
    }
  return double(count) / (image.width() * image.height());
}

void keep(const QImage& image, const QString& name) {
  const QString dir = qEnvironmentVariable("RCI_VIEW3D_PNG_DIR");
  if (!dir.isEmpty()) image.save(dir + '/' + name + ".png");
}

// The Qt3D window inside the (only) view on screen.
QWindow* window3d() {
  for (QWindow* w : QGuiApplication::allWindows())
    if (w->inherits("Qt3DExtras::Qt3DWindow") && w->isExposed()) return w;
  return nullptr;
}

void sendMouse(QWindow* window, QEvent::Type type, const QPointF& pos, Qt::MouseButton button,
               Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
  const Qt::MouseButtons buttons = type == QEvent::MouseButtonRelease ? Qt::NoButton : Qt::MouseButtons(button);
  QMouseEvent event(type, pos, window->mapToGlobal(pos), type == QEvent::MouseMove ? Qt::NoButton : button, buttons,
                    modifiers);
  QCoreApplication::sendEvent(window, &event);
}

}  // namespace

class TestView3dRender : public QObject {
  Q_OBJECT
 private slots:
  void rendersTheRobot();
  void rendersEveryModel();
  void mousePullEmitsSpringForce();
  void pointerOrbitsPansZooms();
  void factoryViewCaptures();
  void followsTheSimulator();
  void softwareGlHasALiveUpdateBudget();
  void rendersKukaModels();
  void followsTheKukaSimulator();
};

void TestView3dRender::rendersTheRobot() {
  RobotView view;
  QVERIFY2(view.is3D(), qPrintable(view.unavailableReason()));
  view.resize(800, 600);
  view.show();
  QVERIFY(QTest::qWaitForWindowExposed(&view));
  view.setModel(xmate::XMATE7_PRO);
  QMatrix4x4 box;
  box.translate(0.45f, 0, 0.45f);
  view.setSafetyBox(true, QVector3D(0.7f, 1.0f, 0.9f), box);
  view.setWaypoints(std::vector<QVector3D>{{0.55f, -0.25f, 0.35f}, {0.55f, 0.0f, 0.55f}, {0.5f, 0.25f, 0.4f}});
  view.setPlannedPath({{0.55f, -0.25f, 0.35f}, {0.55f, -0.1f, 0.5f}, {0.55f, 0.0f, 0.55f}, {0.52f, 0.15f, 0.5f},
                       {0.5f, 0.25f, 0.4f}});
  const QImage first = captureNow([&](auto done) { view.capture(done); });
  QVERIFY(!first.isNull());
  keep(first, QStringLiteral("view3d_home"));
  const double coverage = centreCoverage(first);
  QVERIFY2(coverage > 0.05, qPrintable(QStringLiteral("robot covers %1 of the centre").arg(coverage)));
  // Upright: sky above, the floor grid below (a flipped capture would swap them).
  const int h = first.height();
  QVERIFY(rowCoverage(first, 0, h / 8) < 0.01);
  QVERIFY(rowCoverage(first, h - h / 8, h) > 0.03);

  view.setJointPositions({1.2, -0.4, 0.6, 1.6, -0.8, 0.9, 0.5});
  std::vector<LinkTint> tints(7, LinkTint::kNone);
  tints[3] = LinkTint::kNearLimit;
  tints[5] = LinkTint::kOverload;
  view.setLinkTints(tints);
  QTest::qWait(200);
  const QImage second = captureNow([&](auto done) { view.capture(done); });
  QVERIFY(!second.isNull());
  keep(second, QStringLiteral("view3d_moved"));
  const double changed = changedShare(first, second);
  QVERIFY2(changed > 0.01, qPrintable(QStringLiteral("only %1 of the pixels changed").arg(changed)));
}

void TestView3dRender::rendersEveryModel() {
  RobotView view;
  QVERIFY(view.is3D());
  view.resize(640, 480);
  view.show();
  QVERIFY(QTest::qWaitForWindowExposed(&view));
  for (const char* name : {"xmate3_pro", "xmate7", "xmate3", "xmate7_pro"}) {
    const xmate::model::RobotSpec* spec = xmate::model::findRobotSpec(name);
    QVERIFY(spec);
    view.setModel(spec->type);
    QCOMPARE(view.model(), spec->type);
    view.resetView();
    const QImage image = captureNow([&](auto done) { view.capture(done); });
    keep(image, QStringLiteral("view3d_%1").arg(QLatin1String(name)));
    QVERIFY2(centreCoverage(image) > 0.05, name);
  }
}

void TestView3dRender::mousePullEmitsSpringForce() {
  RobotView view;
  QVERIFY(view.is3D());
  view.resize(800, 600);
  view.show();
  QVERIFY(QTest::qWaitForWindowExposed(&view));
  QSignalSpy spy(&view, &RobotView::pullForceChanged);
  QPointF tcp;
  QTRY_VERIFY(view.scene());
  // The TCP's pixel in the 3D area; then grab 20 px to its right.
  QWindow* window = window3d();
  QVERIFY(window);
  QTRY_VERIFY(window->width() > 100);
  QVERIFY(view.camera().project(view.scene()->tcpPosition(), QSizeF(window->size()), tcp));
  view.setPullEnabled(false);
  QVERIFY(!view.beginPull(tcp));
  QCOMPARE(spy.count(), 0);
  view.setPullEnabled(true);
  QVERIFY(!view.beginPull(tcp + QPointF(200, 0)));  // not on the TCP
  QVERIFY(view.beginPull(tcp + QPointF(20, 0)));
  QVERIFY(view.pulling());
  QVERIFY(view.scene()->springVisible());
  QCOMPARE(spy.count(), 1);
  const QVector3D near_force = spy.last().at(0).value<QVector3D>();
  QVERIFY(near_force.length() > 0.1f && near_force.length() < RobotView::kPullMaxForce);
  view.movePull(tcp + QPointF(-150, -120));
  keep(captureNow([&](auto done) { view.capture(done); }), QStringLiteral("view3d_pull"));
  view.movePull(tcp + QPointF(600, -400));  // far: clamped
  QVERIFY(std::abs(spy.last().at(0).value<QVector3D>().length() - RobotView::kPullMaxForce) < 1e-3f);
  view.endPull();
  QVERIFY(!view.pulling());
  QVERIFY(!view.scene()->springVisible());
  QCOMPARE(spy.last().at(0).value<QVector3D>(), QVector3D());
  // Disabling during a pull releases it.
  QVERIFY(view.beginPull(tcp));
  view.setPullEnabled(false);
  QVERIFY(!view.pulling());
  QCOMPARE(spy.last().at(0).value<QVector3D>(), QVector3D());
}

void TestView3dRender::factoryViewCaptures() {
  Session session;
  std::unique_ptr<QWidget> widget(createRobotView(session, nullptr));
  auto* view = qobject_cast<RobotView*>(widget.get());
  QVERIFY(view && view->is3D());
  widget->resize(640, 480);
  widget->show();
  QVERIFY(QTest::qWaitForWindowExposed(widget.get()));
  const QImage image = captureNow([&](auto done) { captureRobotView(widget.get(), done); });
  QVERIFY(!image.isNull());
  // The whole widget: the tool strip on top, the render below it.
  QCOMPARE(image.size(), widget->grab().toImage().size());
  const QPoint sky(image.width() / 2, image.height() / 10);
  QVERIFY(differs(image.pixel(2, 2), image.pixel(sky)));
  QVERIFY(centreCoverage(image, sky) > 0.05);
  keep(image, QStringLiteral("view3d_factory"));
}


// Real pointer events on the Qt3D window: left drag orbits, right drag pans, the wheel zooms,
// a double click resets; Shift + left drag from the TCP pulls.
void TestView3dRender::pointerOrbitsPansZooms() {
  RobotView view;
  view.resize(800, 600);
  view.show();
  QVERIFY(QTest::qWaitForWindowExposed(&view));
  QWindow* window = window3d();
  QVERIFY(window);
  const OrbitCamera start = view.camera();
  sendMouse(window, QEvent::MouseButtonPress, {400, 300}, Qt::LeftButton);
  sendMouse(window, QEvent::MouseMove, {460, 280}, Qt::LeftButton);
  sendMouse(window, QEvent::MouseButtonRelease, {460, 280}, Qt::LeftButton);
  QVERIFY(std::abs(view.camera().yaw_deg - start.yaw_deg) > 10);
  QVERIFY(view.camera().pitch_deg != start.pitch_deg);
  QCOMPARE(view.camera().target, start.target);

  sendMouse(window, QEvent::MouseButtonPress, {400, 300}, Qt::RightButton);
  sendMouse(window, QEvent::MouseMove, {450, 300}, Qt::RightButton);
  sendMouse(window, QEvent::MouseButtonRelease, {450, 300}, Qt::RightButton);
  QVERIFY((view.camera().target - start.target).length() > 0.01f);

  QWheelEvent wheel({400, 300}, window->mapToGlobal(QPointF(400, 300)), {}, {0, 240}, Qt::NoButton, Qt::NoModifier,
                    Qt::NoScrollPhase, false);
  QCoreApplication::sendEvent(window, &wheel);
  QVERIFY(view.camera().distance < start.distance);

  QMouseEvent twice(QEvent::MouseButtonDblClick, QPointF(400, 300), window->mapToGlobal(QPointF(400, 300)),
                    Qt::LeftButton, Qt::LeftButton, Qt::NoModifier);
  QCoreApplication::sendEvent(window, &twice);
  sendMouse(window, QEvent::MouseButtonRelease, {400, 300}, Qt::LeftButton);
  QCOMPARE(view.camera().distance, start.distance);
  QCOMPARE(view.camera().yaw_deg, start.yaw_deg);

  view.setPullEnabled(true);
  QSignalSpy spy(&view, &RobotView::pullForceChanged);
  QPointF tcp;
  QVERIFY(view.camera().project(view.scene()->tcpPosition(), QSizeF(window->size()), tcp));
  sendMouse(window, QEvent::MouseButtonPress, tcp, Qt::LeftButton, Qt::ShiftModifier);
  QVERIFY(view.pulling());
  sendMouse(window, QEvent::MouseMove, tcp + QPointF(0, -50), Qt::LeftButton, Qt::ShiftModifier);
  QVERIFY(spy.last().at(0).value<QVector3D>().z() > 1.0f);
  QCOMPARE(view.camera().yaw_deg, start.yaw_deg);  // pulling does not orbit
  sendMouse(window, QEvent::MouseButtonRelease, tcp + QPointF(0, -50), Qt::LeftButton);
  QVERIFY(!view.pulling());
  QCOMPARE(spy.last().at(0).value<QVector3D>(), QVector3D());
}

// The whole path: a Session with the built-in simulator drives the view on tick(); the safety box
// follows operatorSettingsChanged(); in drag mode a mouse pull pushes the simulated TCP.
void TestView3dRender::followsTheSimulator() {
  Session session;
  std::unique_ptr<QWidget> widget(createRobotView(session, nullptr));
  auto* view = qobject_cast<RobotView*>(widget.get());
  QVERIFY(view && view->is3D());
  widget->resize(800, 600);
  widget->show();
  QVERIFY(QTest::qWaitForWindowExposed(widget.get()));
  SessionTarget target;
  target.kind = SessionTarget::Kind::kSimulator;
  target.type = xmate::XMATE3_PRO;
  QSignalSpy opened(&session, &Session::opened);
  session.open(target);
  QTRY_VERIFY_WITH_TIMEOUT(opened.count() == 1, 30000);
  QTRY_VERIFY_WITH_TIMEOUT(session.live().has_state, 10000);
  QSignalSpy ticks(&session, &Session::tick);
  QTRY_VERIFY_WITH_TIMEOUT(ticks.count() >= 2, 10000);
  QCOMPARE(view->model(), xmate::XMATE3_PRO);
  QCOMPARE(view->scene()->linkCount(), 8);
  QCOMPARE(view->scene()->jointPositions(), session.live().state.q);

  OperatorSettings settings = session.operatorSettings();
  settings.box.enabled = true;
  session.setOperatorSettings(settings);
  QVERIFY(view->scene()->safetyBoxVisible());

  QVERIFY(!view->pullEnabled());
  QSignalSpy finished(&session, &Session::commandFinished);
  session.run(QStringLiteral("drag"), [](xmate::Robot& robot) {
    robot.setMotorPower(1);
    robot.startDrag(2, 1);
  });
  QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 1, 20000);
  QVERIFY2(finished.at(0).at(1).toBool(), qPrintable(finished.at(0).at(2).toString()));
  QTRY_VERIFY_WITH_TIMEOUT(view->pullEnabled(), 10000);

  QWindow* window = window3d();
  QVERIFY(window);
  QPointF tcp;
  QVERIFY(view->camera().project(view->scene()->tcpPosition(), QSizeF(window->size()), tcp));
  QVERIFY(view->beginPull(tcp + QPointF(0, -30)));  // up on the screen
  const auto wrench = [&] { return session.simulator()->status().sim.external_wrench; };
  QTRY_VERIFY_WITH_TIMEOUT(wrench()[2] > 1.0, 5000);
  if (!qEnvironmentVariableIsEmpty("RCI_VIEW3D_PNG_DIR")) {  // the whole widget, as on screen
    view->movePull(tcp + QPointF(-90, -40));
    QTest::qWait(300);
    const QRect area(widget->mapToGlobal(QPoint(0, 0)), widget->size());
    keep(QGuiApplication::primaryScreen()->grabWindow(0, area.x(), area.y(), area.width(), area.height()).toImage(),
         QStringLiteral("view3d_widget"));
  }
  view->endPull();
  QTRY_VERIFY_WITH_TIMEOUT(wrench() == (std::array<double, 6>{}), 5000);
  session.close();
}

// With OpenGL on the CPU (Mesa llvmpipe, as under xvfb without a GPU), live poses are drawn at
// most kSoftwareLiveHz times a second, and a note beside the hint says so.
void TestView3dRender::softwareGlHasALiveUpdateBudget() {
  RobotView view;
  QVERIFY(view.is3D());
  if (!view.softwareRendered()) QSKIP("OpenGL runs on a GPU here: every live update is drawn");
  QVERIFY(view.liveUpdateDue());
  QElapsedTimer clock;
  clock.start();
  const bool again = view.liveUpdateDue();
  if (clock.elapsed() < 1000 / RobotView::kSoftwareLiveHz / 2) QVERIFY(!again);  // unless this thread stalled
  QTest::qWait(1000 / RobotView::kSoftwareLiveHz + 20);
  QVERIFY(view.liveUpdateDue());
  auto* note = view.findChild<QLabel*>(QStringLiteral("robotViewRenderNote"));
  QVERIFY(note);
  QVERIFY2(note->text().contains(QStringLiteral("Software OpenGL")), qPrintable(note->text()));
  QVERIFY2(note->toolTip().contains(QStringLiteral("OpenGL runs on the CPU here")), qPrintable(note->toolTip()));
}

void TestView3dRender::rendersKukaModels() {
  RobotView view;
  QVERIFY(view.is3D());
  view.resize(640, 480);
  view.show();
  QVERIFY(QTest::qWaitForWindowExposed(&view));
  for (const char* name : {"kr16_2", "kr6_r900_sixx"}) {
    const xmate::model::RobotSpec* spec = xmate::model::findRobotSpec(name);
    QVERIFY(spec);
    view.setModel(*spec);
    QCOMPARE(view.spec().name, spec->name);
    QCOMPARE(view.scene()->linkCount(), 7);
    QVERIFY2(!view.findChild<QLabel*>(QStringLiteral("robotViewHint"))->text().startsWith(QLatin1String("Cannot")),
             name);
    view.resetView();
    // The first frames after a model change may still show the grid alone: capture again until the
    // arm is in (a bounded number of times; a model that never draws fails).
    QImage image;
    for (int attempt = 0; attempt < 20 && housingShare(image) < 0.01; ++attempt)
      image = captureNow([&](auto done) { view.capture(done); });
    keep(image, QStringLiteral("view3d_%1").arg(QLatin1String(name)));
    QVERIFY2(housingShare(image) > 0.01, qPrintable(QStringLiteral("%1: %2 of the pixels are the housing's orange")
                                                        .arg(QLatin1String(name))
                                                        .arg(housingShare(image))));
  }
}

namespace {

double norm3(const std::array<double, 6>& w) { return std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]); }

}  // namespace

// A Session with the built-in KUKA simulator: the view loads the KR 6 R900 sixx, poses it and its
// TCP frame from the arm state, draws the RSI correction envelope around the start pose, and a
// Shift+drag from the flange pushes the simulated KRC (its F/T sensor reads the push); released,
// the push is gone.
void TestView3dRender::followsTheKukaSimulator() {
  Session session;
  std::unique_ptr<QWidget> widget(createRobotView(session, nullptr));
  auto* view = qobject_cast<RobotView*>(widget.get());
  QVERIFY(view && view->is3D());
  widget->resize(800, 600);
  widget->show();
  QVERIFY(QTest::qWaitForWindowExposed(widget.get()));
  QSignalSpy opened(&session, &Session::opened);
  session.open(test::kukaSimulator());
  QTRY_VERIFY_WITH_TIMEOUT(opened.count() == 1, 30000);
  QVERIFY(session.kukaSimulator());
  QTRY_VERIFY_WITH_TIMEOUT(session.live().has_arm_state, 10000);
  QCOMPARE(view->spec().name, std::string_view("kr6_r900_sixx"));
  QCOMPARE(view->scene()->linkCount(), 7);

  // Posed from the arm state: moved elsewhere, the next live update puts it back.
  view->setJointPositions({0.3, -1.2, 1.0, 0.2, 0.4, 0.1, 0});
  view->setTcpPose({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
  QTRY_COMPARE_WITH_TIMEOUT(view->scene()->jointPositions(), session.live().arm.sample.q, 5000);
  const std::array<double, 16>& tcp = session.live().arm.tcp;
  const QVector3D measured{float(tcp[3]), float(tcp[7]), float(tcp[11])};
  QTRY_VERIFY_WITH_TIMEOUT((view->scene()->tcpPosition() - measured).length() < 1e-5f, 5000);
  // The KRC's flange pose and the drawn arm agree (within a millimetre).
  const QVector3D flange = view->scene()->poser()->flangePose(session.live().arm.sample.q).column(3).toVector3D();
  QVERIFY2((flange - measured).length() < 1e-3f, qPrintable(QString::number(double((flange - measured).length()))));

  // The correction envelope holds the flange at the RSI start pose.
  QTRY_VERIFY_WITH_TIMEOUT(view->scene()->correctionEnvelopeVisible(), 5000);
  const QVector3D lo = view->scene()->correctionEnvelopeMin(), hi = view->scene()->correctionEnvelopeMax();
  for (int axis = 0; axis < 3; ++axis) {
    QVERIFY(measured[axis] > lo[axis] - 1e-3f && measured[axis] < hi[axis] + 1e-3f);
    QVERIFY(hi[axis] - lo[axis] > 0.005f);
  }
  QVERIFY(!view->scene()->safetyBoxVisible());  // an xMate's setting
  // The Program panel's waypoints and planned path, as on an xMate.
  ProgramOverlay overlay;
  overlay.waypoints = {{0.5, 0, 0.6}, {0.5, 0.2, 0.6}};
  overlay.labels = {QStringLiteral("P1"), QStringLiteral("P2")};
  overlay.path = {{0.5, 0, 0.6}, {0.5, 0.1, 0.62}, {0.5, 0.2, 0.6}};
  session.setProgramOverlay(overlay);
  QCOMPARE(view->scene()->waypointCount(), 2);
  QCOMPARE(view->scene()->plannedPathPointCount(), 3);
  if (!qEnvironmentVariableIsEmpty("RCI_VIEW3D_PNG_DIR"))
    keep(captureNow([&](auto done) { captureRobotView(widget.get(), done); }), QStringLiteral("view3d_kuka_sim"));

  // Shift+drag from the flange: a spring force at the flange of the simulated KRC.
  QTRY_VERIFY_WITH_TIMEOUT(view->pullEnabled(), 5000);
  QWindow* window = window3d();
  QVERIFY(window);
  QPointF pixel;
  QVERIFY(view->camera().project(view->scene()->tcpPosition(), QSizeF(window->size()), pixel));
  xmate::sim::Krc& krc = session.kukaSimulator()->krc();
  QCOMPARE(norm3(krc.flangeWrench()), 0.0);
  sendMouse(window, QEvent::MouseButtonPress, pixel, Qt::LeftButton, Qt::ShiftModifier);
  QVERIFY(view->pulling());
  sendMouse(window, QEvent::MouseMove, pixel + QPointF(0, -40), Qt::LeftButton, Qt::ShiftModifier);
  QVERIFY(view->scene()->springVisible());
  const double pushed = norm3(krc.flangeWrench());
  QVERIFY2(pushed > 1.0 && pushed <= RobotView::kPullMaxForce + 1e-3, qPrintable(QString::number(pushed)));
  QTRY_VERIFY_WITH_TIMEOUT(session.live().force_reading && norm3(session.live().force) > 1.0, 5000);
  sendMouse(window, QEvent::MouseButtonRelease, pixel + QPointF(0, -40), Qt::LeftButton);
  QVERIFY(!view->pulling());
  QCOMPARE(krc.flangeWrench(), (std::array<double, 6>{}));
  QTRY_VERIFY_WITH_TIMEOUT(norm3(session.live().force) < 0.1, 5000);

  session.close();
  QVERIFY(!view->pullEnabled());
  QVERIFY(!view->scene()->correctionEnvelopeVisible());
}

QTEST_MAIN(TestView3dRender)
#include "test_view3d_render.moc"
