// SPDX-License-Identifier: Apache-2.0
// Tests of rci::ui::Session on the built-in KUKA simulator: open, samples and live state, IO through
// the arm, a streamed motion and its stop, an RSI timeout and the restart, and the same session
// switching to the xMate simulator and back.
#include <QSignalSpy>
#include <QTest>

#include <atomic>
#include <cmath>

#include "arm/rsi_arm.h"
#include "gui_test_support.h"
#include "session/session.h"
#include "sim/krc_server.h"

using rci::ui::Session;
using rci::ui::SessionTarget;
using rci::ui::test::kukaSimulator;
using rci::ui::test::lockstepSimulator;

namespace {

// Moves axis 1 by `delta` rad (a smooth ramp over `cycles`), or holds until the token stops it.
class RampA1 : public xmate::arm::JointMotion {
 public:
  RampA1(double delta, int cycles, const rci::ui::MotionToken& token) : delta_(delta), cycles_(cycles), token_(token) {}
  bool command(const xmate::arm::ArmSample& now, std::array<double, 7>& q) override {
    if (n_ == 0) start_ = now.q;
    ++n_;
    const double s = std::min(1.0, double(n_) / cycles_);
    q = start_;
    q[0] = start_[0] + delta_ * (0.5 - 0.5 * std::cos(M_PI * s));
    return token_.stopRequested() || n_ >= cycles_;
  }
  int cycles() const { return n_; }

 private:
  double delta_;
  int cycles_;
  const rci::ui::MotionToken& token_;
  std::array<double, 7> start_{};
  int n_ = 0;
};

}  // namespace

class TestKukaSession : public QObject {
  Q_OBJECT

 private slots:
  void init() { session_ = std::make_unique<Session>(); }
  void cleanup() { session_.reset(); }
  void opensAndFillsLiveState();
  void setsOutputsThroughTheArm();
  void runsAndStopsArmMotion();
  void refusesXmateCommands();
  void reportsTimeoutAndRestart();
  void switchesFamiliesInOneSession();
  void badTargetsFailClearly();

 private:
  void openKuka();
  std::unique_ptr<Session> session_;
};

void TestKukaSession::openKuka() {
  QSignalSpy opened(session_.get(), &Session::opened);
  QSignalSpy failed(session_.get(), &Session::openFailed);
  session_->open(kukaSimulator());
  QTRY_VERIFY_WITH_TIMEOUT(opened.count() == 1 || failed.count() == 1, 15000);
  QVERIFY2(failed.isEmpty(), failed.isEmpty() ? "" : qPrintable(failed.first().first().toString()));
  QVERIFY(session_->rsiArm() != nullptr);
  QVERIFY(session_->kukaSimulator() != nullptr);
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().rsi.phase == xmate::rsi::SessionPhase::kRunning, 15000);
}

void TestKukaSession::opensAndFillsLiveState() {
  QSignalSpy samples(session_.get(), &Session::armSamplesArrived);
  QSignalSpy xmate_samples(session_.get(), &Session::samplesArrived);
  openKuka();
  QCOMPARE(session_->spec().name, std::string_view("kr6_r900_sixx"));
  QCOMPARE(session_->live().dof, 6);
  QVERIFY(session_->robot() == nullptr && session_->simulator() == nullptr);
  QVERIFY(xmate::arm::has(session_->live().capabilities, xmate::arm::Capability::kCorrectionLimits));
  QVERIFY(!xmate::arm::has(session_->live().capabilities, xmate::arm::Capability::kPowerControl));
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().has_arm_state, 5000);
  QTRY_VERIFY_WITH_TIMEOUT(samples.count() > 3, 5000);
  QVERIFY(xmate_samples.isEmpty());  // a KUKA has no xMate state samples
  QCOMPARE(session_->live().rsi.cycle_ms, 4);
  // The simulated sensor reads the arm's external wrench.
  QVERIFY(session_->live().has_force_sensor);
  session_->kukaSimulator()->krc().setExternalWrench({0, 0, -30, 0, 0, 0});
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().force_reading &&
                               std::hypot(session_->live().force[0], session_->live().force[1], session_->live().force[2]) > 20,
                           5000);
  QVERIFY(session_->target().describe().contains(QStringLiteral("KUKA simulator")));
}

void TestKukaSession::setsOutputsThroughTheArm() {
  openKuka();
  const std::vector<std::string> outputs = session_->arm()->outputNames();
  QVERIFY(!outputs.empty());
  QCOMPARE(QString::fromStdString(outputs.front()), QStringLiteral("$OUT[1]"));
  QSignalSpy finished(session_.get(), &Session::commandFinished);
  session_->runOnArm(QStringLiteral("IO: $OUT[1] on"), [](xmate::arm::Arm& arm) { arm.setOutput(0, true); });
  QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 5000);
  QVERIFY2(finished.first().at(1).toBool(), qPrintable(finished.first().at(2).toString()));
  QTRY_VERIFY_WITH_TIMEOUT((session_->live().outputs & 1u) != 0, 5000);
  // An input the simulator sets is polled.
  session_->kukaSimulator()->krc().setDigitalInput(2, true);
  QTRY_VERIFY_WITH_TIMEOUT((session_->live().inputs & 2u) != 0, 5000);
  // An output the context does not wire fails saying so.
  session_->runOnArm(QStringLiteral("IO: output 40"), [](xmate::arm::Arm& arm) { arm.setOutput(40, true); });
  QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 2, 5000);
  QVERIFY(!finished.last().at(1).toBool());
  QVERIFY(finished.last().at(2).toString().contains(QStringLiteral("wires")));
}

