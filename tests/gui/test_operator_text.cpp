// SPDX-License-Identifier: Apache-2.0
// test_operator_text: the window's words (ui/text/operator_text.h) -- every error bit has a plain
// title, what happened and what to do without programmer words; joints beyond their limits and the
// TCP outside the safety box are described with numbers and the way back; the library's and the
// controller's refusals and failures become plain text with what to press, the raw message kept as
// the detail. No robot needed.
#include <QRegularExpression>
#include <QTest>

#include <stdexcept>

#include <xmate/exception.h>

#include "client/error_bits.h"
#include "model/robot_spec.h"
#include "session/session.h"
#include "text/operator_text.h"

using namespace rci::ui;
using namespace rci::ui::text;
using RCI::robot::RobotMode;

namespace {

constexpr double kRadPerDeg = 0.017453292519943295;

// What the operator reads must not contain a C++ enum, an API call or a document they do not have.
QString programmerWordsIn(const QString& plain) {
  static const QRegularExpression enum_name(QStringLiteral(R"(\bk[A-Z][A-Za-z]+)"));
  if (const auto m = enum_name.match(plain); m.hasMatch()) return m.captured();
  for (const char* word : {"()", "setMotorPower", "automaticErrorRecovery", "SPEC", "startDrag", "stopDrag",
                           "startMove", "setFilters", "setCollisionBehavior", "setLoad", "Control(", ".md",
                           "RobotState", "getSafetyStopState", "reconnect()"})
    if (plain.contains(QLatin1String(word))) return QLatin1String(word);
  return {};
}

QString plainOf(const OperatorMessage& m) { return m.title + QLatin1Char(' ') + m.what + QLatin1Char(' ') + m.todo; }

// A live state of an xMate Pro 7 at rest, motors on, nothing wrong.
LiveState restingState() {
  LiveState live;
  live.connected = true;
  live.has_state = true;
  live.dof = 7;
  live.motor_state = 1;
  live.safety_stop = 1;
  live.state.robot_mode = RobotMode::kIdle;
  live.state.q = {0, 0.5, 0, 1.0, 0, 1.0, 0};
  live.state.toolTobase_pos_m = {1, 0, 0, 0.5, 0, 1, 0, 0, 0, 0, 1, 0.5, 0, 0, 0, 1};
  return live;
}

}  // namespace

class TestOperatorText : public QObject {
  Q_OBJECT

 private slots:
  void everyErrorBitHasPlainText();
  void robotModesAndStopsArePlain();
  void jointBeyondUpperLimit();
  void jointBeyondSoftLowerLimit();
  void jointLimitBitCarriesTheJoint();
  void tcpOutsideTheBox();
  void activeProblemsPutStopsAndCollisionFirst();
  void refusalsTranslate_data();
  void refusalsTranslate();
  void refusalsExplainedFromLiveState();
  void controlFailureNamesTheBits();
  void programFailureKeepsTheInstruction();
  void exceptionTypesTranslate();
  void unknownFailureKeepsTheRawMessage();
  void refusedValuesNameTheField();
  void programProblemsWithoutSolverCodes();
  void connectFailureNamesTheTarget();
};

void TestOperatorText::everyErrorBitHasPlainText() {
  QSet<QString> titles;
  for (int bit = 0; bit < kErrorBitCount; ++bit) {
    const OperatorMessage m = errorBit(bit);
    QVERIFY2(!m.title.isEmpty() && !m.what.isEmpty() && !m.todo.isEmpty(), qPrintable(QString::number(bit)));
    QVERIFY2(programmerWordsIn(plainOf(m)).isEmpty(),
             qPrintable(QStringLiteral("bit %1: '%2' in: %3").arg(bit).arg(programmerWordsIn(plainOf(m)), plainOf(m))));
    QCOMPARE(m.detail, QString::fromLatin1(xmate::client::errorBitName(bit)));
    QCOMPARE(errorBitTitle(bit), m.title);
    QVERIFY2(!titles.contains(m.title), qPrintable(m.title));
    titles.insert(m.title);
    QVERIFY2(m.todo.contains(QLatin1String("Safety panel")) || m.todo.contains(QLatin1String("Jog")),
             qPrintable(m.todo));  // every bit says what to press in the window
  }
  QCOMPARE(errorBitTitle(15), QStringLiteral("Collision detected"));
  QVERIFY(errorBit(15).todo.contains(QLatin1String("Collision panel")));
  QVERIFY(errorBit(15).todo.contains(QLatin1String("Power on")));
  QVERIFY(errorBitTitle(19).contains(QLatin1String("Commands lost")));
  QVERIFY(errorBit(10).todo.contains(QLatin1String("speed")));
}

