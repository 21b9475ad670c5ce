// SPDX-License-Identifier: Apache-2.0
// xmate::Robot's TCP calls against the simulator over loopback: lazy connect, every command's round
// trip and its effect on the controller, client-side validation (nothing sent), refusals,
// version mismatch, reboot and reconnect, and receiveRobotState.
#include <QtTest>

#include <cmath>

#include <xmate/model.h>
#include <xmate/robot.h>

#include "client/connection.h"
#include "client_test_support.h"

using namespace xmate;
using namespace client_test;
using RCI::robot::DISIGNAL;
using RCI::robot::DOSIGNAL;

namespace {

constexpr std::array<double, 16> kIdentity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

// Runs call and returns the std::invalid_argument message ("" if it did not throw one).
template <class F>
QString invalidArgumentOf(F&& call) {
  try {
    call();
  } catch (const std::invalid_argument& e) {
    return QString::fromStdString(e.what());
  }
  return {};
}

}  // namespace

class TestRobotCommands : public QObject {
  Q_OBJECT

 private slots:
  void lazyConnectOnFirstCall();
  void connectToClosedPortThrowsTcpException();
  void incompatibleVersionIsNamed();
  void receiveRobotStateReturnsNewerStates();
  void motorPowerRoundTrip();
  void digitalIoThroughLoopback();
  void safetyStopStateUsesApiNumbering();
  void settingsAreAccepted();
  void toolAndLoadAreRememberedAndApplied();
  void validationRejectsBeforeSending_data();
  void validationRejectsBeforeSending();
  void dragRoundTrip();
  void controllerRefusalIsCommandException();
  void rebootThenReconnectRestoresDefaults();
  void sessionTimingAndCounters();
};

void TestRobotCommands::lazyConnectOnFirstCall() {
  auto server = startSim();
  auto robot = robotFor(*server);
  QVERIFY(!server->status().session);
  QVERIFY(!robot->connection().isOpen());
  QCOMPARE(robot->getMotorState(), 1);  // first call connects
  QVERIFY(robot->connection().isOpen());
  QVERIFY(eventually([&] { return server->status().session && server->status().streaming; }));
  QCOMPARE(server->status().counters.sessions, uint64_t(1));
  robot->connect();  // no-op when connected
  QCOMPARE(server->status().counters.sessions, uint64_t(1));
}

void TestRobotCommands::connectToClosedPortThrowsTcpException() {
  Robot robot("127.0.0.1", unusedPort());
  try {
    robot.connect();
    QFAIL("connect() to a closed port succeeded");
  } catch (const TcpException& e) {
    const QString what = e.what();
    QVERIFY2(what.contains("127.0.0.1") && what.contains("port"), e.what());
  }
  QVERIFY(!robot.reconnect());
  QVERIFY_THROWS_EXCEPTION(std::invalid_argument, Robot("not-an-ip", 1337));
}

void TestRobotCommands::incompatibleVersionIsNamed() {
  SimOptions o;
  o.reject_connect = true;
  auto server = startSim(o);
  auto robot = robotFor(*server);
  try {
    robot->connect();
    QFAIL("connect() succeeded against an incompatible controller");
  } catch (const ProtocolException& e) {
    QVERIFY2(QString(e.what()).contains("incompatible library version"), e.what());
  }
  QVERIFY(!robot->connection().isOpen());
}

void TestRobotCommands::receiveRobotStateReturnsNewerStates() {
  auto server = startSim();
  auto robot = robotFor(*server);
  const auto a = robot->receiveRobotState();
  const auto b = robot->receiveRobotState();
  QVERIFY(b.message_id > a.message_id);
  QCOMPARE(b.robot_mode, RCI::robot::RobotMode::kIdle);
  // The state is the controller's: compare with what the simulator produced.
  const auto sim = server->latestState();
  QVERIFY(maxAbsDiff(sim.q, b.q) < 1e-9);
  QVERIFY(std::abs(b.toolTobase_pos_m[15] - 1.0) < 1e-12);
  RCI::robot::RobotState latest;
  QVERIFY(robot->connection().latestState(latest));
  QVERIFY(latest.message_id >= b.message_id);
}

void TestRobotCommands::motorPowerRoundTrip() {
  SimOptions o;
  o.motors_on = false;
  auto server = startSim(o);
  auto robot = robotFor(*server);
  QCOMPARE(robot->getMotorState(), 0);
  QVERIFY(robot->setMotorPower(1));
  QCOMPARE(robot->getMotorState(), 1);
  QVERIFY(server->status().sim.motors_on);
  QVERIFY(robot->setMotorPower(0));
  QCOMPARE(robot->getMotorState(), 0);
  QVERIFY(!server->status().sim.motors_on);
}