void TestKukaSession::runsAndStopsArmMotion() {
  openKuka();
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().has_arm_state, 5000);
  const double a1 = session_->live().arm.sample.q[0];
  QSignalSpy done(session_.get(), &Session::motionFinished);
  session_->runArmMotion(QStringLiteral("move A1"), [](xmate::arm::Arm& arm, const rci::ui::MotionToken& token) {
    RampA1 motion(0.05, 250, token);  // 2.9 deg in 1 s
    arm.runJointMotion(motion);
  });
  QTRY_COMPARE_WITH_TIMEOUT(done.count(), 1, 15000);
  QVERIFY2(done.first().at(1).toBool(), qPrintable(done.first().at(2).toString()));
  QTRY_VERIFY_WITH_TIMEOUT(std::abs(session_->live().arm.sample.q[0] - (a1 + 0.05)) < 2e-3, 5000);

  // A motion that would hold for minutes ends at requestStop().
  session_->runArmMotion(QStringLiteral("hold"), [](xmate::arm::Arm& arm, const rci::ui::MotionToken& token) {
    RampA1 motion(0, 1000000, token);
    arm.runJointMotion(motion);
  });
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().motion_running, 5000);
  session_->requestStop();
  QTRY_COMPARE_WITH_TIMEOUT(done.count(), 2, 10000);
  QVERIFY(done.last().at(1).toBool());
}

void TestKukaSession::refusesXmateCommands() {
  openKuka();
  QSignalSpy finished(session_.get(), &Session::commandFinished);
  session_->run(QStringLiteral("Power: on"), [](xmate::Robot& robot) { robot.setMotorPower(1); });
  QCOMPARE(finished.count(), 1);
  QVERIFY(!finished.first().at(1).toBool());
  QVERIFY(finished.first().at(2).toString().contains(QStringLiteral("xMate only")));
}

void TestKukaSession::reportsTimeoutAndRestart() {
  openKuka();
  const uint32_t first = session_->live().rsi.session;
  // The PC's answers are lost: the robot counts them late up to the context's Timeout and stops RSI.
  session_->kukaSimulator()->krc().dropAnswers(1000);
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().rsi.phase == xmate::rsi::SessionPhase::kStopped, 15000);
  QCOMPARE(session_->live().rsi.cause, xmate::rsi::StopCause::kTimeout);
  QVERIFY(QString::fromStdString(xmate::rsi::describe(session_->live().rsi)).contains(QStringLiteral("late")));
  QVERIFY(session_->isOpen());  // the window stays connected and waits for RSI to start again
  session_->kukaSimulator()->krc().dropAnswers(0);
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().rsi.phase == xmate::rsi::SessionPhase::kRunning &&
                               session_->live().rsi.session > first,
                           20000);
}

void TestKukaSession::switchesFamiliesInOneSession() {
  openKuka();
  QSignalSpy opened(session_.get(), &Session::opened);
  session_->open(lockstepSimulator());
  QTRY_COMPARE_WITH_TIMEOUT(opened.count(), 1, 15000);
  QVERIFY(session_->robot() != nullptr);
  QVERIFY(session_->rsiArm() == nullptr && session_->kukaSimulator() == nullptr);
  QCOMPARE(session_->spec().family, xmate::model::RobotFamily::kXmate);
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().has_state && session_->live().has_arm_state, 10000);
  QVERIFY(xmate::arm::has(session_->live().capabilities, xmate::arm::Capability::kPowerControl));
  session_->open(kukaSimulator());
  QTRY_COMPARE_WITH_TIMEOUT(opened.count(), 2, 15000);
  QCOMPARE(session_->spec().family, xmate::model::RobotFamily::kKuka);
  QVERIFY(!session_->live().has_state);
}

void TestKukaSession::badTargetsFailClearly() {
  QSignalSpy failed(session_.get(), &Session::openFailed);
  SessionTarget unknown = kukaSimulator();
  unknown.kuka_model = QStringLiteral("kr1000_titan");
  session_->open(unknown);
  QCOMPARE(failed.count(), 1);
  QVERIFY(failed.last().first().toString().contains(QStringLiteral("kr6_r900_sixx")));

  SessionTarget missing;
  missing.kind = SessionTarget::Kind::kKukaRobot;
  missing.rsi_config = QStringLiteral("/nonexistent/RSI_EthernetConfig.xml");
  session_->open(missing);
  QTRY_COMPARE_WITH_TIMEOUT(failed.count(), 2, 10000);
  const QString reason = failed.last().first().toString();
  QVERIFY2(reason.contains(QStringLiteral("RSI_EthernetConfig.xml")), qPrintable(reason));
  QVERIFY(!session_->isOpen());
}

QTEST_MAIN(TestKukaSession)
#include "test_kuka_session.moc"