void TestOperatorText::robotModesAndStopsArePlain() {
  QCOMPARE(robotMode(RobotMode::kIdle), QStringLiteral("Idle"));
  QCOMPARE(robotMode(RobotMode::kGuiding), QStringLiteral("Hand guiding"));
  QCOMPARE(robotMode(RobotMode::kReflex), QStringLiteral("Stopped by an error"));
  QCOMPARE(robotMode(RobotMode::kAutomaticErrorRecovery), QStringLiteral("Recovering"));
  for (RobotMode mode : {RobotMode::kOther, RobotMode::kIdle, RobotMode::kMove, RobotMode::kGuiding,
                         RobotMode::kReflex, RobotMode::kUserStopped, RobotMode::kAutomaticErrorRecovery})
    QVERIFY2(programmerWordsIn(robotMode(mode)).isEmpty(), qPrintable(robotMode(mode)));
  QCOMPARE(safetyStop(2), QStringLiteral("Emergency stop pressed"));
  QCOMPARE(safetyStop(3), QStringLiteral("Guard stop active"));
}

void TestOperatorText::jointBeyondUpperLimit() {
  const auto& spec = xmate::model::robotSpec(xmate::XMATE7_PRO);
  std::array<double, 7> q{};
  q[5] = 120.7 * kRadPerDeg;  // J6 goes to 120 deg
  const auto beyond = jointsBeyondLimits(q, 7, nullptr, spec);
  QCOMPARE(int(beyond.size()), 1);
  QCOMPARE(beyond[0].joint, 5);
  QCOMPARE(describe(beyond[0]), QStringLiteral("J6 reached its upper limit (120.7° > 120.0°)"));
  QCOMPARE(remedy(beyond[0]), QStringLiteral("J6 is 0.7° beyond its upper limit: Jog J6 \u2212 or guide it back "
                                             "towards the range"));
  q[5] = 119.0 * kRadPerDeg;  // within: nothing
  QVERIFY(jointsBeyondLimits(q, 7, nullptr, spec).empty());
}

void TestOperatorText::jointBeyondSoftLowerLimit() {
  const auto& spec = xmate::model::robotSpec(xmate::XMATE7_PRO);
  OperatorSettings settings;
  settings.soft_limits_enabled = true;
  for (size_t j = 0; j < 7; ++j) {
    settings.soft_lower_deg[j] = -90;
    settings.soft_upper_deg[j] = 90;
  }
  std::array<double, 7> q{};
  q[1] = -92.25 * kRadPerDeg;
  const auto beyond = jointsBeyondLimits(q, 7, &settings, spec);
  QCOMPARE(int(beyond.size()), 1);
  QCOMPARE(describe(beyond[0]), QStringLiteral("J2 reached its lower soft limit (-92.3° < -90.0°)"));
  QVERIFY2(remedy(beyond[0]).contains(QStringLiteral("2.3° beyond")), qPrintable(remedy(beyond[0])));
  QVERIFY2(remedy(beyond[0]).contains(QStringLiteral("Jog J2 +")), qPrintable(remedy(beyond[0])));
  // Soft limits off: the model's range applies, and -92° is inside it.
  settings.soft_limits_enabled = false;
  QVERIFY(jointsBeyondLimits(q, 7, &settings, spec).empty());
}

