// SPDX-License-Identifier: Apache-2.0
// Robot::Control() against the lock-step simulator: joint, Cartesian and torque callbacks that end
// with MotionFinished, the startMove pairing rules, a callback that throws, invalid commands, and
// what the session publishes meanwhile (state ring, counters).
#include <QtTest>

#include <cmath>
#include <stdexcept>

#include <xmate/joint_motion.h>
#include <xmate/rate_limiting.h>
#include <xmate/robot.h>

#include "client/connection.h"
#include "client/error_bits.h"
#include "client_test_support.h"

using namespace xmate;
using namespace client_test;
using CM = RCI::robot::StartMoveRequest::ControllerMode;
using MM = RCI::robot::StartMoveRequest::MotionGeneratorMode;
using RCI::robot::RobotMode;
using RCI::robot::RobotState;

class TestControlLoop : public QObject {
  Q_OBJECT

 private slots:
  void jointCallbackReachesTarget();
  void jointImpedanceCallbackRuns();
  void cartesianCallbackMovesTcp();
  void torqueCallbackWithZeroTorqueHolds();
  void controlWithoutStartMoveIsInvalidOperation();
  void modeMismatchIsInvalidOperation();
  void callbackExceptionIsRethrownAndMotionStopped();
  void nanCommandIsInvalidArgument();
  void nonHomogeneousPoseIsInvalidArgument();
  void samplesAndCountersFollowTheRun();
  void slowCallerBetweenStartMoveAndControlLosesNothing();
  void rateLimiterKeepsCommandsWithinTheLimits();
  void rateLimiterLetsAStreamWithAJumpFinish();
};

void TestControlLoop::jointCallbackReachesTarget() {
  auto server = startSim();
  auto robot = robotFor(*server);
  const RobotState s0 = robot->receiveRobotState();
  std::array<double, 7> goal = s0.q;
  goal[0] += 0.2;
  goal[3] -= 0.1;
  JointMotionGenerator generator(0.5, goal);
  std::array<double, 7> start{};
  double time = 0;
  int calls = 0;
  robot->startMove(CM::kJointPosition, MM::kJointPosition);
  robot->Control(JointControl([&](RobotState s) -> JointPositions {
    if (calls++ == 0) start = s.q;
    time += 0.001;
    generator.calculateSynchronizedValues_joint(start);
    std::array<double, 7> delta{};
    JointPositions out;
    const bool done = generator.calculateDesiredValues_joint(time, delta);
    for (int i = 0; i < 7; ++i) out.q[i] = start[i] + delta[i];
    return done ? MotionFinished(out) : out;
  }));
  QVERIFY(calls > 100);
  QVERIFY(std::abs(calls - generator.GetTime() / 0.001) <= 2);  // one call per cycle until the plan ends
  const RobotState s1 = robot->receiveRobotState();
  QVERIFY(s1.robot_mode != RobotMode::kMove);
  QVERIFY(eventually([&] { return maxAbsDiff(robot->receiveRobotState().q, goal) < 1e-4; }, 3000));
  QVERIFY(!server->status().sim.motion_active);
}

void TestControlLoop::jointImpedanceCallbackRuns() {
  auto server = startSim();
  auto robot = robotFor(*server);
  robot->setJointImpedance({2000, 2000, 2000, 2000, 200, 200, 200});
  int calls = 0;
  robot->startMove(CM::kJointImpedance, MM::kJointPosition);
  robot->Control(holdStill(300, &calls));
  QCOMPARE(calls, 300);
}

void TestControlLoop::cartesianCallbackMovesTcp() {
  auto server = startSim();
  auto robot = robotFor(*server);
  const RobotState s0 = robot->receiveRobotState();
  std::array<double, 16> start{};
  double time = 0;
  const double period = 2.0;  // s: z goes down 5 cm and back with a smooth cosine profile
  double lowest = 1e9;
  robot->startMove(CM::kCartesianPosition, MM::kCartesianPosition);
  robot->Control(CartesianControl([&](RobotState s) -> CartesianPose {
    if (time == 0) start = s.toolTobase_pos_m;
    time += 0.001;
    lowest = std::min(lowest, s.toolTobase_pos_m[11]);
    CartesianPose out;
    out.toolTobase_pos_c = start;
    out.toolTobase_pos_c[11] -= 0.025 * (1 - std::cos(2 * M_PI * time / period));
    return time >= period - 1e-9 ? MotionFinished(out) : out;
  }));
  QVERIFY2(std::abs((s0.toolTobase_pos_m[11] - lowest) - 0.05) < 2e-3, qPrintable(QString::number(lowest)));
  QVERIFY(eventually([&] { return std::abs(robot->receiveRobotState().toolTobase_pos_m[11] - start[11]) < 1e-4; }, 3000));
}

