// SPDX-License-Identifier: Apache-2.0
// test_panels: builds the dock panels on a Session with the embedded lock-step simulator (DO->DI
// loop-back) and drives them with QTest: power, IO, thresholds, refusals, an injected collision,
// recovery, drag, jog; plus the jog profile and limit braking on a simulated state loop.
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QVBoxLayout>

#include <chrono>
#include <cmath>
#include <functional>
#include <set>
#include <thread>
#include <utility>

#include <xmate/move.h>

#include "model/robot_spec.h"
#include "panels/fields.h"
#include "panels/lamp.h"
#include "panels/tool_panel.h"
#include "session/session.h"
#include "sim/server.h"
#include "window/parts.h"
#include "gui_test_support.h"
#include "window_driver.h"

using namespace rci::ui;

namespace {

constexpr int kWaitMs = 20000;  // a safety net for a loaded machine, not a timing claim

}  // namespace

class TestPanels : public QObject {
  Q_OBJECT

 private:
  template <class T>
  T* find(const QString& name) {
    return test::WindowDriver(host_).find<T>(name);
  }
  bool lampOn(const QString& name) {
    auto* lamp = find<Lamp>(name);
    return lamp && lamp->isOn();
  }
  void click(const QString& name) { QVERIFY2(test::WindowDriver(host_).click(name), qPrintable(name)); }
  void setField(const QString& name, double value) {
    auto* field = find<QDoubleSpinBox>(name);
    QVERIFY2(field, qPrintable(name));
    field->setValue(value);
  }
  QString statusText(const QString& panel) { return find<QLabel>(panel + QStringLiteral(".status"))->text(); }
  // Waits until the panel's status line reports the action done (or fails with what it says).
  void waitDone(const QString& panel, const QString& action) {
    QTRY_VERIFY2_WITH_TIMEOUT(statusText(panel).startsWith(action + QStringLiteral(": done")) ||
                                  statusText(panel).contains(QStringLiteral("failed")),
                              qPrintable(statusText(panel)), kWaitMs);
    QVERIFY2(!statusText(panel).contains(QStringLiteral("failed")), qPrintable(statusText(panel)));
  }
  void powerOn() {
    click(QStringLiteral("power.on"));
    QTRY_VERIFY_WITH_TIMEOUT(lampOn(QStringLiteral("power.lamp")), kWaitMs);
  }
  void waitMotionEnd() {
    QTRY_VERIFY_WITH_TIMEOUT(!session_->live().motion_running, kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(session_->live().state.robot_mode != RCI::robot::RobotMode::kMove, kWaitMs);
  }
  // Holds a jog button until `reached` holds, then lets go and waits for the jog to end; true if
  // every jog ended cleanly. A jog the dead-man ended (the window did not tick for 150 ms, which a
  // loaded test machine can cause) is pressed again, as an operator would.
  bool holdJog(QPushButton* button, const std::function<bool()>& reached, QString* failure) {
    QElapsedTimer timer;
    timer.start();
    while (timer.elapsed() < kWaitMs) {
      QSignalSpy finished(session_, &Session::motionFinished);
      QTest::mousePress(button, Qt::LeftButton);
      while (!reached() && finished.isEmpty() && timer.elapsed() < kWaitMs) QTest::qWait(10);
      QTest::mouseRelease(button, Qt::LeftButton);
      if (!QTest::qWaitFor([&] { return !finished.isEmpty(); }, kWaitMs)) break;
      const QString message = finished.first().at(2).toString();
      if (finished.first().at(1).toBool()) return reached();
      if (!message.contains(QStringLiteral("did not respond"))) {
        *failure = message;
        return false;
      }
      waitMotionEnd();
    }
    *failure = QStringLiteral("not reached in time");
    return false;
  }

  QTemporaryDir settings_dir_;
  Session* session_ = nullptr;
  QWidget* host_ = nullptr;
  std::vector<PanelSpec> panels_;

 private slots:
  void initTestCase();
  void cleanupTestCase();
  void panelsAndNames();
  void powerOnLightsMotorLamp();
  void digitalOutputLoopsBackToInput();
  void thresholdsApplyAndRecord();
  void invalidThresholdRefusedAndNothingSent();
  void filtersRefuseAndWarn();
  void settingsPersist();
  void softLimitsRefuseAndApply();
  void toolPayloadAndImpedanceEditors();
  void toolFrameFromAngles();
  void safetyBoxApplyRecords();
  void collisionShowsInSafetyPanelAndRecovers();
  void dragTogglesGuiding();
  void jogMovesJoint();
  void jogMovesTcp();
  void stopsShowInSafetyPanel();
  void simulatorPanelDisabledWithoutSimulator();
  void sixAxisModelHidesSeventhJoint();
};

void TestPanels::initTestCase() {
  QVERIFY(settings_dir_.isValid());
  test::usePrivateSettings(settings_dir_.path());
  session_ = new Session;
  host_ = new QWidget;
  panels_ = createPanels(*session_, host_);
  auto* layout = new QVBoxLayout(host_);
  for (const auto& p : panels_) layout->addWidget(p.widget);
  host_->show();

  SessionTarget target;
  target.kind = SessionTarget::Kind::kSimulator;
  target.type = xmate::XMATE7_PRO;
  target.lockstep = true;
  target.loopback = true;
  QSignalSpy failed(session_, &Session::openFailed);
  session_->open(target);
  QTRY_VERIFY_WITH_TIMEOUT(session_->isOpen() || failed.count() > 0, kWaitMs);
  QVERIFY2(session_->isOpen(), failed.isEmpty() ? "" : qPrintable(failed.first().first().toString()));
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().has_state, kWaitMs);
}