void TestRobotCommands::digitalIoThroughLoopback() {
  SimOptions o;
  o.loopback_io = true;
  auto server = startSim(o);
  auto robot = robotFor(*server);
  QVERIFY(!robot->getDI(DISIGNAL::DI0_2));
  QVERIFY(robot->setDO(DOSIGNAL::DO0_2, true));
  QVERIFY(server->status().sim.digital_out[2]);
  QVERIFY(robot->getDI(DISIGNAL::DI0_2));
  QVERIFY(!robot->getDI(DISIGNAL::DI1_1));
  QVERIFY(robot->setDO(DOSIGNAL::DO0_2, false));
  QVERIFY(!robot->getDI(DISIGNAL::DI0_2));
  // Without loop-back the scene drives the inputs.
  server->setDoToDiLoopback(false);
  server->setDigitalInput(5, true);
  QVERIFY(robot->getDI(DISIGNAL::DI1_1));
}

void TestRobotCommands::safetyStopStateUsesApiNumbering() {
  auto server = startSim();
  auto robot = robotFor(*server);
  QCOMPARE(robot->getSafetyStopState(), 1);
  server->setEmergencyStop(true);
  QCOMPARE(robot->getSafetyStopState(), 2);
  QCOMPARE(robot->getMotorState(), 0);  // ESTOP powers the motors off
  server->setEmergencyStop(false);
  server->setGuardStop(true);
  QCOMPARE(robot->getSafetyStopState(), 3);
  server->setGuardStop(false);
  QCOMPARE(robot->getSafetyStopState(), 1);
}

void TestRobotCommands::settingsAreAccepted() {
  auto server = startSim();
  auto robot = robotFor(*server);
  robot->setCollisionBehavior({60, 60, 50, 40, 25, 25, 15});
  robot->setCartesianLimit({2, 2, 2}, kIdentity, true);
  robot->setCartesianLimit({2, 2, 2}, kIdentity, false);
  robot->setJointImpedance({1000, 1000, 1000, 1000, 100, 100, 100});
  robot->setCartesianImpedance({1500, 1500, 1500, 100, 100, 100});
  robot->setFilters(50, 50, 50);
  robot->setCartImpDesiredTau({0, 0, 10, 0, 0, 0});
  robot->setJointLimit({160, 110, 160, 110, 160, 110, 350}, {-160, -110, -160, -110, -160, -110, -350}, true);
  robot->setFcCoor(kIdentity, 1);
  robot->setFcCoor(kIdentity, 3);
  robot->automaticErrorRecovery();
  QCOMPARE(robot->getMotorState(), 1);
}

void TestRobotCommands::toolAndLoadAreRememberedAndApplied() {
  auto server = startSim();
  auto robot = robotFor(*server);
  QCOMPARE(robot->toolFrame(), kIdentity);
  const auto flange = robot->receiveRobotState().toolTobase_pos_m;
  std::array<double, 16> tool = kIdentity;
  tool[11] = 0.1;  // TCP 10 cm along the flange's z axis
  robot->setCoor(tool);
  QCOMPARE(robot->toolFrame(), tool);
  // The controller now reports the TCP: 0.1 m along the flange's z axis (third column).
  QVERIFY(eventually([&] {
    const auto tcp = robot->receiveRobotState().toolTobase_pos_m;
    return std::abs(tcp[3] - (flange[3] + 0.1 * flange[2])) < 1e-6 &&
           std::abs(tcp[7] - (flange[7] + 0.1 * flange[6])) < 1e-6 &&
           std::abs(tcp[11] - (flange[11] + 0.1 * flange[10])) < 1e-6;
  }));
  robot->setLoad(2.5, {0, 0, 0.05}, {0.01, 0, 0, 0, 0.01, 0, 0, 0, 0.01});
  double mass = 0;
  std::array<double, 3> center{};
  std::array<double, 9> inertia{};
  robot->load(mass, center, inertia);
  QCOMPARE(mass, 2.5);
  QCOMPARE(center[2], 0.05);
  QCOMPARE(inertia[4], 0.01);

  // A model made from the robot starts with its tool: its TCP pose is the one the controller reports.
  xmate::XmateModel model(robot.get(), xmate::XMATE7_PRO);
  const auto state = robot->receiveRobotState();
  QVERIFY(maxAbsDiff(model.GetCartPose(state.q), state.toolTobase_pos_m) < 1e-6);
  // ... and its payload: the gravity torques differ from those of an unloaded model.
  xmate::XmateModel unloaded(xmate::XMATE7_PRO);
  std::array<double, 7> full{}, inertial{}, coriolis{}, gravity{}, gravity_unloaded{};
  model.GetTauNoFriction(state.q, {}, {}, full, inertial, coriolis, gravity);
  unloaded.GetTauNoFriction(state.q, {}, {}, full, inertial, coriolis, gravity_unloaded);
  QVERIFY(maxAbsDiff(gravity, gravity_unloaded) > 0.1);
}