void TestControlLoop::torqueCallbackWithZeroTorqueHolds() {
  auto server = startSim();
  auto robot = robotFor(*server);
  const RobotState s0 = robot->receiveRobotState();
  int calls = 0;
  robot->startMove(CM::kTorque, MM::kIdle);
  robot->Control(TorqueControl([&](RobotState s) -> Torques {
    ++calls;
    Torques out;  // the controller compensates gravity: zero extra torque holds the arm
    // A gentle damping keeps numerical drift from building up.
    for (int i = 0; i < 7; ++i) out.tau[i] = -2.0 * s.dq_m[i];
    return calls >= 500 ? MotionFinished(out) : out;
  }));
  QCOMPARE(calls, 500);
  const RobotState s1 = robot->receiveRobotState();
  QVERIFY2(maxAbsDiff(s0.q, s1.q) < 5e-3, qPrintable(QString::number(maxAbsDiff(s0.q, s1.q))));
}

void TestControlLoop::controlWithoutStartMoveIsInvalidOperation() {
  auto server = startSim();
  auto robot = robotFor(*server);
  try {
    robot->Control(holdStill(10));
    QFAIL("Control() without startMove() ran");
  } catch (const InvalidOperationException& e) {
    QVERIFY2(QString(e.what()).contains("call startMove(kJointPosition or kJointImpedance, kJointPosition) first"),
             e.what());
  }
  // One Control() per startMove(): the second one needs a new startMove().
  robot->startMove(CM::kJointPosition, MM::kJointPosition);
  robot->Control(holdStill(10));
  QVERIFY_THROWS_EXCEPTION(InvalidOperationException, robot->Control(holdStill(10)));
}

void TestControlLoop::modeMismatchIsInvalidOperation() {
  auto server = startSim();
  auto robot = robotFor(*server);
  robot->startMove(CM::kJointPosition, MM::kJointPosition);
  try {
    robot->Control(CartesianControl([](RobotState s) { return CartesianPose{s.toolTobase_pos_c, false, 0, true}; }));
    QFAIL("a Cartesian callback ran after startMove(kJointPosition, kJointPosition)");
  } catch (const InvalidOperationException& e) {
    QVERIFY2(QString(e.what()).contains("startMove(kJointPosition, kJointPosition) does not drive a CartesianControl"),
             e.what());
  }
  robot->stopMove();
  startMoveWhenReady(*robot, CM::kTorque, MM::kIdle);
  QVERIFY_THROWS_EXCEPTION(InvalidOperationException, robot->Control(holdStill(5)));
  robot->stopMove();
}

void TestControlLoop::callbackExceptionIsRethrownAndMotionStopped() {
  auto server = startSim();
  auto robot = robotFor(*server);
  struct Boom : std::runtime_error {
    using std::runtime_error::runtime_error;
  };
  int calls = 0;
  std::array<double, 7> start{};
  robot->startMove(CM::kJointPosition, MM::kJointPosition);
  try {
    robot->Control(JointControl([&](RobotState s) -> JointPositions {
      if (calls == 0) start = s.q;
      if (++calls == 50) throw Boom("planner gave up");
      return JointPositions{start, false};
    }));
    QFAIL("the callback's exception was swallowed");
  } catch (const Boom& e) {
    QCOMPARE(QString(e.what()), QString("planner gave up"));
  }
  QCOMPARE(calls, 50);
  QVERIFY(eventually([&] { return !server->status().sim.motion_active; }));
  // The robot is usable again.
  startMoveWhenReady(*robot, CM::kJointPosition, MM::kJointPosition);
  robot->Control(holdStill(20));
}

void TestControlLoop::nanCommandIsInvalidArgument() {
  auto server = startSim();
  auto robot = robotFor(*server);
  int calls = 0;
  robot->startMove(CM::kJointPosition, MM::kJointPosition);
  try {
    std::array<double, 7> start{};
    robot->Control(JointControl([&](RobotState s) -> JointPositions {
      if (calls == 0) start = s.q;
      JointPositions out{start, false};
      if (++calls == 30) out.q[3] = std::nan("");
      return out;
    }));
    QFAIL("a NaN command was sent");
  } catch (const std::invalid_argument& e) {
    QVERIFY2(QString(e.what()).contains("q[3] = nan"), e.what());
    QVERIFY2(QString(e.what()).contains("the motion was stopped"), e.what());
  }
  QVERIFY(eventually([&] { return !server->status().sim.motion_active; }));
  QVERIFY(!RobotState(robot->receiveRobotState()).errors[10]);  // the NaN never reached the controller
}