void TestPanels::cleanupTestCase() {
  delete host_;
  delete session_;
}

void TestPanels::panelsAndNames() {
  // 12 + Program + the KUKA ones: hand guiding by the force sensor, Force sensor, RSI.
  QCOMPARE(int(panels_.size()), 16);
  std::set<QString> ids;
  for (const auto& p : panels_) {
    QVERIFY(p.widget);
    QVERIFY(!p.title.isEmpty());
    QVERIFY(ids.insert(p.id).second);
  }
  const char* names[] = {"power.on", "power.off", "power.reboot", "io.do0", "io.do5", "io.di0", "io.di5",
                         "safety.recover", "safety.estop", "safety.gstop", "safety.bit0", "safety.bit19",
                         "collision.threshold1", "collision.apply", "collision.bar1", "box.sizex", "box.x",
                         "box.enable", "box.apply", "limits.upper1", "limits.lower7", "limits.enable",
                         "limits.auto", "limits.apply", "filters.joint", "filters.cartesian", "filters.torque",
                         "filters.apply", "impedance.joint1", "impedance.cart6", "impedance.wrench3",
                         "impedance.joint.apply", "impedance.cart.apply", "impedance.wrench.apply", "tool.x",
                         "tool.rz", "tool.apply", "payload.mass", "payload.ixx", "payload.apply", "drag.space",
                         "drag.type", "drag.start", "drag.stop", "jog.joint1.plus", "jog.joint7.minus",
                         "jog.cart.x.plus", "jog.cart.rz.minus", "jog.speed", "sim.fx", "sim.mz",
                         "sim.wrench.apply", "sim.wrench.release", "sim.estop", "sim.gstop", "sim.di0",
                         "sim.loopback"};
  for (const char* name : names) QVERIFY2(host_->findChild<QWidget*>(QLatin1String(name)), name);
}

void TestPanels::powerOnLightsMotorLamp() {
  QVERIFY(find<QPushButton>(QStringLiteral("power.on"))->isEnabled());
  powerOn();
  waitDone(QStringLiteral("power"), QStringLiteral("power on"));
}