void TestRobotCommands::validationRejectsBeforeSending_data() {
  QTest::addColumn<int>("which");
  QTest::addColumn<QString>("expected");
  QTest::newRow("collision above max") << 0 << "upper_torque_thresholds_nominal[1] = 80";
  QTest::newRow("collision NaN") << 1 << "upper_torque_thresholds_nominal[0] is not a finite number";
  QTest::newRow("stiffness above max") << 2 << "K_theta[4] = 301";
  QTest::newRow("cartesian stiffness") << 3 << "K_x[3] = 400";
  QTest::newRow("tool not homogeneous") << 4 << "F_T_EE";
  QTest::newRow("tool too far") << 5 << "0.6 m from the flange";
  QTest::newRow("load too heavy") << 6 << "mass = 8";
  QTest::newRow("load inertia asymmetric") << 7 << "symmetric";
  QTest::newRow("filter too low") << 8 << "joint_hz = 0.5";
  QTest::newRow("wrench too large") << 9 << "tau[2] = 61";
  QTest::newRow("motor power 2") << 10 << "state = 2";
  QTest::newRow("soft limit beyond hardware") << 11 << "upper[0] = 171";
  QTest::newRow("fc_type 0") << 12 << "fc_type = 0";
  QTest::newRow("joint drag translation") << 13 << "drag_type = 3";
  QTest::newRow("drag space 3") << 14 << "drag_space = 3";
  QTest::newRow("safety box size 0") << 15 << "size[1] = 0";
  QTest::newRow("start move pair") << 16 << "(kTorque, kJointPosition) is not supported";
  QTest::newRow("6-axis element 6") << 17 << "must be 0 on the 6-axis";
}

void TestRobotCommands::validationRejectsBeforeSending() {
  QFETCH(int, which);
  QFETCH(QString, expected);
  // Nobody listens on this port: a call that reached the network would throw TcpException.
  Robot robot("127.0.0.1", unusedPort(), which == 17 ? XMATE7 : XMATE7_PRO);
  std::array<double, 16> skewed = kIdentity;
  skewed[1] = 0.1;
  std::array<double, 16> far = kIdentity;
  far[3] = 0.6;
  using CM = RCI::robot::StartMoveRequest::ControllerMode;
  using MM = RCI::robot::StartMoveRequest::MotionGeneratorMode;
  const std::function<void()> calls[] = {
      [&] { robot.setCollisionBehavior({75, 80, 60, 45, 30, 30, 20}); },
      [&] { robot.setCollisionBehavior({NAN, 1, 1, 1, 1, 1, 1}); },
      [&] { robot.setJointImpedance({1, 1, 1, 1, 301, 1, 1}); },
      [&] { robot.setCartesianImpedance({1, 1, 1, 400, 1, 1}); },
      [&] { robot.setCoor(skewed); },
      [&] { robot.setCoor(far); },
      [&] { robot.setLoad(8, {0, 0, 0}, {0, 0, 0, 0, 0, 0, 0, 0, 0}); },
      [&] { robot.setLoad(1, {0, 0, 0}, {0.01, 0.002, 0, 0, 0.01, 0, 0, 0, 0.01}); },
      [&] { robot.setFilters(0.5, 10, 10); },
      [&] { robot.setCartImpDesiredTau({0, 0, 61, 0, 0, 0}); },
      [&] { robot.setMotorPower(2); },
      [&] { robot.setJointLimit({171, 120, 170, 120, 170, 120, 360}, {-170, -120, -170, -120, -170, -120, -360}, false); },
      [&] { robot.setFcCoor(kIdentity, 0); },
      [&] { robot.startDrag(1, 1); },
      [&] { robot.startDrag(3, 3); },
      [&] { robot.setCartesianLimit({1, 0, 1}, kIdentity, true); },
      [&] { robot.startMove(CM::kTorque, MM::kJointPosition); },
      [&] { robot.setJointImpedance({1, 1, 1, 1, 1, 1, 1}); },
  };
  const QString message = invalidArgumentOf(calls[which]);
  QVERIFY2(message.contains(expected), qPrintable("got: '" + message + "', expected to contain '" + expected + "'"));
  QVERIFY(!robot.connection().isOpen());
}