void TestControlLoop::nonHomogeneousPoseIsInvalidArgument() {
  auto server = startSim();
  auto robot = robotFor(*server);
  robot->startMove(CM::kCartesianPosition, MM::kCartesianPosition);
  try {
    robot->Control(CartesianControl([&](RobotState s) -> CartesianPose {
      CartesianPose out{s.toolTobase_pos_c, false, 0, false};
      out.toolTobase_pos_c[0] *= 1.01;  // stretches the rotation
      return out;
    }));
    QFAIL("a non-homogeneous pose was sent");
  } catch (const std::invalid_argument& e) {
    QVERIFY2(QString(e.what()).contains("not a homogeneous transform"), e.what());
  }
  QVERIFY(eventually([&] { return !server->status().sim.motion_active; }));
}

void TestControlLoop::samplesAndCountersFollowTheRun() {
  auto server = startSim();
  auto robot = robotFor(*server);
  robot->connect();
  client::Connection& session = robot->connection();
  client::StateSample drain[512];
  while (session.samples().popBatch(drain, 512) > 0) {
  }
  const auto before = session.timing().counters;
  const uint64_t received_before = server->status().counters.commands_received;
  robot->startMove(CM::kJointPosition, MM::kJointPosition);
  robot->Control(holdStill(400));
  QVERIFY(eventually([&] { return session.timing().counters.commands_sent >= before.commands_sent + 400; }, 2000));
  const auto after = session.timing();
  // 400 answers from the callback, plus the "hold" answers sent before the controller reported the
  // motion running (Connection::runControl): a few, or hundreds on a loaded machine. The client's
  // count is exact: the controller received every one of them.
  const uint64_t sent = after.counters.commands_sent - before.commands_sent;
  QVERIFY2(sent >= 400, qPrintable(QString::number(sent)));
  QVERIFY2(eventually([&] { return server->status().counters.commands_received - received_before == sent; }, 2000),
           qPrintable(QStringLiteral("sent %1, received %2")
                          .arg(sent)
                          .arg(server->status().counters.commands_received - received_before)));
  QCOMPARE(after.counters.send_failures, uint64_t(0));
  QVERIFY(after.cost.cycles >= 400);
  // The ring saw the motion: consecutive message_ids, some in kMove.
  int moving = 0;
  uint64_t previous = 0;
  client::StateSample s;
  while (session.samples().pop(s)) {
    if (previous) QVERIFY(s.message_id > previous);
    previous = s.message_id;
    moving += s.robot_mode == RobotMode::kMove;
  }
  QVERIFY2(moving >= 395, qPrintable(QString::number(moving)));  // the first may still say kIdle
  QVERIFY(server->status().counters.commands_used >= 400);
}

void TestControlLoop::slowCallerBetweenStartMoveAndControlLosesNothing() {
  auto server = startSim();
  auto robot = robotFor(*server);
  robot->connect();
  const uint64_t lost_before = server->status().counters.commands_lost;
  robot->startMove(CM::kJointPosition, MM::kJointPosition);
  // The controller expects commands from now on; the session holds the robot still meanwhile.
  QVERIFY(eventually([&] { return server->status().counters.commands_used >= 300; }));
  int calls = 0;
  robot->Control(holdStill(100, &calls));
  QCOMPARE(calls, 100);
  QCOMPARE(server->status().counters.commands_lost, lost_before);
  QVERIFY(!client::anyError(robot->receiveRobotState().errors));
}