void TestPanels::digitalOutputLoopsBackToInput() {
  QVERIFY(!lampOn(QStringLiteral("io.di2")));
  click(QStringLiteral("io.do2"));
  QTRY_VERIFY_WITH_TIMEOUT(lampOn(QStringLiteral("io.di2")), kWaitMs);
  QVERIFY(find<QCheckBox>(QStringLiteral("io.do2"))->isChecked());
  click(QStringLiteral("io.do2"));
  QTRY_VERIFY_WITH_TIMEOUT(!lampOn(QStringLiteral("io.di2")), kWaitMs);
  QVERIFY(!find<QCheckBox>(QStringLiteral("io.do2"))->isChecked());
}

void TestPanels::thresholdsApplyAndRecord() {
  setField(QStringLiteral("collision.threshold1"), 60);
  click(QStringLiteral("collision.apply"));
  waitDone(QStringLiteral("collision"), QStringLiteral("apply thresholds"));
  QCOMPARE(session_->operatorSettings().collision_thresholds[0], 60.0);
  QCOMPARE(session_->operatorSettings().collision_thresholds[6], 20.0);
  QVERIFY(find<MessageLine>(QStringLiteral("collision.message"))->kind().isEmpty());
}

void TestPanels::invalidThresholdRefusedAndNothingSent() {
  QSignalSpy sent(session_, &Session::commandFinished);
  setField(QStringLiteral("collision.threshold3"), 90);  // J3 allows at most 60 Nm
  click(QStringLiteral("collision.apply"));
  auto* message = find<MessageLine>(QStringLiteral("collision.message"));
  QCOMPARE(message->kind(), QStringLiteral("error"));
  QVERIFY2(message->text().contains(QStringLiteral("J3 threshold = 90")), qPrintable(message->text()));
  QVERIFY(message->text().contains(QStringLiteral("60")));
  QVERIFY(find<QDoubleSpinBox>(QStringLiteral("collision.threshold3"))->property("invalid").toBool());
  // Commands run in order: once a later command finished, a sent threshold would have finished too.
  click(QStringLiteral("filters.apply"));
  waitDone(QStringLiteral("filters"), QStringLiteral("apply filters"));
  for (const auto& args : sent) QVERIFY(!args.first().toString().startsWith(QStringLiteral("Collision:")));
  QCOMPARE(session_->operatorSettings().collision_thresholds[2], 60.0);
  setField(QStringLiteral("collision.threshold3"), 60);
}

void TestPanels::filtersRefuseAndWarn() {
  QSignalSpy sent(session_, &Session::commandFinished);
  auto* message = find<MessageLine>(QStringLiteral("filters.message"));
  setField(QStringLiteral("filters.torque"), 2000);  // above 1000 Hz: refused
  click(QStringLiteral("filters.apply"));
  QCOMPARE(message->kind(), QStringLiteral("error"));
  QVERIFY2(message->text().contains(QStringLiteral("Torque filter = 2000")), qPrintable(message->text()));
  QVERIFY(find<QDoubleSpinBox>(QStringLiteral("filters.torque"))->property("invalid").toBool());
  QCOMPARE(sent.count(), 0);

  setField(QStringLiteral("filters.torque"), 5);  // allowed, outside 10-100 Hz: warned and sent
  click(QStringLiteral("filters.apply"));
  QCOMPARE(message->kind(), QStringLiteral("warning"));
  QVERIFY2(message->text().contains(QStringLiteral("torque 5 Hz")), qPrintable(message->text()));
  waitDone(QStringLiteral("filters"), QStringLiteral("apply filters"));
  QVERIFY(!find<QDoubleSpinBox>(QStringLiteral("filters.torque"))->property("invalid").toBool());

  setField(QStringLiteral("filters.torque"), 100);
  click(QStringLiteral("filters.apply"));
  QVERIFY(message->kind().isEmpty());
  waitDone(QStringLiteral("filters"), QStringLiteral("apply filters"));
}