void TestOperatorText::jointLimitBitCarriesTheJoint() {
  LiveState live = restingState();
  live.state.q[5] = 120.7 * kRadPerDeg;
  live.state.errors[0] = true;
  live.state.robot_mode = RobotMode::kReflex;
  OperatorSettings settings;
  const RobotView view{&live, &settings, &xmate::model::robotSpec(xmate::XMATE7_PRO)};
  const OperatorMessage m = errorBit(0, view);
  QCOMPARE(m.title, QStringLiteral("Joint position limit reached"));
  QVERIFY2(m.what.contains(QStringLiteral("J6 reached its upper limit (120.7° > 120.0°)")), qPrintable(m.what));
  QVERIFY2(m.todo.contains(QStringLiteral("J6 is 0.7° beyond its upper limit: Jog J6 \u2212 or guide it back")),
           qPrintable(m.todo));
  QVERIFY2(m.todo.startsWith(QStringLiteral("Press Recover in the Safety panel, then bring it back.")), qPrintable(m.todo));

  // The same joint without the bit (after Recover) is still reported, without Recover.
  live.state.errors[0] = false;
  const auto problems = activeProblems(view);
  QCOMPARE(int(problems.size()), 1);
  QVERIFY2(problems[0].what.contains(QStringLiteral("J6 reached its upper limit")), qPrintable(problems[0].what));
  QVERIFY2(!problems[0].todo.contains(QStringLiteral("Recover")), qPrintable(problems[0].todo));
}

void TestOperatorText::tcpOutsideTheBox() {
  SafetyBox box;
  box.enabled = true;
  box.size = {0.4, 0.4, 0.4};
  box.frame = {1, 0, 0, 0.5, 0, 1, 0, 0, 0, 0, 1, 0.5, 0, 0, 0, 1};
  std::array<double, 16> tcp{1, 0, 0, 0.5 + 0.2 + 0.023, 0, 1, 0, 0.1, 0, 0, 1, 0.5, 0, 0, 0, 1};
  const auto out = tcpOutsideBox(tcp, box);
  QVERIFY(out.has_value());
  QVERIFY2(describe(*out).contains(QStringLiteral("23 mm outside the safety box")), qPrintable(describe(*out)));
  QVERIFY2(describe(*out).contains(QStringLiteral("+x side")), qPrintable(describe(*out)));
  QVERIFY2(remedy(*out).contains(QStringLiteral("TCP x \u2212")), qPrintable(remedy(*out)));
  tcp[3] = 0.6;
  QVERIFY(!tcpOutsideBox(tcp, box).has_value());
  tcp[11] = 0.5 - 0.25;  // 50 mm below the -z side
  const auto below = tcpOutsideBox(tcp, box);
  QVERIFY(below.has_value());
  QVERIFY2(remedy(*below).contains(QStringLiteral("TCP z +")), qPrintable(remedy(*below)));
  box.enabled = false;
  QVERIFY(!tcpOutsideBox(tcp, box).has_value());
}

void TestOperatorText::activeProblemsPutStopsAndCollisionFirst() {
  LiveState live = restingState();
  live.safety_stop = 2;
  live.state.errors[3] = true;
  live.state.errors[10] = true;
  live.state.errors[15] = true;
  OperatorSettings settings;
  const RobotView view{&live, &settings, &xmate::model::robotSpec(xmate::XMATE7_PRO)};
  const auto problems = activeProblems(view);
  QCOMPARE(int(problems.size()), 3);  // e-stop, collision, the two speed bits as one
  QCOMPARE(problems[0].title, QStringLiteral("Emergency stop pressed"));
  QCOMPARE(problems[1].title, QStringLiteral("Collision detected"));
  QVERIFY2(problems[2].title.contains(errorBitTitle(3)) && problems[2].title.contains(errorBitTitle(10)),
           qPrintable(problems[2].title));
  for (const auto& m : problems) QVERIFY2(programmerWordsIn(plainOf(m)).isEmpty(), qPrintable(plainOf(m)));
  QVERIFY(activeProblems(RobotView{}).empty());
}