void TestRobotCommands::dragRoundTrip() {
  auto server = startSim();
  auto robot = robotFor(*server);
  robot->startDrag(2, 1);
  QVERIFY(eventually([&] { return server->status().sim.dragging; }));
  QVERIFY(eventually([&] { return robot->receiveRobotState().robot_mode == RCI::robot::RobotMode::kGuiding; }));
  robot->stopDrag();
  QVERIFY(eventually([&] { return !server->status().sim.dragging; }));
  whenReady([&] { robot->startDrag(1, 3); });  // the first drag may still be coming to rest
  QVERIFY(eventually([&] { return server->status().sim.dragging; }));
  robot->stopDrag();
}

void TestRobotCommands::controllerRefusalIsCommandException() {
  SimOptions o;
  o.motors_on = false;
  auto server = startSim(o);
  auto robot = robotFor(*server);
  using CM = RCI::robot::StartMoveRequest::ControllerMode;
  using MM = RCI::robot::StartMoveRequest::MotionGeneratorMode;
  try {
    robot->startMove(CM::kJointPosition, MM::kJointPosition);  // motors are off
    QFAIL("startMove with the motors off was accepted");
  } catch (const CommandException& e) {
    QVERIFY2(QString(e.what()).contains("startMove: the controller refused: not possible"), e.what());
  }
  server->setEmergencyStop(true);
  try {
    robot->setMotorPower(1);
    QFAIL("setMotorPower(1) under an emergency stop was accepted");
  } catch (const CommandException& e) {
    QVERIFY2(QString(e.what()).startsWith("setMotorPower: the controller refused"), e.what());
  }
  server->setEmergencyStop(false);
}

void TestRobotCommands::rebootThenReconnectRestoresDefaults() {
  auto server = startSim();
  auto robot = robotFor(*server);
  std::array<double, 16> tool = kIdentity;
  tool[11] = 0.05;
  const auto flange_before = robot->receiveRobotState().toolTobase_pos_m;
  robot->setCoor(tool);
  // The state sent in the cycle of the request may still show the flange.
  QVERIFY(eventually([&] { return robot->receiveRobotState().toolTobase_pos_m[11] != flange_before[11]; }));
  const auto with_tool = robot->receiveRobotState().toolTobase_pos_m;
  robot->rebootRobot();
  QVERIFY(!robot->connection().isOpen());
  QCOMPARE(robot->toolFrame(), kIdentity);
  QVERIFY(eventually([&] { return robot->reconnect(); }));
  QVERIFY(robot->connection().isOpen());
  QCOMPARE(server->status().counters.reboots, uint64_t(1));
  // The fresh controller has no tool: the reported pose is the flange, 5 cm behind the old TCP.
  const auto flange = robot->receiveRobotState().toolTobase_pos_m;
  QVERIFY(std::abs((with_tool[11] - flange[11]) - 0.05 * flange[10]) < 1e-6);
}

void TestRobotCommands::sessionTimingAndCounters() {
  auto server = startSim();
  auto robot = robotFor(*server);
  robot->connect();
  QVERIFY(robot->connection().udpPort() != 0);
  QVERIFY(eventually([&] { return robot->connection().timing().counters.states_received > 300; }));
  const client::SessionTiming t = robot->connection().timing();
  QCOMPARE(t.counters.states_wrong_length, uint64_t(0));
  QCOMPARE(t.counters.states_bad_value, uint64_t(0));
  QVERIFY(t.period.cycles > 100);
  // The periods were measured (a backlog the real-time thread drains at once after a stall -- seen
  // under AddressSanitizer on a loaded machine -- can legitimately give a shortest period of 0).
  QVERIFY(t.period.mean_us > 0);
  QVERIFY(t.period.max_us >= t.period.min_us);
  // The GUI ring holds consecutive samples of what arrived.
  client::StateSample sample, next;
  QVERIFY(robot->connection().samples().pop(sample));
  QVERIFY(robot->connection().samples().pop(next));
  QVERIFY(next.message_id > sample.message_id);
  QVERIFY(next.time >= sample.time);
  QCOMPARE(sample.robot_mode, RCI::robot::RobotMode::kIdle);
  QCOMPARE(sample.errors, uint32_t(0));
}

QTEST_APPLESS_MAIN(TestRobotCommands)
#include "test_robot_commands.moc"
