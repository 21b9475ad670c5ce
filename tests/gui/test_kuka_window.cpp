// SPDX-License-Identifier: Apache-2.0
// The operator's KUKA flow through the main window on the built-in KUKA simulator: the panels that
// apply to a KUKA, force-guiding the flange by the F/T sensor (each guide mode), recording MOVEJ /
// MOVEL / MOVEC waypoints, replaying them, an RSI timeout the window reports and recovers from, and
// the same window switching back to an xMate.
#include <QDockWidget>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>

#include "arm/rsi_arm.h"
#include "guide/admittance.h"
#include "gui_test_support.h"
#include "model/arm_kinematics.h"
#include "panels/lamp.h"
#include "panels/program_panel.h"
#include "session/session.h"
#include "sim/krc_server.h"
#include "teach/executor.h"
#include "window/main_window.h"
#include "window/message_log.h"
#include "window_driver.h"

using namespace rci::ui;
using rci::ui::test::WindowDriver;

namespace {

constexpr int kWaitMs = 60000;  // a safety net for a loaded machine, not a timing claim

std::array<double, 3> position(const std::array<double, 16>& pose) { return {pose[3], pose[7], pose[11]}; }

double distance(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

double angle(const std::array<double, 16>& a, const std::array<double, 16>& b) {
  // The angle of R_a^T R_b from its trace.
  double trace = 0;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) trace += a[size_t(4 * k + i)] * b[size_t(4 * k + i)];
  return std::acos(std::clamp((trace - 1) / 2, -1.0, 1.0));
}

}  // namespace

class TestKukaWindow : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase();
  void cleanupTestCase();
  void showsThePanelsThatApply();
  void guidesInEachMode();
  void teachesAndReplays();
  void reportsRsiTimeoutAndRecovers();
  void switchesBackToAnXmate();
  void nextStartShowsThePanelsTheRobotHas();

 private:
  const xmate::arm::ArmState& arm() const { return session_->live().arm; }
  bool dockVisible(const QString& panel) const {
    auto* widget = window_->findChild<QWidget*>(panel);
    for (QWidget* w = widget; w; w = w->parentWidget())
      if (auto* dock = qobject_cast<QDockWidget*>(w)) return !dock->isHidden();
    return false;
  }
  bool atRest() const {
    double step = 0;
    for (size_t i = 0; i < 6; ++i) step = std::max(step, std::abs(arm().sample.q[i] - rest_q_[i]));
    rest_q_ = arm().sample.q;
    return step < 1e-5;
  }
  // Pushes the flange with `wrench` (base frame) in the simulator until the guide moved it (metres
  // or radians), then lets go and waits until the arm is at rest.
  void guideBy(const std::array<double, 6>& wrench, double metres, double radians);
  void record(int type_index) {
    driver_->find<QComboBox>(QStringLiteral("program.recordType"))->setCurrentIndex(type_index);
    QVERIFY(driver_->click(QStringLiteral("program.record")));
  }
  int rows() const { return driver_->find<QTableView>(QStringLiteral("program.list"))->model()->rowCount(); }
  bool logHas(const QString& needle) const { return log_->find(needle) >= 0; }
  void startGuiding(int axes);
  void stopGuiding();

  QTemporaryDir dir_;
  Session* session_ = nullptr;
  MainWindow* window_ = nullptr;
  MessageLog* log_ = nullptr;
  ProgramPanel* program_ = nullptr;
  std::unique_ptr<WindowDriver> driver_;
  mutable std::array<double, 7> rest_q_{};
};

void TestKukaWindow::initTestCase() {
  QVERIFY(dir_.isValid());
  qputenv("XDG_STATE_HOME", dir_.filePath(QStringLiteral("state")).toUtf8());
  test::usePrivateSettings(dir_.filePath(QStringLiteral("config")));
  session_ = new Session;
  window_ = new MainWindow(*session_);
  window_->resize(1600, 1000);
  window_->show();
  QVERIFY(QTest::qWaitForWindowExposed(window_));
  driver_ = std::make_unique<WindowDriver>(window_);
  log_ = window_->findChild<MessageLog*>();
  program_ = window_->findChild<ProgramPanel*>(QStringLiteral("panel.program"));
  QVERIFY(log_ && program_);
  program_->setDialogs({[] { return QString(); }, [](const QString&) { return QString(); },
                        [] { return ProgramPanel::UnsavedChoice::kDiscard; }});
  QSignalSpy failed(session_, &Session::openFailed);
  window_->connectTo(test::kukaSimulator());
  QTRY_VERIFY_WITH_TIMEOUT(session_->isOpen() || failed.count() > 0, kWaitMs);
  QVERIFY2(session_->isOpen(), failed.isEmpty() ? "" : qPrintable(failed.first().first().toString()));
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().rsi.phase == xmate::rsi::SessionPhase::kRunning &&
                               session_->live().force_reading,
                           kWaitMs);
}

