// SPDX-License-Identifier: Apache-2.0
// test_operator_scenario: the operator's whole teach loop in the real window, through its widgets,
// against the built-in simulator: connect -> power on -> hand-guide J7 into a soft limit (the
// wall holds it, no stop) -> soft limits that leave the joint outside (a violation) -> recover
// with the window's own controls (Recover, Jog back) -> record J, L and C waypoints -> save ->
// disconnect -> connect again -> open -> run to the end -> the event log holds every step.
// Registered twice: offscreen (the 3D view is a placeholder; pulls go through the Simulator panel)
// and under Xvfb with the 3D view (the first waypoint is pulled with Shift + drag on the TCP).
// The simulator's clock is real time (as the window uses it) unless RCI_SCENARIO_LOCKSTEP=1.
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QGuiApplication>
#include <QMouseEvent>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QWindow>

#include <algorithm>
#include <cmath>

#include "model/robot_spec.h"
#include "panels/lamp.h"
#include "panels/program_panel.h"
#include "session/session.h"
#include "teach/executor.h"
#include "view3d/robot_scene.h"
#include "view3d/robot_view.h"
#include "window/main_window.h"
#include "window/message_log.h"
#include "window_driver.h"
#include "state_compare.h"

using namespace rci::ui;
using rci::ui::test::WindowDriver;

namespace {

constexpr int kWaitMs = 60000;  // a safety net for a loaded machine, not a timing claim
constexpr double kDeg = 180.0 / 3.14159265358979323846;

using rci_test::anyError;
using rci_test::distance;

QWindow* window3d() {
  for (QWindow* w : QGuiApplication::allWindows())
    if (w->inherits("Qt3DExtras::Qt3DWindow") && w->isExposed()) return w;
  return nullptr;
}

void sendMouse(QWindow* window, QEvent::Type type, const QPointF& pos, Qt::KeyboardModifiers modifiers) {
  const Qt::MouseButtons buttons = type == QEvent::MouseButtonRelease ? Qt::NoButton : Qt::MouseButtons(Qt::LeftButton);
  QMouseEvent event(type, pos, window->mapToGlobal(pos), type == QEvent::MouseMove ? Qt::NoButton : Qt::LeftButton,
                    buttons, modifiers);
  QCoreApplication::sendEvent(window, &event);
}

}  // namespace

// Runs a step that may fail inside a helper, and ends the test at its first failure.
#define STEP(call)                               \
  do {                                           \
    call;                                        \
    if (QTest::currentTestFailed()) return;      \
  } while (false)

class TestOperatorScenario : public QObject {
  Q_OBJECT

