// SPDX-License-Identifier: Apache-2.0
// Tests of rci::ui::Session against the embedded lock-step simulator: open, ticks and samples,
// commands, IO loop-back, motions, stop, close, watchdog and a refused connection.
#include <QSignalSpy>
#include <QTest>

#include <algorithm>

#include "arm/arm.h"
#include "gui_test_support.h"
#include "session/session.h"

using rci::ui::Session;
using rci::ui::SessionTarget;
using rci::ui::test::lockstepSimulator;
using rci::ui::test::unusedPort;

namespace {

// Holds the joints still until the session asks to stop (or ~60 s of cycles pass), then finishes.
class HoldUntilStopped : public xmate::arm::JointMotion {
 public:
  HoldUntilStopped(const rci::ui::MotionToken& token, int* cycles) : token_(token), cycles_(cycles) {}
  bool command(const xmate::arm::ArmSample& now, std::array<double, 7>& q) override {
    if (first_) hold_ = now.q_command, first_ = false;
    ++*cycles_;
    q = hold_;
    return token_.stopRequested() || *cycles_ > 60000;
  }

 private:
  const rci::ui::MotionToken& token_;
  int* cycles_;
  bool first_ = true;
  std::array<double, 7> hold_{};
};

void holdUntilStopped(const rci::ui::MotionToken& token, xmate::arm::Arm& arm, int* cycles) {
  HoldUntilStopped motion(token, cycles);
  arm.runJointMotion(motion);
}

// Joint 1 by +0.05 rad in 1 s along a quintic (minimum-jerk) profile.
class NudgeJointOne : public xmate::arm::JointMotion {
 public:
  bool command(const xmate::arm::ArmSample& now, std::array<double, 7>& q) override {
    if (first_) start_ = now.q_command, first_cycle_ = now.cycle, first_ = false;
    const double t = std::min(1.0, double(now.cycle - first_cycle_) * 1e-3);
    q = start_;
    q[0] += 0.05 * t * t * t * (10 - 15 * t + 6 * t * t);
    return t >= 1.0;
  }

 private:
  bool first_ = true;
  uint64_t first_cycle_ = 0;
  std::array<double, 7> start_{};
};

}  // namespace

class TestSession : public QObject {
  Q_OBJECT

 private slots:
  void init();
  void cleanup();
  void opensAndTicks();
  void runsCommands();
  void failingCommandReportsMessage();
  void ioLoopback();
  void runsMotion();
  void refusesSecondMotion();
  void requestStopEndsMotion();
  void closesCleanly();
  void reportsControllerSilence();
  void reconnectsAfterReboot();
  void refusedConnectionFailsClearly();
  void namesModels();

 private:
  void openSimulator();
  void powerOn();
  std::unique_ptr<Session> session_;
};

void TestSession::init() { session_ = std::make_unique<Session>(); }
void TestSession::cleanup() { session_.reset(); }

void TestSession::openSimulator() {
  QSignalSpy opened(session_.get(), &Session::opened);
  QSignalSpy failed(session_.get(), &Session::openFailed);
  session_->open(lockstepSimulator());
  QVERIFY(session_->isOpening());
  QTRY_VERIFY_WITH_TIMEOUT(opened.count() + failed.count() > 0, 20000);
  QVERIFY2(failed.isEmpty(), failed.isEmpty() ? "" : qPrintable(failed.first().first().toString()));
  QVERIFY(session_->isOpen());
  QVERIFY(session_->simulator() != nullptr);
  QVERIFY(session_->robot() != nullptr);
}

void TestSession::powerOn() {
  QSignalSpy finished(session_.get(), &Session::commandFinished);
  session_->run("power on", [](xmate::Robot& robot) { robot.setMotorPower(1); });
  QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 1, 20000);
  QVERIFY2(finished.first().at(1).toBool(), qPrintable(finished.first().at(2).toString()));
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().motor_state == 1, 20000);
}