QTEST_APPLESS_MAIN(TestControlLoop)
// JointRateLimiter alone, against the controller's own difference quotients: whatever the targets do
// (steps of every size, back and forth, noise), the commands stay within the bounds, a target
// within the bounds passes unchanged, and a target that stops is reached.
void TestControlLoop::rateLimiterKeepsCommandsWithinTheLimits() {
  const JointRateLimits limits = ratedJointRateLimits(XMATE7_PRO, 1.0);
  JointRateLimiter limiter(limits);
  RobotState s{};
  s.q_c = {0.1, 0.2, -0.3, 1.0, 0.0, 0.5, 0.0};
  const std::array<double, 7> start = s.q_c;
  uint32_t noise = 12345;
  double worst_v = 0, worst_a = 0, worst_j = 0;  // largest use of each bound, as a fraction of it
  for (int k = 0; k < 6000; ++k) {
    std::array<double, 7> desired = start;
    const double step = (k / 500) % 2 == 0 ? 0.3 : -0.2;  // targets that jump every 0.5 s
    noise = noise * 1664525u + 1013904223u;
    for (size_t i = 0; i < 7; ++i) desired[i] += step * (1 + 0.1 * double(i)) + 1e-4 * double(noise % 100);
    const std::array<double, 7> q = limiter.limit(desired, s);
    for (size_t i = 0; i < 7; ++i) {
      const double v = (q[i] - s.q_c[i]) / 0.001, a = (v - s.dq_c[i]) / 0.001, j = (a - s.ddq_c[i]) / 0.001;
      worst_v = std::max(worst_v, std::abs(v) / limits.velocity[i]);
      worst_a = std::max(worst_a, std::abs(a) / limits.acceleration[i]);
      worst_j = std::max(worst_j, std::abs(j) / limits.jerk[i]);
      s.q_c[i] = q[i];
      s.dq_c[i] = v;
      s.ddq_c[i] = a;
    }
  }
  qInfo("largest share of the bounds used: velocity %.6f, acceleration %.6f, jerk %.6f", worst_v, worst_a, worst_j);
  QVERIFY(worst_v <= 1 + 1e-9 && worst_a <= 1 + 1e-9 && worst_j <= 1 + 1e-9);
  QVERIFY(worst_v > 0.99);  // the steps are large enough to need the bounds

  // Held still: a target that does not move any more is reached and kept.
  std::array<double, 7> goal = s.q_c;
  goal[0] += 0.05;
  for (int k = 0; k < 3000; ++k) {
    const std::array<double, 7> q = limiter.limit(goal, s);
    for (size_t i = 0; i < 7; ++i) {
      const double v = (q[i] - s.q_c[i]) / 0.001;
      s.ddq_c[i] = (v - s.dq_c[i]) / 0.001;
      s.dq_c[i] = v;
      s.q_c[i] = q[i];
    }
  }
  QVERIFY2(maxAbsDiff(s.q_c, goal) < 1e-9, qPrintable(QString::number(maxAbsDiff(s.q_c, goal))));

  // A smooth motion well within the bounds passes unchanged.
  RobotState smooth{};
  smooth.q_c = start;
  JointRateLimiter smooth_limiter(limits);
  double changed = 0;
  for (int k = 1; k < 2000; ++k) {
    std::array<double, 7> desired = start;
    desired[1] += 0.05 * (1 - std::cos(M_PI * k / 2000.0));
    const std::array<double, 7> q = smooth_limiter.limit(desired, smooth);
    changed = std::max(changed, maxAbsDiff(q, desired));
    const double v = (q[1] - smooth.q_c[1]) / 0.001;
    smooth.ddq_c[1] = (v - smooth.dq_c[1]) / 0.001;
    smooth.dq_c[1] = v;
    smooth.q_c = q;
  }
  QVERIFY2(changed < 1e-12, qPrintable(QString::number(changed)));
  QVERIFY_THROWS_EXCEPTION(std::invalid_argument, ratedJointRateLimits(XMATE7_PRO, 1.5));
}

// On the simulator: a stream with a 3 mrad jump in the middle makes the controller stop the
// motion; through JointRateLimiter the same stream finishes at its target without an error bit.
void TestControlLoop::rateLimiterLetsAStreamWithAJumpFinish() {
  auto stream = [](Robot& robot, bool limited) {
    JointRateLimiter limiter(ratedJointRateLimits(XMATE7_PRO));
    std::array<double, 7> start{};
    int64_t first = -1;
    robot.startMove(CM::kJointPosition, MM::kJointPosition);
    robot.Control(JointControl([&](RobotState s) -> JointPositions {
      if (first < 0) {
        first = int64_t(s.message_id);
        start = s.q_c;
      }
      const double t = double(int64_t(s.message_id) - first) * 0.001;  // elapsed controller time
      std::array<double, 7> desired = start;
      desired[0] += 0.05 * (1 - std::cos(M_PI * std::min(t, 1.0))) / 2 + (t >= 0.5 ? 0.003 : 0.0);
      JointPositions out{limited ? limiter.limit(desired, s) : desired};
      return t >= 1.5 ? MotionFinished(out) : out;
    }));
    return start;
  };
  {
    auto server = startSim();
    auto robot = robotFor(*server);
    robot->receiveRobotState();
    QVERIFY_THROWS_EXCEPTION(ControlException, stream(*robot, false));
  }
  auto server = startSim();
  auto robot = robotFor(*server);
  robot->receiveRobotState();
  const std::array<double, 7> start = stream(*robot, true);
  std::array<double, 7> goal = start;
  goal[0] += 0.053;
  QVERIFY(eventually([&] { return maxAbsDiff(robot->receiveRobotState().q, goal) < 1e-4; }, 3000));
  QVERIFY(!anyError(robot->receiveRobotState()));
}

#include "test_control_loop.moc"