void TestKukaWindow::cleanupTestCase() {
  driver_.reset();
  delete window_;
  delete session_;
}

void TestKukaWindow::showsThePanelsThatApply() {
  QVERIFY(!dockVisible(QStringLiteral("panel.power")));   // a KUKA is powered from its smartPAD
  QVERIFY(!dockVisible(QStringLiteral("panel.drag")));    // no built-in hand guiding
  QVERIFY(!dockVisible(QStringLiteral("panel.collision")));
  QVERIFY(dockVisible(QStringLiteral("panel.guide")));    // guiding by the force sensor instead
  QVERIFY(dockVisible(QStringLiteral("panel.program")));
  QVERIFY(dockVisible(QStringLiteral("panel.io")));
  QVERIFY(logHas(QStringLiteral("Connected to KUKA simulator")));
}

void TestKukaWindow::startGuiding(int axes) {
  QVERIFY(driver_->choose(QStringLiteral("guide.axes"), axes));
  QVERIFY(driver_->click(QStringLiteral("guide.start")));
  QTRY_VERIFY_WITH_TIMEOUT(driver_->find<Lamp>(QStringLiteral("guide.lamp"))->isOn(), kWaitMs);
}

void TestKukaWindow::stopGuiding() {
  QVERIFY(driver_->click(QStringLiteral("guide.stop")));
  QTRY_VERIFY_WITH_TIMEOUT(!session_->live().motion_running, kWaitMs);
  QVERIFY(driver_->text(QStringLiteral("guide.state")).contains(QStringLiteral("stopped by the operator")));
}

void TestKukaWindow::guideBy(const std::array<double, 6>& wrench, double metres, double radians) {
  const std::array<double, 16> start = arm().tcp;
  xmate::sim::Krc& krc = session_->kukaSimulator()->krc();
  krc.setExternalWrench(wrench);
  QTRY_VERIFY2_WITH_TIMEOUT(distance(position(arm().tcp), position(start)) > metres && angle(arm().tcp, start) >= radians,
                            qPrintable(QStringLiteral("moved %1 m, turned %2 rad; %3")
                                           .arg(distance(position(arm().tcp), position(start)))
                                           .arg(angle(arm().tcp, start))
                                           .arg(driver_->text(QStringLiteral("guide.detail")))),
                            kWaitMs);
  krc.setExternalWrench({});
  QTRY_VERIFY_WITH_TIMEOUT(atRest(), kWaitMs);
}

void TestKukaWindow::guidesInEachMode() {
  // Translation: a push along +y moves the flange along +y and keeps its orientation.
  startGuiding(int(xmate::guide::GuideAxes::kTranslation));
  std::array<double, 16> start = arm().tcp;
  guideBy({0, 40, 0, 0, 0, 0}, 0.02, 0);
  QVERIFY(arm().tcp[7] > start[7] + 0.02);
  QVERIFY2(angle(arm().tcp, start) < 0.01, qPrintable(QString::number(angle(arm().tcp, start))));
  stopGuiding();
  // Rotation: a twist turns the flange and keeps its position.
  startGuiding(int(xmate::guide::GuideAxes::kRotation));
  start = arm().tcp;
  guideBy({0, 0, 0, 0, 0, 3}, 0, 0.05);
  QVERIFY2(distance(position(arm().tcp), position(start)) < 0.005,
           qPrintable(QString::number(distance(position(arm().tcp), position(start)))));
  stopGuiding();
  // Free: both.
  startGuiding(int(xmate::guide::GuideAxes::kFree));
  guideBy({0, 0, 40, 0, 0, 3}, 0.02, 0.03);
  stopGuiding();
}