void TestSession::opensAndTicks() {
  openSimulator();
  QSignalSpy ticks(session_.get(), &Session::tick);
  int samples = 0;
  connect(session_.get(), &Session::samplesArrived, this,
          [&](const xmate::client::StateSample*, int count) { samples += count; });
  QTRY_VERIFY_WITH_TIMEOUT(ticks.count() >= 3 && samples > 0, 20000);
  const rci::ui::LiveState& live = session_->live();
  QVERIFY(live.connected);
  QVERIFY(live.has_state);
  QVERIFY(live.simulated);
  QCOMPARE(live.dof, 7);
  QVERIFY(live.state.message_id > 0);
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().loop_rate_hz > 0, 20000);
  QCOMPARE(session_->target().describe(), QString("Simulator (xMate7 Pro)"));
}

void TestSession::runsCommands() {
  openSimulator();
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().has_state, 20000);
  QCOMPARE(session_->live().motor_state, 0);
  powerOn();
  QVERIFY(session_->live().sim.motors_on);
}

void TestSession::failingCommandReportsMessage() {
  openSimulator();
  QSignalSpy finished(session_.get(), &Session::commandFinished);
  session_->run("thresholds", [](xmate::Robot& robot) { robot.setCollisionBehavior({1e9, 1, 1, 1, 1, 1, 1}); });
  QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 1, 20000);
  QCOMPARE(finished.first().at(0).toString(), QString("thresholds"));
  QCOMPARE(finished.first().at(1).toBool(), false);
  QVERIFY(!finished.first().at(2).toString().isEmpty());
}

void TestSession::ioLoopback() {
  openSimulator();
  QSignalSpy finished(session_.get(), &Session::commandFinished);
  session_->run("DO1_0 on", [](xmate::Robot& robot) { robot.setDO(RCI::robot::DOSIGNAL::DO1_0, true); });
  QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 1, 20000);
  QVERIFY(finished.first().at(1).toBool());
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().digital_in[4], 20000);
  QVERIFY(session_->live().digital_out[4]);
  QVERIFY(!session_->live().digital_in[0]);
}

void TestSession::runsMotion() {
  openSimulator();
  powerOn();
  QSignalSpy started(session_.get(), &Session::motionStarted);
  QSignalSpy finished(session_.get(), &Session::motionFinished);
  session_->runArmMotion("MOVEJ", [](xmate::arm::Arm& arm, const rci::ui::MotionToken&) {
    NudgeJointOne motion;
    arm.runJointMotion(motion);
  });
  QCOMPARE(started.count(), 1);
  QVERIFY(session_->live().motion_running);
  QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 1, 30000);
  QVERIFY2(finished.first().at(1).toBool(), qPrintable(finished.first().at(2).toString()));
  QTRY_VERIFY_WITH_TIMEOUT(!session_->live().motion_running, 5000);
  QTRY_VERIFY_WITH_TIMEOUT(std::abs(session_->live().state.q[0] - 0.05) < 1e-3, 10000);
}

void TestSession::refusesSecondMotion() {
  openSimulator();
  powerOn();
  int cycles = 0;
  QSignalSpy commands(session_.get(), &Session::commandFinished);
  QSignalSpy finished(session_.get(), &Session::motionFinished);
  session_->runArmMotion("hold", [&](xmate::arm::Arm& arm, const rci::ui::MotionToken& token) { holdUntilStopped(token, arm, &cycles); });
  session_->runArmMotion("second", [](xmate::arm::Arm&, const rci::ui::MotionToken&) {});
  QCOMPARE(commands.count(), 1);
  QCOMPARE(commands.first().at(0).toString(), QString("second"));
  QVERIFY(commands.first().at(2).toString().contains("already running"));
  session_->requestStop();
  QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 1, 30000);
}

void TestSession::requestStopEndsMotion() {
  openSimulator();
  powerOn();
  int cycles = 0;
  QSignalSpy finished(session_.get(), &Session::motionFinished);
  session_->runArmMotion("hold", [&](xmate::arm::Arm& arm, const rci::ui::MotionToken& token) { holdUntilStopped(token, arm, &cycles); });
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().sim.motion_active, 20000);
  QVERIFY(!session_->stopRequested());
  session_->requestStop();
  QVERIFY(session_->stopRequested());
  QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 1, 30000);
  QVERIFY2(finished.first().at(1).toBool(), qPrintable(finished.first().at(2).toString()));
  QVERIFY(cycles < 60000);
  QVERIFY(!session_->stopRequested());
}

