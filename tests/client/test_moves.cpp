// SPDX-License-Identifier: Apache-2.0
// MOVEJ, MOVEL and MOVEC against the lock-step simulator: they reach their targets (1e-4 rad,
// 0.1 mm), with and without a model, on a 7-axis and a 6-axis arm; and they refuse, with a
// MotionException saying why, a start that is not where the robot is, unreachable targets and
// collinear arc points.
#include <QtTest>

#include <cmath>

#include <xmate/model.h>
#include <xmate/move.h>
#include <xmate/robot.h>

#include "client/connection.h"
#include "client_test_support.h"

using namespace xmate;
using namespace client_test;
using RCI::robot::RobotState;

namespace {

constexpr double kJointTolerance = 1e-4;     // rad
constexpr double kPositionTolerance = 1e-4;  // m

double rotationDifference(const std::array<double, 16>& a, const std::array<double, 16>& b) {
  double m = 0;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m = std::max(m, std::abs(a[4 * r + c] - b[4 * r + c]));
  return m;
}

// Waits until the measured TCP has settled at target (the controller tracks the last command).
bool settlesAt(Robot& robot, const std::array<double, 16>& target) {
  return eventually([&] {
    const auto s = robot.receiveRobotState();
    return distance(s.toolTobase_pos_m, target) < kPositionTolerance &&
           rotationDifference(s.toolTobase_pos_m, target) < 1e-4;
  }, 3000);
}

bool settlesAt(Robot& robot, const std::array<double, 7>& q) {
  return eventually([&] { return maxAbsDiff(robot.receiveRobotState().q, q) < kJointTolerance; }, 3000);
}

template <class F>
QString motionExceptionOf(F&& call) {
  try {
    call();
  } catch (const MotionException& e) {
    return QString::fromStdString(e.what());
  }
  return {};
}

}  // namespace

class TestMoves : public QObject {
  Q_OBJECT

 private slots:
  void movejReachesTarget();
  void movejOnSixAxisArm();
  void movejRejectsStartFarFromRobot();
  void movejRejectsTargetOutsideJointRange();
  void movelReachesTargetInCartesianMode();
  void movelWithModelReachesTargetInJointMode();
  void movecPassesThroughMidAndReachesTarget();
  void movecWithModel();
  void movelRejectsStartFarFromRobot();
  void movelRejectsUnreachableTarget();
  void movecRejectsCollinearPoints();
  void invalidSpeedRatio();
};

void TestMoves::movejReachesTarget() {
  auto server = startSim();
  auto robot = robotFor(*server);
  const std::array<double, 7> q_init = robot->receiveRobotState().q;
  const std::array<double, 7> target{0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9};  // the manual's example
  QVERIFY(MOVEJ(0.5, q_init, target, *robot));
  QVERIFY(settlesAt(*robot, target));
  // A zero move returns at once.
  QVERIFY(MOVEJ(0.5, robot->receiveRobotState().q, target, *robot));
}

void TestMoves::movejOnSixAxisArm() {
  SimOptions o;
  o.type = XMATE7;
  auto server = startSim(o);
  auto robot = robotFor(*server, XMATE7);
  const std::array<double, 7> target{0.0, M_PI / 6, M_PI / 3, 0.0, M_PI / 2, 0.0, 0.0};  // example 2
  QVERIFY(MOVEJ(0.4, robot->receiveRobotState().q, target, *robot));
  QVERIFY(settlesAt(*robot, target));
  QCOMPARE(robot->receiveRobotState().q_c[6], 0.0);
}

void TestMoves::movejRejectsStartFarFromRobot() {
  auto server = startSim();
  auto robot = robotFor(*server);
  std::array<double, 7> q = robot->receiveRobotState().q;
  q[2] += 0.01;
  const QString message = motionExceptionOf([&] { MOVEJ(0.5, q, {0, 0, 0, 0, 0, 0, 0}, *robot); });
  QVERIFY2(message.contains("q_start[2]") && message.contains("pass the current state"), qPrintable(message));
  QVERIFY(!server->status().sim.motion_active);
}

void TestMoves::movejRejectsTargetOutsideJointRange() {
  auto server = startSim();
  auto robot = robotFor(*server);
  const QString message =
      motionExceptionOf([&] { MOVEJ(0.5, robot->receiveRobotState().q, {0, 2.5, 0, 0, 0, 0, 0}, *robot); });
  QVERIFY2(message.contains("q_target[1]") && message.contains("joint range"), qPrintable(message));
}

void TestMoves::movelReachesTargetInCartesianMode() {
  auto server = startSim();
  auto robot = robotFor(*server);
  cart_pos start, target;
  start.pos = robot->receiveRobotState().toolTobase_pos_m;
  target = start;
  target.pos[11] -= 0.1;  // the manual's example: 10 cm down
  target.pos[3] += 0.05;
  QVERIFY(MOVEL(0.5, start, target, *robot));
  QVERIFY(settlesAt(*robot, target.pos));
}