void TestPanels::settingsPersist() {
  QSettings settings(QStringLiteral("RCI Studio"), QStringLiteral("rci-studio"));
  QVERIFY2(settings.fileName().startsWith(settings_dir_.path()), qPrintable(settings.fileName()));
  QCOMPARE(settings.value(QStringLiteral("collision/collision.threshold1")).toDouble(), 60.0);
  QCOMPARE(settings.value(QStringLiteral("filters/filters.torque")).toDouble(), 100.0);
  // A new set of panels starts from the saved values.
  QWidget other;
  createPanels(*session_, &other);
  QCOMPARE(other.findChild<QDoubleSpinBox*>(QStringLiteral("collision.threshold1"))->value(), 60.0);
}

void TestPanels::softLimitsRefuseAndApply() {
  auto* message = find<MessageLine>(QStringLiteral("limits.message"));
  find<QCheckBox>(QStringLiteral("limits.enable"))->setChecked(true);
  setField(QStringLiteral("limits.lower2"), 100);
  setField(QStringLiteral("limits.upper2"), 50);
  click(QStringLiteral("limits.apply"));
  QCOMPARE(message->kind(), QStringLiteral("error"));
  QVERIFY2(message->text().contains(QStringLiteral("J2 lower limit = 100 must be below J2 upper limit = 50")),
           qPrintable(message->text()));
  setField(QStringLiteral("limits.upper1"), 200);  // beyond the 170 deg hardware limit
  setField(QStringLiteral("limits.lower2"), -100);
  setField(QStringLiteral("limits.upper2"), 100);
  click(QStringLiteral("limits.apply"));
  QVERIFY2(message->text().contains(QStringLiteral("J1 upper limit = 200")), qPrintable(message->text()));
  QVERIFY(find<QDoubleSpinBox>(QStringLiteral("limits.upper1"))->property("invalid").toBool());

  setField(QStringLiteral("limits.upper1"), 150);
  click(QStringLiteral("limits.apply"));
  QVERIFY(message->kind().isEmpty());
  waitDone(QStringLiteral("limits"), QStringLiteral("apply soft limits"));
  QVERIFY(session_->operatorSettings().soft_limits_enabled);
  QCOMPARE(session_->operatorSettings().soft_upper_deg[0], 150.0);
  QCOMPARE(session_->operatorSettings().soft_lower_deg[1], -100.0);
}