void TestSession::closesCleanly() {
  openSimulator();
  powerOn();
  int cycles = 0;
  session_->runArmMotion("hold", [&](xmate::arm::Arm& arm, const rci::ui::MotionToken& token) { holdUntilStopped(token, arm, &cycles); });
  QSignalSpy closed(session_.get(), &Session::closed);
  QSignalSpy ticks(session_.get(), &Session::tick);
  session_->close();
  QCOMPARE(closed.count(), 1);
  QCOMPARE(closed.first().first().toString(), QString());
  QVERIFY(!session_->isOpen());
  QVERIFY(session_->robot() == nullptr);
  QVERIFY(!session_->live().connected);
  QTest::qWait(200);
  QCOMPARE(ticks.count(), 0);
  session_->close();  // twice is harmless
  QCOMPARE(closed.count(), 1);
  openSimulator();  // and it opens again
  session_.reset();  // the destructor waits for the teardown
}

void TestSession::reportsControllerSilence() {
  openSimulator();
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().has_state, 20000);
  QSignalSpy closed(session_.get(), &Session::closed);
  QSignalSpy reconnecting(session_.get(), &Session::reconnecting);
  session_->simulator()->kill();  // dead for good: the reconnect gives up at once
  QTRY_VERIFY_WITH_TIMEOUT(closed.count() == 1, 20000);
  QCOMPARE(reconnecting.count(), 1);
  QVERIFY(closed.first().first().toString().contains("stopped"));
  QVERIFY(!session_->isOpen());
  QVERIFY(!session_->isReconnecting());
}

void TestSession::reconnectsAfterReboot() {
  openSimulator();
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().has_state, 20000);
  QSignalSpy reconnected(session_.get(), &Session::reconnected);
  QSignalSpy closed(session_.get(), &Session::closed);
  session_->run("reboot", [](xmate::Robot& robot) { robot.rebootRobot(); });
  QTRY_VERIFY_WITH_TIMEOUT(session_->isReconnecting(), 20000);
  QTRY_VERIFY_WITH_TIMEOUT(reconnected.count() == 1 || closed.count() == 1, 30000);
  QCOMPARE(closed.count(), 0);
  QVERIFY(session_->isOpen());
  QVERIFY(!session_->isReconnecting());
  const uint64_t id = session_->live().state.message_id;
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().state.message_id != id, 20000);  // states flow again
  powerOn();  // and commands work on the new session
}

void TestSession::refusedConnectionFailsClearly() {
  SessionTarget target;
  target.kind = SessionTarget::Kind::kRobot;
  target.host = "127.0.0.1";
  target.port = unusedPort();
  QSignalSpy failed(session_.get(), &Session::openFailed);
  QSignalSpy opened(session_.get(), &Session::opened);
  session_->open(target);
  QTRY_VERIFY_WITH_TIMEOUT(failed.count() == 1, 20000);
  QCOMPARE(opened.count(), 0);
  const QString reason = failed.first().first().toString();
  QVERIFY2(reason.contains(QString("127.0.0.1:%1").arg(target.port)), qPrintable(reason));
  QVERIFY2(reason.contains("check", Qt::CaseInsensitive), qPrintable(reason));
  QVERIFY(!session_->isOpen());
  QVERIFY(!session_->isOpening());
  QSignalSpy finished(session_.get(), &Session::commandFinished);
  session_->run("power on", [](xmate::Robot& robot) { robot.setMotorPower(1); });
  QCOMPARE(finished.count(), 1);
  QVERIFY(!finished.first().at(1).toBool());
}

void TestSession::namesModels() {
  xmate::XmateType type = xmate::XMATE7_PRO;
  QVERIFY(rci::ui::parseModel("xmate3_pro", type));
  QCOMPARE(type, xmate::XMATE3_PRO);
  QVERIFY(rci::ui::parseModel(" XMATE7 ", type));
  QCOMPARE(type, xmate::XMATE7);
  QVERIFY(!rci::ui::parseModel("ur5", type));
  QCOMPARE(rci::ui::modelName(xmate::XMATE3), QString("xMate3"));
  SessionTarget robot;
  robot.kind = SessionTarget::Kind::kRobot;
  QCOMPARE(robot.describe(), QString("Robot 192.168.0.160:1337 (xMate7 Pro)"));
}

QTEST_MAIN(TestSession)
#include "test_session.moc"