void TestOperatorText::refusalsTranslate_data() {
  QTest::addColumn<QString>("raw");
  QTest::addColumn<QString>("expected");  // in the plain line
  QTest::newRow("not connected") << "not connected: connect to a robot or the simulator first" << "Not connected";
  QTest::newRow("busy") << "a motion is already running" << "Another motion is running";
  QTest::newRow("sim: guiding") << "startMove: hand guiding is active; call stopDrag first"
                                << "Press Stop guiding in the Drag panel";
  QTest::newRow("sim: motors off") << "startDrag: the motors are off; call setMotorPower(1) first"
                                   << "Press Power on in the Power panel";
  QTest::newRow("reflex") << "startMove: the controller refused: aborted by a reflex (error bits set); error bits are "
                             "set: call automaticErrorRecovery() first"
                          << "press Recover";
  QTest::newRow("e-stop") << "startMove: the controller refused: aborted by an emergency stop; release the emergency "
                             "stop, then automaticErrorRecovery()"
                          << "emergency stop is pressed";
  QTest::newRow("stopping") << "startMove: the robot is still stopping; try again shortly" << "coming to rest";
  QTest::newRow("client: stopping") << "startMove: the arm is still stopping (joint 2 at 0.12 rad/s); wait until it "
                                       "stands still, then try again"
                                    << "no longer says";
  QTest::newRow("client: guiding") << "startMove: the controller refused: not possible in the robot's current state; "
                                      "hand guiding is on: call stopDrag() first"
                                   << "Press Stop guiding in the Drag panel";
  QTest::newRow("client: no reason") << "startMove: the controller refused: not possible in the robot's current "
                                        "state; the controller gave no reason the client can see (robot mode kIdle, "
                                        "no error bits, no safety stop, motors on, the arm at rest)"
                                     << "refused without a reason";
  QTest::newRow("soft limit") << "MOVEJ: joint 3 would reach 125.00 deg, beyond its soft upper limit of 120.00 deg "
                                 "(setJointLimit) at the target; choose a target (and for MOVEL/MOVEC a path) within "
                                 "the limits, or change the limits"
                              << "J3 would reach 125.00° at the target, beyond its upper limit of 120.00°";
  QTest::newRow("box") << "MOVEL: the TCP would leave the safety box through its +x face (0.100 m from the box "
                          "centre) and reach 0.150 m (setCartesianLimit) 62 % of the way; choose a target"
                       << "cross the box's +x face at 62 % of the way";
  QTest::newRow("rebooting") << "startDrag: the controller is rebooting" << "restarting";
  QTest::newRow("guard") << "startDrag: the guard stop is active" << "Close it";
  QTest::newRow("lost") << "getMotorState: no response from 127.0.0.1:1337: no response within 500 ms; check the IP "
                           "and port and that the controller is in RCI mode"
                        << "Lost contact with the robot";
  QTest::newRow("connect") << "connect: connection refused; check the controller's IP address and port and that it "
                              "is in RCI mode"
                           << "Cannot reach the robot";
  QTest::newRow("limits") << "setJointLimit: the controller refused: not possible in the robot's current state"
                          << "refused the soft limits";
  QTest::newRow("path") << "MOVEL: the path cannot be followed at 42% of its duration (t = 0.420 s of 1.000 s), TCP "
                           "at (0.100, 0.200, 0.300) m: the pose is beyond the arm's reach (IK code 1). Choose start, "
                           "via and target poses inside the workspace and away from singular poses, or move in joint "
                           "space with MOVEJ"
                        << "At 42 % of the way the pose is beyond the arm's reach";
  QTest::newRow("range") << "MOVEJ: q_target[1] = 2.200000 rad is outside the joint range [-2.094395, 2.094395] of "
                            "the xMate Pro 7; choose a reachable target"
                         << "J2 at 126.1°";
  QTest::newRow("wait di") << "instruction 4 (WAIT_DI): DI0_1 did not become true within 5000 ms; check the sensor "
                              "and its wiring, or raise timeout_ms"
                           << "DI0_1 did not become high within 5000 ms";
}

void TestOperatorText::refusalsTranslate() {
  QFETCH(QString, raw);
  QFETCH(QString, expected);
  const OperatorMessage m = failure(raw);
  QVERIFY2(m.line().contains(expected), qPrintable(m.line()));
  QVERIFY2(programmerWordsIn(plainOf(m)).isEmpty(), qPrintable(programmerWordsIn(plainOf(m)) + ": " + plainOf(m)));
  QVERIFY2(!m.detail_inline, qPrintable(m.line()));  // recognised, not the fallback
  QCOMPARE(m.detail, raw);
}