void TestPanels::toolPayloadAndImpedanceEditors() {
  auto* tool_message = find<MessageLine>(QStringLiteral("tool.message"));
  setField(QStringLiteral("tool.z"), 0.8);  // beyond the 0.5 m the controller accepts
  click(QStringLiteral("tool.apply"));
  QCOMPARE(tool_message->kind(), QStringLiteral("error"));
  QVERIFY2(tool_message->text().contains(QStringLiteral("0.5 m")), qPrintable(tool_message->text()));
  setField(QStringLiteral("tool.z"), 0.1);
  setField(QStringLiteral("tool.rz"), 90);
  click(QStringLiteral("tool.apply"));
  QVERIFY(tool_message->kind().isEmpty());
  waitDone(QStringLiteral("tool"), QStringLiteral("apply TCP"));
  QTRY_COMPARE_WITH_TIMEOUT(session_->robot()->toolFrame()[11], 0.1, kWaitMs);
  setField(QStringLiteral("tool.z"), 0);
  setField(QStringLiteral("tool.rz"), 0);
  click(QStringLiteral("tool.apply"));
  waitDone(QStringLiteral("tool"), QStringLiteral("apply TCP"));

  auto* payload_message = find<MessageLine>(QStringLiteral("payload.message"));
  setField(QStringLiteral("payload.mass"), 9);  // the xMate Pro 7 carries at most 7 kg
  click(QStringLiteral("payload.apply"));
  QCOMPARE(payload_message->kind(), QStringLiteral("error"));
  QVERIFY(find<QDoubleSpinBox>(QStringLiteral("payload.mass"))->property("invalid").toBool());
  setField(QStringLiteral("payload.mass"), 1);
  setField(QStringLiteral("payload.ixx"), 0.001);
  setField(QStringLiteral("payload.iyy"), 0.001);
  setField(QStringLiteral("payload.izz"), 0.005);  // violates Ixx + Iyy >= Izz
  click(QStringLiteral("payload.apply"));
  QVERIFY2(payload_message->text().contains(QStringLiteral("triangle")), qPrintable(payload_message->text()));
  setField(QStringLiteral("payload.izz"), 0.001);
  click(QStringLiteral("payload.apply"));
  waitDone(QStringLiteral("tool"), QStringLiteral("apply payload"));
  setField(QStringLiteral("payload.mass"), 0);
  click(QStringLiteral("payload.apply"));
  waitDone(QStringLiteral("tool"), QStringLiteral("apply payload"));

  setField(QStringLiteral("impedance.wrench3"), 80);  // Fz beyond 60 N
  click(QStringLiteral("impedance.wrench.apply"));
  QCOMPARE(find<MessageLine>(QStringLiteral("impedance.wrench.message"))->kind(), QStringLiteral("error"));
  QVERIFY(find<QDoubleSpinBox>(QStringLiteral("impedance.wrench3"))->property("invalid").toBool());
  setField(QStringLiteral("impedance.wrench3"), 10);
  click(QStringLiteral("impedance.wrench.apply"));
  waitDone(QStringLiteral("impedance"), QStringLiteral("apply desired wrench"));
  setField(QStringLiteral("impedance.joint5"), 400);  // J5 allows 300 Nm/rad
  click(QStringLiteral("impedance.joint.apply"));
  QVERIFY(find<QDoubleSpinBox>(QStringLiteral("impedance.joint5"))->property("invalid").toBool());
  setField(QStringLiteral("impedance.joint5"), 250);
  click(QStringLiteral("impedance.joint.apply"));
  waitDone(QStringLiteral("impedance"), QStringLiteral("apply joint stiffness"));
  click(QStringLiteral("impedance.cart.apply"));
  waitDone(QStringLiteral("impedance"), QStringLiteral("apply Cartesian stiffness"));
}

void TestPanels::toolFrameFromAngles() {
  const auto m = toolFrameFromXyzRpy({0.01, 0.02, 0.03, 0, 0, 90});
  const std::array<double, 16> expected{0, -1, 0, 0.01, 1, 0, 0, 0.02, 0, 0, 1, 0.03, 0, 0, 0, 1};
  for (int i = 0; i < 16; ++i) QVERIFY2(std::abs(m[i] - expected[i]) < 1e-12, qPrintable(QString::number(i)));
  const auto n = toolFrameFromXyzRpy({0, 0, 0, 90, 0, 90});
  // R = Rz(90) Rx(90): tool x -> base y, tool y -> base z, tool z -> base x.
  QVERIFY(std::abs(n[4 * 1 + 0] - 1) < 1e-12);
  QVERIFY(std::abs(n[4 * 2 + 1] - 1) < 1e-12);
  QVERIFY(std::abs(n[4 * 0 + 2] - 1) < 1e-12);
}