void TestKukaWindow::teachesAndReplays() {
  QVERIFY(driver_->click(QStringLiteral("program.new")));
  startGuiding(int(xmate::guide::GuideAxes::kTranslation));
  record(0);  // MOVEJ where the arm is
  guideBy({0, -40, 0, 0, 0, 0}, 0.03, 0);
  record(1);  // MOVEL
  guideBy({0, 0, -40, 0, 0, 0}, 0.02, 0);
  record(2);  // MOVEC via
  guideBy({0, 40, 0, 0, 0, 0}, 0.03, 0);
  record(2);  // MOVEC target
  QCOMPARE(rows(), 3);
  const std::array<double, 7> last = arm().sample.q;
  stopGuiding();

  // Replay from the start: Go to the first waypoint first, then run the program.
  QVERIFY(driver_->click(QStringLiteral("program.run")));
  QTRY_VERIFY_WITH_TIMEOUT(program_->isRunning(), kWaitMs);
  QTRY_VERIFY_WITH_TIMEOUT(!program_->isRunning(), 2 * kWaitMs);
  QVERIFY2(program_->lastReport().outcome == xmate::teach::RunState::kFinished,
           qPrintable(QString::fromStdString(program_->lastReport().message)));
  double error = 0;
  for (size_t i = 0; i < 6; ++i) error = std::max(error, std::abs(arm().sample.q[i] - last[i]));
  QVERIFY2(error < 2e-3, qPrintable(QString::number(error)));
}

void TestKukaWindow::reportsRsiTimeoutAndRecovers() {
  const uint32_t before = session_->live().rsi.session;
  session_->kukaSimulator()->krc().dropAnswers(1000);  // the PC's answers are lost on the way
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().rsi.phase == xmate::rsi::SessionPhase::kStopped, kWaitMs);
  QTRY_VERIFY_WITH_TIMEOUT(logHas(QStringLiteral("RSITimeout")), kWaitMs);
  session_->kukaSimulator()->krc().dropAnswers(0);
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().rsi.phase == xmate::rsi::SessionPhase::kRunning &&
                               session_->live().rsi.session > before,
                           kWaitMs);
  QTRY_VERIFY_WITH_TIMEOUT(logHas(QStringLiteral("RSI running")), kWaitMs);
  // Guiding works again in the new RSI session.
  startGuiding(int(xmate::guide::GuideAxes::kTranslation));
  guideBy({40, 0, 0, 0, 0, 0}, 0.01, 0);
  stopGuiding();
}

void TestKukaWindow::switchesBackToAnXmate() {
  QSignalSpy opened(session_, &Session::opened);
  window_->connectTo(test::lockstepSimulator());
  QTRY_COMPARE_WITH_TIMEOUT(opened.count(), 1, kWaitMs);
  QVERIFY(dockVisible(QStringLiteral("panel.power")));
  QVERIFY(dockVisible(QStringLiteral("panel.drag")));
  QVERIFY(!dockVisible(QStringLiteral("panel.guide")));
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().has_state, kWaitMs);
}

// Quit while a KUKA is connected (its xMate-only panels hidden), start again, connect an xMate: they
// are back -- the saved layout does not keep them hidden as if the operator had closed them.
void TestKukaWindow::nextStartShowsThePanelsTheRobotHas() {
  QSignalSpy opened(session_, &Session::opened);
  window_->connectTo(test::kukaSimulator());
  QTRY_COMPARE_WITH_TIMEOUT(opened.count(), 1, kWaitMs);
  QVERIFY(!dockVisible(QStringLiteral("panel.power")));
  QVERIFY(window_->close());
  driver_.reset();
  delete window_;
  session_->close();
  window_ = new MainWindow(*session_);
  window_->resize(1600, 1000);
  window_->show();
  QVERIFY(QTest::qWaitForWindowExposed(window_));
  window_->connectTo(test::lockstepSimulator());
  QTRY_COMPARE_WITH_TIMEOUT(opened.count(), 2, kWaitMs);
  QVERIFY(dockVisible(QStringLiteral("panel.power")));
  QVERIFY(dockVisible(QStringLiteral("panel.drag")));
  QVERIFY(!dockVisible(QStringLiteral("panel.guide")));
}

QTEST_MAIN(TestKukaWindow)
#include "test_kuka_window.moc"