// The controller says only "not possible": the live state tells which button to press.
void TestOperatorText::refusalsExplainedFromLiveState() {
  const QString raw = QStringLiteral(
      "startMove: the controller refused: not possible in the robot's current state; power the motors on "
      "(setMotorPower(1)), stop dragging (stopDrag()) and release a guard stop");
  LiveState live = restingState();
  OperatorSettings settings;
  const RobotView view{&live, &settings, &xmate::model::robotSpec(xmate::XMATE7_PRO)};
  live.motor_state = 0;
  QVERIFY2(failure(raw, view).line().startsWith(QStringLiteral("The motors are off. Press Power on in the Power panel")),
           qPrintable(failure(raw, view).line()));
  live.motor_state = 1;
  live.state.robot_mode = RobotMode::kGuiding;
  QVERIFY2(failure(raw, view).line().contains(QStringLiteral("Press Stop guiding in the Drag panel")),
           qPrintable(failure(raw, view).line()));
  live.state.robot_mode = RobotMode::kIdle;
  live.safety_stop = 3;
  QVERIFY2(failure(raw, view).line().contains(QStringLiteral("guard stop")), qPrintable(failure(raw, view).line()));
  live.safety_stop = 2;
  const QString power = QStringLiteral("setMotorPower: the controller refused: not possible in the robot's current "
                                       "state (release an emergency stop first)");
  QVERIFY2(failure(power, view).line().contains(QStringLiteral("The emergency stop is pressed")),
           qPrintable(failure(power, view).line()));
  live.safety_stop = 1;
  live.state.errors[15] = true;
  const OperatorMessage errors = failure(raw, view);
  QVERIFY2(errors.line().contains(QStringLiteral("The robot reported an error")), qPrintable(errors.line()));
  QVERIFY2(errors.line().contains(QStringLiteral("Collision detected")), qPrintable(errors.line()));
  QVERIFY2(errors.line().contains(QStringLiteral("press Recover")), qPrintable(errors.line()));
  for (const OperatorMessage& m : {failure(raw, view), failure(power, view), errors})
    QVERIFY2(programmerWordsIn(plainOf(m)).isEmpty(), qPrintable(plainOf(m)));
}

void TestOperatorText::controlFailureNamesTheBits() {
  const QString raw = QStringLiteral(
      "Control(kJointPosition): the controller stopped the motion at message_id 1234 with error bits 15 kCollision "
      "(collision detected). What to do: a collision was detected and the motors were powered off: if there was no "
      "contact, raise the thresholds (setCollisionBehavior) or correct the payload (setLoad); then "
      "automaticErrorRecovery() and setMotorPower(1). Then call automaticErrorRecovery().");
  const OperatorMessage m = failure(raw);
  QVERIFY2(m.title.contains(QStringLiteral("Collision detected")), qPrintable(m.title));
  QVERIFY2(m.todo.contains(QStringLiteral("press Recover in the Safety panel")), qPrintable(m.todo));
  QVERIFY2(m.todo.contains(QStringLiteral("Power on")), qPrintable(m.todo));
  QVERIFY2(programmerWordsIn(plainOf(m)).isEmpty(), qPrintable(plainOf(m)));
  QCOMPARE(m.detail, raw);
}

void TestOperatorText::programFailureKeepsTheInstruction() {
  const QString raw = QStringLiteral(
      "instruction 3 (MOVEL \"P3\"): the controller aborted the motion: Control(kCartesianPosition): the controller "
      "stopped the motion at message_id 99 with error bits 10 kCommandJointVelocityLimitsViolation (commanded joint "
      "velocity over the limit). What to do: check that the planned trajectory is continuous and differentiable and "
      "within the limits of the model (docs/error_bits.md), filter it if needed (setFilters). Then call "
      "automaticErrorRecovery().");
  const OperatorMessage m = failure(raw);
  QVERIFY2(m.line().startsWith(QStringLiteral("Instruction 3 (MOVEL \"P3\"): The robot stopped the motion: Motion too "
                                              "fast for a joint.")),
           qPrintable(m.line()));
  QVERIFY2(m.todo.contains(QStringLiteral("speed override")), qPrintable(m.todo));
  QVERIFY2(programmerWordsIn(plainOf(m)).isEmpty(), qPrintable(plainOf(m)));
}