 private:
  const RCI::robot::RobotState& state() const { return session_->live().state; }
  bool atRest() const {
    double speed = 0;
    for (double v : state().dq_m) speed = std::max(speed, std::abs(v));
    return speed < 1e-4;
  }
  // The joints (deg), speeds and errors, for failure messages.
  QString describe() const {
    QStringList q, dq;
    for (int i = 0; i < 7; ++i) {
      q << QString::number(state().q[i] * kDeg, 'f', 1);
      dq << QString::number(state().dq_m[i], 'f', 3);
    }
    return QStringLiteral("q [deg] %1; dq [rad/s] %2; errors %3; wrench %4")
        .arg(q.join(' '), dq.join(' '), anyError(state()) ? QStringLiteral("yes") : QStringLiteral("none"))
        .arg(session_->live().sim.external_wrench[5]);
  }
  bool logHas(const QString& needle) const { return log_->find(needle) >= 0; }
  QString logDump() const {
    QStringList rows;
    for (int i = 0; i < log_->count(); ++i) rows << log_->text(i);
    return rows.join('\n');
  }
  bool motorsOn() const { return driver_->find<Lamp>(QStringLiteral("power.lamp"))->isOn(); }
  // Sets the Simulator panel's wrench fields (N, Nm) and presses Apply, as an operator pushes the arm.
  void push(const std::array<double, 6>& wrench) {
    const char* names[6] = {"fx", "fy", "fz", "mx", "my", "mz"};
    for (int i = 0; i < 6; ++i) QVERIFY(driver_->type(QStringLiteral("sim.") + QLatin1String(names[i]), wrench[i]));
    QVERIFY(driver_->click(QStringLiteral("sim.wrench.apply")));
  }
  void letGo() {
    QVERIFY(driver_->click(QStringLiteral("sim.wrench.release")));
    QTRY_VERIFY_WITH_TIMEOUT(session_->live().sim.external_wrench == (std::array<double, 6>{}), kWaitMs);
  }
  // Pushes the TCP with `force` (N, base frame) through the Simulator panel until it moved `metres`.
  void guideBy(const std::array<double, 3>& force, double metres) {
    const auto start = state().toolTobase_pos_m;
    push({force[0], force[1], force[2], 0, 0, 0});
    if (QTest::currentTestFailed()) return;
    QTRY_VERIFY2_WITH_TIMEOUT(distance(state().toolTobase_pos_m, start) > metres,
                              qPrintable(QStringLiteral("moved %1 m of %2 m; ").arg(distance(state().toolTobase_pos_m, start)).arg(metres) + describe()), kWaitMs);
    letGo();
    QTRY_VERIFY_WITH_TIMEOUT(atRest(), kWaitMs);
  }
  // Shift + drag from the TCP in the 3D view until the TCP moved `metres`.
  void pullWithMouse(double metres) {
    auto* view = qobject_cast<RobotView*>(window_->robotView());
    QWindow* window = window3d();
    QVERIFY(view && window && view->scene());
    QTRY_VERIFY_WITH_TIMEOUT(view->pullEnabled(), kWaitMs);
    QPointF tcp;
    QVERIFY(view->camera().project(view->scene()->tcpPosition(), QSizeF(window->size()), tcp));
    const auto start = state().toolTobase_pos_m;
    sendMouse(window, QEvent::MouseButtonPress, tcp, Qt::ShiftModifier);
    QVERIFY(view->pulling());
    sendMouse(window, QEvent::MouseMove, tcp + QPointF(0, -60), Qt::ShiftModifier);
    QTRY_VERIFY_WITH_TIMEOUT(distance(state().toolTobase_pos_m, start) > metres, kWaitMs);
    sendMouse(window, QEvent::MouseButtonRelease, tcp + QPointF(0, -60), Qt::NoModifier);
    QVERIFY(!view->pulling());
    QTRY_VERIFY_WITH_TIMEOUT(atRest(), kWaitMs);
  }
  void record(int type_index) {
    driver_->find<QComboBox>(QStringLiteral("program.recordType"))->setCurrentIndex(type_index);
    QVERIFY(driver_->click(QStringLiteral("program.record")));
  }
  int rows() const { return driver_->find<QTableView>(QStringLiteral("program.list"))->model()->rowCount(); }
  void connectThroughToolbar();
  void powerOn();

  QTemporaryDir dir_;
  Session* session_ = nullptr;
  MainWindow* window_ = nullptr;
  MessageLog* log_ = nullptr;
  ProgramPanel* program_ = nullptr;
  std::unique_ptr<WindowDriver> driver_;
  QString save_path_;
  QString open_path_;

 private slots:
  void initTestCase();
  void cleanupTestCase();
  void teachLoop();
};