void TestMoves::movelWithModelReachesTargetInJointMode() {
  auto server = startSim();
  auto robot = robotFor(*server);
  std::array<double, 16> tool{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0.08, 0, 0, 0, 1};
  const double flange_z = robot->receiveRobotState().toolTobase_pos_m[11];
  robot->setCoor(tool);
  XmateModel model(robot.get(), XMATE7_PRO);
  model.SetCoor(robot->toolFrame());
  cart_pos start, target;
  // The state sent in the cycle of the setCoor request may still show the flange.
  QVERIFY(eventually([&] { return std::abs(robot->receiveRobotState().toolTobase_pos_m[11] - flange_z) > 0.01; }));
  start.pos = robot->receiveRobotState().toolTobase_pos_m;
  target = start;
  target.pos[11] -= 0.1;
  target.pos[7] += 0.05;
  const double psi_before = robot->receiveRobotState().psi_m;
  QVERIFY(MOVEL(0.5, start, target, *robot, model));
  QVERIFY(settlesAt(*robot, target.pos));
  // psi not given: the arm angle is held.
  QVERIFY(std::abs(robot->receiveRobotState().psi_m - psi_before) < 1e-3);
}

void TestMoves::movecPassesThroughMidAndReachesTarget() {
  auto server = startSim();
  auto robot = robotFor(*server);
  cart_pos start, mid, target;
  start.pos = robot->receiveRobotState().toolTobase_pos_m;
  mid = start;
  target = start;
  mid.pos[3] += 0.05;  // a half circle of radius 5 cm in the x-z plane
  mid.pos[11] -= 0.05;
  target.pos[11] -= 0.1;
  client::StateSample sample;
  while (robot->connection().samples().pop(sample)) {
  }
  QVERIFY(MOVEC(0.5, start, mid, target, *robot));
  QVERIFY(settlesAt(*robot, target.pos));
  // The measured TCP passed through the mid point (the ring holds every state of the move).
  double closest_to_mid = 1e9;
  while (robot->connection().samples().pop(sample)) {
    const double d = std::sqrt(std::pow(sample.tcp_position[0] - mid.pos[3], 2) +
                               std::pow(sample.tcp_position[1] - mid.pos[7], 2) +
                               std::pow(sample.tcp_position[2] - mid.pos[11], 2));
    closest_to_mid = std::min(closest_to_mid, d);
  }
  QVERIFY2(closest_to_mid < 2e-3, qPrintable(QString::number(closest_to_mid)));
}

void TestMoves::movecWithModel() {
  auto server = startSim();
  auto robot = robotFor(*server);
  XmateModel model(robot.get(), XMATE7_PRO);
  cart_pos start, mid, target;
  start.pos = robot->receiveRobotState().toolTobase_pos_m;
  mid = start;
  target = start;
  mid.pos[7] += 0.04;
  mid.pos[11] -= 0.04;
  target.pos[11] -= 0.08;
  QVERIFY(MOVEC(0.5, start, mid, target, *robot, model));
  QVERIFY(settlesAt(*robot, target.pos));
}

void TestMoves::movelRejectsStartFarFromRobot() {
  auto server = startSim();
  auto robot = robotFor(*server);
  cart_pos start, target;
  start.pos = robot->receiveRobotState().toolTobase_pos_m;
  target = start;
  start.pos[3] += 0.005;
  const QString message = motionExceptionOf([&] { MOVEL(0.5, start, target, *robot); });
  QVERIFY2(message.contains("5.00 mm") && message.contains("pass the current state"), qPrintable(message));
}

void TestMoves::movelRejectsUnreachableTarget() {
  auto server = startSim();
  auto robot = robotFor(*server);
  cart_pos start, target;
  start.pos = robot->receiveRobotState().toolTobase_pos_m;
  target = start;
  target.pos[3] += 1.5;  // far beyond the reach of a 1.3 m arm
  const QString message = motionExceptionOf([&] { MOVEL(0.5, start, target, *robot); });
  QVERIFY2(message.contains("beyond the arm's reach") && message.contains("% of its duration"), qPrintable(message));
  QVERIFY(!server->status().sim.motion_active);
}

void TestMoves::movecRejectsCollinearPoints() {
  auto server = startSim();
  auto robot = robotFor(*server);
  cart_pos start, mid, target;
  start.pos = robot->receiveRobotState().toolTobase_pos_m;
  mid = start;
  target = start;
  mid.pos[11] -= 0.05;
  target.pos[11] -= 0.1;
  const QString message = motionExceptionOf([&] { MOVEC(0.5, start, mid, target, *robot); });
  QVERIFY2(message.contains("collinear"), qPrintable(message));
}

void TestMoves::invalidSpeedRatio() {
  auto server = startSim();
  auto robot = robotFor(*server);
  const auto q = robot->receiveRobotState().q;
  QVERIFY_THROWS_EXCEPTION(std::invalid_argument, MOVEJ(0.0, q, q, *robot));
  QVERIFY_THROWS_EXCEPTION(std::invalid_argument, MOVEJ(1.5, q, q, *robot));
}

QTEST_APPLESS_MAIN(TestMoves)
#include "test_moves.moc"