void TestPanels::safetyBoxApplyRecords() {
  click(QStringLiteral("box.fromtcp"));
  const auto& pose = session_->live().state.toolTobase_pos_m;
  QCOMPARE(find<QDoubleSpinBox>(QStringLiteral("box.z"))->value(), std::round(pose[11] * 1000) / 1000);
  setField(QStringLiteral("box.sizex"), 7);  // over the 5 m maximum
  click(QStringLiteral("box.apply"));
  QCOMPARE(find<MessageLine>(QStringLiteral("box.message"))->kind(), QStringLiteral("error"));
  setField(QStringLiteral("box.sizex"), 2);
  setField(QStringLiteral("box.sizey"), 2);
  setField(QStringLiteral("box.sizez"), 2);
  find<QCheckBox>(QStringLiteral("box.enable"))->setChecked(true);
  click(QStringLiteral("box.apply"));
  waitDone(QStringLiteral("box"), QStringLiteral("enable box"));
  const SafetyBox& box = session_->operatorSettings().box;
  QVERIFY(box.enabled);
  QCOMPARE(box.size[0], 2.0);
  QCOMPARE(box.frame[11], find<QDoubleSpinBox>(QStringLiteral("box.z"))->value());
}

void TestPanels::collisionShowsInSafetyPanelAndRecovers() {
  QVERIFY(lampOn(QStringLiteral("power.lamp")));
  QVERIFY(!lampOn(QStringLiteral("safety.bit15")));
  // Holding with the motors on is position control: a hard push trips the collision detection.
  setField(QStringLiteral("sim.fx"), 250);
  click(QStringLiteral("sim.wrench.apply"));
  QTRY_VERIFY_WITH_TIMEOUT(lampOn(QStringLiteral("safety.bit15")), kWaitMs);
  const QString details = find<QLabel>(QStringLiteral("safety.details"))->text();
  QVERIFY2(details.contains(QStringLiteral("Collision detected")), qPrintable(details));
  QVERIFY2(details.contains(QStringLiteral("What to do")), qPrintable(details));
  QVERIFY2(!details.contains(QStringLiteral("kCollision")), qPrintable(details));  // the enum only in a tooltip
  QVERIFY2(details.contains(QStringLiteral("raise the thresholds")), qPrintable(details));
  QTRY_VERIFY_WITH_TIMEOUT(!lampOn(QStringLiteral("power.lamp")), kWaitMs);  // motors off after a collision

  click(QStringLiteral("sim.wrench.release"));
  click(QStringLiteral("safety.recover"));
  waitDone(QStringLiteral("safety"), QStringLiteral("recover errors"));
  QTRY_VERIFY_WITH_TIMEOUT(!lampOn(QStringLiteral("safety.bit15")), kWaitMs);
  QTRY_COMPARE_WITH_TIMEOUT(find<QLabel>(QStringLiteral("safety.details"))->text(), QStringLiteral("No errors."),
                            kWaitMs);
  powerOn();
}

void TestPanels::dragTogglesGuiding() {
  auto* space = find<QComboBox>(QStringLiteral("drag.space"));
  auto* type = find<QComboBox>(QStringLiteral("drag.type"));
  space->setCurrentIndex(space->findData(1));
  QCOMPARE(type->currentData().toInt(), 3);  // joint space is always free
  QVERIFY(!type->isEnabled());
  space->setCurrentIndex(space->findData(2));
  type->setCurrentIndex(type->findData(1));
  click(QStringLiteral("drag.start"));
  waitDone(QStringLiteral("drag"), QStringLiteral("start guiding"));
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().state.robot_mode == RCI::robot::RobotMode::kGuiding, kWaitMs);
  QTRY_VERIFY_WITH_TIMEOUT(lampOn(QStringLiteral("drag.lamp")), kWaitMs);
  click(QStringLiteral("drag.stop"));
  waitDone(QStringLiteral("drag"), QStringLiteral("stop guiding"));
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().state.robot_mode == RCI::robot::RobotMode::kIdle, kWaitMs);
  QTRY_VERIFY_WITH_TIMEOUT(!lampOn(QStringLiteral("drag.lamp")), kWaitMs);
}