void TestOperatorScenario::initTestCase() {
  QStandardPaths::setTestModeEnabled(true);
  QVERIFY(dir_.isValid());
  qputenv("XDG_STATE_HOME", dir_.filePath(QStringLiteral("state")).toUtf8());
  QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, dir_.filePath(QStringLiteral("config")));
  QSettings(QStringLiteral("RCI Studio"), QStringLiteral("rci-studio")).clear();
  session_ = new Session;
  window_ = new MainWindow(*session_);
  window_->show();
  QVERIFY(QTest::qWaitForWindowExposed(window_));
  driver_ = std::make_unique<WindowDriver>(window_);
  log_ = window_->findChild<MessageLog*>();
  program_ = window_->findChild<ProgramPanel*>(QStringLiteral("panel.program"));
  QVERIFY(log_ && program_);
  // The file dialogs answer with these paths (a modal dialog would wait for a person).
  program_->setDialogs({[this] { return open_path_; }, [this](const QString&) { return save_path_; },
                        [] { return ProgramPanel::UnsavedChoice::kDiscard; }});
}

void TestOperatorScenario::cleanupTestCase() {
  driver_.reset();
  delete window_;
  delete session_;
}

void TestOperatorScenario::connectThroughToolbar() {
  QSignalSpy failed(session_, &Session::openFailed);
  if (qEnvironmentVariableIntValue("RCI_SCENARIO_LOCKSTEP") == 1) {
    SessionTarget target;  // the toolbar has no clock choice: the command line's --lockstep does this
    target.lockstep = true;
    window_->connectTo(target);
  } else {
    QCOMPARE(driver_->find<QComboBox>(QStringLiteral("connection.kind"))->currentIndex(), 0);  // built-in simulator
    QVERIFY(driver_->click(QStringLiteral("connection.connect")));
  }
  QTRY_VERIFY_WITH_TIMEOUT(session_->isOpen() || failed.count() > 0, kWaitMs);
  QVERIFY2(session_->isOpen(), failed.isEmpty() ? "" : qPrintable(failed.first().first().toString()));
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().has_state, kWaitMs);
  QCOMPARE(driver_->text(QStringLiteral("connection.connect")), QStringLiteral("Disconnect"));
}

void TestOperatorScenario::powerOn() {
  QVERIFY(driver_->click(QStringLiteral("power.on")));
  QTRY_VERIFY_WITH_TIMEOUT(motorsOn(), kWaitMs);
}