void TestOperatorText::exceptionTypesTranslate() {
  std::array<bool, 20> bits{};
  bits[1] = true;
  const xmate::ControlException control("Control(kCartesianPosition): odd wording", bits, {});
  QVERIFY2(failure(control).title.contains(QStringLiteral("Outside the safety box")), qPrintable(failure(control).line()));
  const xmate::TcpException tcp("setDO: cannot send to 10.0.0.2:1337: broken pipe");
  QVERIFY2(failure(tcp).title.contains(QStringLiteral("Lost contact")), qPrintable(failure(tcp).line()));
  const xmate::MotionException motion("MOVEC: the via point and the target coincide");
  QVERIFY2(failure(motion).title.contains(QStringLiteral("cannot be planned")), qPrintable(failure(motion).line()));
  QVERIFY(failure(motion).line().contains(QStringLiteral("coincide")));  // unknown specifics as the inline detail
  const std::invalid_argument value("setExternalWrench: fx = 9000 N is outside [-1000, 1000]");
  QVERIFY2(failure(value).title.contains(QStringLiteral("out of range")), qPrintable(failure(value).line()));
}

void TestOperatorText::unknownFailureKeepsTheRawMessage() {
  const OperatorMessage m = failure(QStringLiteral("frobnicate: the flux capacitor is cold"));
  QVERIFY(m.detail_inline);
  QVERIFY2(m.line().startsWith(QStringLiteral("The command did not succeed.")), qPrintable(m.line()));
  QVERIFY2(m.line().endsWith(QStringLiteral("(frobnicate: the flux capacitor is cold)")), qPrintable(m.line()));
}

// The editors' refusals name the field the operator typed into, not the call's parameter.
void TestOperatorText::refusedValuesNameTheField() {
  const struct {
    const char* raw;
    const char* plain;
  } cases[] = {
      {"setCollisionBehavior: upper_torque_thresholds_nominal[2] = 90 is outside (0, 60] Nm",
       "J3 threshold = 90 is outside (0, 60] Nm"},
      {"setJointLimit: lower[1] = 100 must be below upper[1] = 50", "J2 lower limit = 100 must be below J2 upper limit = 50"},
      {"setFilters: torque_hz = 2000 is outside [1, 1000] Hz (10-100 Hz recommended)",
       "Torque filter = 2000 is outside [1, 1000] Hz (10-100 Hz recommended)"},
      {"setLoad: inertia must be symmetric (row-major 3x3 about the centre of mass, kg m^2)",
       "Inertia must be symmetric (row-major 3x3 about the centre of mass, kg m^2)"},
      {"setCartImpDesiredTau: tau[2] = 80 is outside [-60, 60] N", "Desired wrench Fz = 80 is outside [-60, 60] N"},
      {"setCoor: the TCP is 0.8 m from the flange; at most 0.5 m is accepted",
       "The TCP is 0.8 m from the flange; at most 0.5 m is accepted"},
  };
  for (const auto& c : cases) {
    const QString plain = valueRefusal(c.raw);
    QCOMPARE(plain, QString::fromUtf8(c.plain));
    QVERIFY2(programmerWordsIn(plain).isEmpty(), qPrintable(plain));
  }
}

void TestOperatorText::programProblemsWithoutSolverCodes() {
  const QString plain = programProblem(
      "instruction 2 (MOVEL \"far\"): the target pose cannot be reached: the pose is beyond the arm's reach (IK code "
      "1); re-teach it, or give the target's joint angles \"q\"");
  QCOMPARE(plain, QStringLiteral("instruction 2 (MOVEL \"far\"): the target pose cannot be reached: the pose is beyond "
                                 "the arm's reach; re-teach it (Touch up in the Program panel)"));
}

void TestOperatorText::connectFailureNamesTheTarget() {
  const QString refused = connectFailure(
      QStringLiteral("Robot 10.0.0.2:1337 (xMate7 Pro)"),
      QStringLiteral("connect: connection refused; check the controller's IP address and port and that it is in RCI mode"));
  QVERIFY2(refused.startsWith(QStringLiteral("Could not connect to Robot 10.0.0.2:1337 (xMate7 Pro): Cannot reach the robot.")),
           qPrintable(refused));
  // Not recognised: the reason as it is.
  QCOMPARE(connectFailure(QStringLiteral("Simulator (xMate7 Pro)"), QStringLiteral("port 1337 is in use")),
           QStringLiteral("Could not connect to Simulator (xMate7 Pro): port 1337 is in use"));
}

QTEST_GUILESS_MAIN(TestOperatorText)
#include "test_operator_text.moc"