void TestPanels::jogMovesJoint() {
  waitMotionEnd();
  const double q0 = session_->live().state.q[0];
  auto* plus = find<QPushButton>(QStringLiteral("jog.joint1.plus"));
  QString failure;
  QVERIFY2(holdJog(plus, [&] { return session_->live().state.q[0] > q0 + 0.02; }, &failure), qPrintable(failure));
  waitMotionEnd();
  const auto& state = session_->live().state;
  QVERIFY(state.q[0] > q0 + 0.02);
  for (int i = 1; i < 7; ++i) QVERIFY(std::abs(state.dq_m[i]) < 1e-2);
  QVERIFY(!lampOn(QStringLiteral("safety.bit10")));
}

void TestPanels::jogMovesTcp() {
  waitMotionEnd();
  const double z0 = session_->live().state.toolTobase_pos_m[11];
  auto* down = find<QPushButton>(QStringLiteral("jog.cart.z.minus"));
  QString failure;
  QVERIFY2(holdJog(down, [&] { return session_->live().state.toolTobase_pos_m[11] < z0 - 0.01; }, &failure),
           qPrintable(failure));
}

void TestPanels::stopsShowInSafetyPanel() {
  waitMotionEnd();
  click(QStringLiteral("sim.gstop"));
  QTRY_VERIFY_WITH_TIMEOUT(lampOn(QStringLiteral("safety.gstop")), kWaitMs);
  QVERIFY(lampOn(QStringLiteral("power.lamp")));  // a guard stop keeps the motors on
  click(QStringLiteral("sim.gstop"));
  QTRY_VERIFY_WITH_TIMEOUT(!lampOn(QStringLiteral("safety.gstop")), kWaitMs);

  click(QStringLiteral("sim.estop"));
  QTRY_VERIFY_WITH_TIMEOUT(lampOn(QStringLiteral("safety.estop")), kWaitMs);
  QTRY_VERIFY_WITH_TIMEOUT(!lampOn(QStringLiteral("power.lamp")), kWaitMs);
  click(QStringLiteral("power.on"));  // refused while the e-stop is pressed: the panel says why
  QTRY_VERIFY_WITH_TIMEOUT(statusText(QStringLiteral("power")).contains(QStringLiteral("failed")), kWaitMs);
  QCOMPARE(find<MessageLine>(QStringLiteral("power.status"))->kind(), QStringLiteral("error"));
  click(QStringLiteral("sim.estop"));
  QTRY_VERIFY_WITH_TIMEOUT(!lampOn(QStringLiteral("safety.estop")), kWaitMs);
  powerOn();
}

void TestPanels::sixAxisModelHidesSeventhJoint() {
  SessionTarget target;
  target.type = xmate::XMATE7;
  target.lockstep = true;
  session_->open(target);
  QTRY_VERIFY_WITH_TIMEOUT(session_->isOpen(), kWaitMs);
  QVERIFY(!find<QDoubleSpinBox>(QStringLiteral("collision.threshold7"))->isVisible());
  QVERIFY(find<QDoubleSpinBox>(QStringLiteral("collision.threshold6"))->isVisible());
  QVERIFY(!find<QPushButton>(QStringLiteral("jog.joint7.plus"))->isVisible());
  // The 6-axis maxima apply: J4 of the xMate7 allows 30 Nm.
  setField(QStringLiteral("collision.threshold4"), 40);
  click(QStringLiteral("collision.apply"));
  QVERIFY2(find<QLabel>(QStringLiteral("collision.message"))->text().contains(QStringLiteral("J4 threshold = 40")),
           qPrintable(find<QLabel>(QStringLiteral("collision.message"))->text()));
  session_->close();
}

void TestPanels::simulatorPanelDisabledWithoutSimulator() {
  auto* apply = find<QPushButton>(QStringLiteral("sim.wrench.apply"));
  QVERIFY(apply->isEnabled());
  session_->close();
  QTRY_VERIFY_WITH_TIMEOUT(!apply->isEnabled(), kWaitMs);
  QVERIFY(!find<QPushButton>(QStringLiteral("power.on"))->isEnabled());
}

QTEST_MAIN(TestPanels)
#include "test_panels.moc"