void TestOperatorScenario::teachLoop() {
  const bool with_3d = qobject_cast<RobotView*>(window_->robotView()) &&
                       qobject_cast<RobotView*>(window_->robotView())->is3D();
  qInfo("3D view: %s; simulator clock: %s", with_3d ? "yes" : "placeholder",
        qEnvironmentVariableIntValue("RCI_SCENARIO_LOCKSTEP") == 1 ? "lock-step" : "real time");

  // ---- Connect, power on, set J7's soft limit 10 deg above it, hand-guide J7 into that limit:
  // the wall holds it short of the limit, nothing stops.
  STEP(connectThroughToolbar());
  STEP(powerOn());
  const auto& spec = xmate::model::robotSpec(session_->target().type);
  const double wall_limit = std::round(state().q[6] * kDeg) + 10.0;
  QVERIFY(driver_->click(QStringLiteral("limits.hardware")));
  driver_->check(QStringLiteral("limits.enable"), true);
  driver_->check(QStringLiteral("limits.auto"), false);
  QVERIFY(driver_->type(QStringLiteral("limits.upper7"), wall_limit));
  QVERIFY(driver_->click(QStringLiteral("limits.apply")));
  QTRY_VERIFY_WITH_TIMEOUT(session_->operatorSettings().soft_limits_enabled, kWaitMs);
  QVERIFY(driver_->choose(QStringLiteral("drag.space"), 1));  // joint space
  QVERIFY(driver_->choose(QStringLiteral("drag.type"), 3));   // free
  QVERIFY(driver_->click(QStringLiteral("drag.start")));
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().sim.dragging, kWaitMs);
  // A twist about the tool's axis (pointing down: -z in the base frame) turns J7 towards its limit.
  STEP(push({0, 0, 0, 0, 0, -5}));
  QTRY_VERIFY2_WITH_TIMEOUT(state().q[6] * kDeg > wall_limit - 5.0 && std::abs(state().dq_m[6]) < 1e-3,
                            qPrintable(describe()), kWaitMs);
  QTest::qWait(300);  // keep twisting against the wall
  QVERIFY2(!anyError(state()), qPrintable(describe() + "\n" + logDump()));
  QVERIFY2(state().q[6] * kDeg <= wall_limit, qPrintable(describe()));
  QVERIFY(session_->live().sim.dragging);
  for (int i = 0; i < spec.dof; ++i)
    QVERIFY2(state().q[i] <= spec.q_max[i] && state().q[i] >= spec.q_min[i], qPrintable(QString("J%1").arg(i + 1)));
  STEP(letGo());
  QVERIFY(driver_->click(QStringLiteral("drag.stop")));
  QTRY_VERIFY_WITH_TIMEOUT(!session_->live().sim.dragging && atRest(), kWaitMs);
  qInfo("at J7's wall: %s", qPrintable(describe()));

  // ---- Soft limits that leave J7 outside: the robot reports J7 beyond its limit.
  const double soft_upper = std::floor(state().q[6] * kDeg - 3.0);
  QVERIFY(driver_->type(QStringLiteral("limits.upper7"), soft_upper));
  QVERIFY(driver_->click(QStringLiteral("limits.apply")));
  QTRY_VERIFY_WITH_TIMEOUT(state().errors[0], kWaitMs);
  // The Safety panel says which joint, by how much and what to press.
  QTRY_VERIFY2_WITH_TIMEOUT(driver_->text(QStringLiteral("safety.details")).contains(QStringLiteral("J7 reached its upper soft limit")),
                            qPrintable(driver_->text(QStringLiteral("safety.details"))), kWaitMs);
  const QString details = driver_->text(QStringLiteral("safety.details"));
  QVERIFY2(details.contains(QStringLiteral("Press Recover")) && details.contains(QStringLiteral("Jog J7 −")), qPrintable(details));

  // ---- Recover with the window's controls, then hold Jog J7 − until J7 is back in range.
  QVERIFY(driver_->click(QStringLiteral("safety.recover")));
  QTRY_VERIFY_WITH_TIMEOUT(!anyError(state()), kWaitMs);
  QVERIFY(motorsOn());  // a position limit does not switch the motors off
  QVERIFY2(driver_->text(QStringLiteral("safety.details")).contains(QStringLiteral("beyond its upper soft limit")),
           qPrintable(driver_->text(QStringLiteral("safety.details"))));
  // Hold Jog J7 −; if the jog ended early (the dead-man stops a jog when the window did not tick for
  // 150 ms, which a loaded machine can cause), press again, as an operator would.
  QVERIFY(driver_->press(QStringLiteral("jog.joint7.minus")));
  QElapsedTimer jogging;
  jogging.start();
  while (!(state().q[6] * kDeg < soft_upper - 1.0 || anyError(state())) && jogging.elapsed() < kWaitMs) {
    QTest::qWait(20);
    if (!session_->live().motion_running && !anyError(state())) {
      driver_->release(QStringLiteral("jog.joint7.minus"));
      QVERIFY(driver_->press(QStringLiteral("jog.joint7.minus")));
    }
  }
  driver_->release(QStringLiteral("jog.joint7.minus"));
  QTRY_VERIFY_WITH_TIMEOUT(!session_->live().motion_running && atRest(), kWaitMs);
  if (anyError(state())) qInfo("jogging back failed: %s\nthe event log:\n%s", qPrintable(describe()), qPrintable(logDump()));
  QVERIFY(!anyError(state()));
  QVERIFY(state().q[6] * kDeg < soft_upper);
  qInfo("jogged back: %s", qPrintable(describe()));
  // Back to the hardware range for teaching.
  driver_->check(QStringLiteral("limits.enable"), false);
  QVERIFY(driver_->click(QStringLiteral("limits.apply")));
  QTRY_VERIFY_WITH_TIMEOUT(!session_->operatorSettings().soft_limits_enabled, kWaitMs);

  // ---- Teach: guide in Cartesian translation and record J, L and C (via, target).
  QVERIFY(driver_->choose(QStringLiteral("drag.space"), 2));
  QVERIFY(driver_->choose(QStringLiteral("drag.type"), 1));
  QVERIFY(driver_->click(QStringLiteral("drag.start")));
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().sim.dragging, kWaitMs);
  if (with_3d)
    STEP(pullWithMouse(0.03));
  else
    STEP(guideBy({0, 25, 0}, 0.05));
  STEP(record(0));
  QCOMPARE(rows(), 1);
  STEP(guideBy({0, 0, -25}, 0.05));
  STEP(record(1));
  QCOMPARE(rows(), 2);
  STEP(guideBy({25, 0, 0}, 0.04));
  STEP(record(2));  // the via point
  STEP(guideBy({0, -25, 0}, 0.04));
  STEP(record(2));  // the target
  QCOMPARE(rows(), 3);
  QVERIFY(driver_->click(QStringLiteral("drag.stop")));
  QTRY_VERIFY_WITH_TIMEOUT(!session_->live().sim.dragging, kWaitMs);
  save_path_ = dir_.filePath(QStringLiteral("taught.json"));
  QVERIFY(driver_->click(QStringLiteral("program.save")));
  QVERIFY(QFileInfo::exists(save_path_));

  // ---- Disconnect, connect again, open the program and run it to the end.
  QVERIFY(driver_->click(QStringLiteral("connection.connect")));  // "Disconnect"
  QTRY_VERIFY_WITH_TIMEOUT(!session_->isOpen(), kWaitMs);
  STEP(connectThroughToolbar());
  STEP(powerOn());
  QVERIFY(driver_->click(QStringLiteral("program.new")));
  QCOMPARE(rows(), 0);
  open_path_ = save_path_;
  QVERIFY(driver_->click(QStringLiteral("program.open")));
  QCOMPARE(rows(), 3);
  QVERIFY(driver_->click(QStringLiteral("program.run")));
  QTRY_VERIFY_WITH_TIMEOUT(program_->isRunning(), kWaitMs);
  QTRY_VERIFY_WITH_TIMEOUT(!program_->isRunning(), 3 * kWaitMs);
  QVERIFY2(program_->lastReport().outcome == xmate::teach::RunState::kFinished,
           qPrintable(QString::fromStdString(program_->lastReport().message) + "\n" + logDump()));

  // ---- The event log holds every step, in the dock and in the file.
  const QStringList steps = {QStringLiteral("Connected to"),        QStringLiteral("Motors on"),
                             QStringLiteral("Hand guiding started"), QStringLiteral("Hand guiding stopped"),
                             QStringLiteral("Robot reports:"),       QStringLiteral("J7"),
                             QStringLiteral("recover"),              QStringLiteral("Errors cleared"),
                             QStringLiteral("J7 is back within its range"),
                             QStringLiteral("Recorded P1"),          QStringLiteral("Recorded P3"),
                             QStringLiteral("Saved taught.json"),    QStringLiteral("Disconnected"),
                             QStringLiteral("Opened taught.json"),   QStringLiteral("finished")};
  const auto missing = std::find_if(steps.begin(), steps.end(), [this](const QString& step) { return !logHas(step); });
  if (missing != steps.end()) qInfo("the event log:\n%s", qPrintable(logDump()));  // QVERIFY2 cuts long messages
  QVERIFY2(missing == steps.end(), qPrintable(missing == steps.end() ? QString() : *missing + QStringLiteral(" is not in the log")));
  log_->flushLogFile();
  QFile file(log_->logFilePath());
  QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(log_->logFilePath()));
  const QString written = QString::fromUtf8(file.readAll());
  for (const QString& step : steps) QVERIFY2(written.contains(step), qPrintable(step + " is not in the log file"));
}

QTEST_MAIN(TestOperatorScenario)
#include "test_operator_scenario.moc"
