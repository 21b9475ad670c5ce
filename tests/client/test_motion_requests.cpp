// SPDX-License-Identifier: Apache-2.0
// What happens when a motion is asked for, against the simulator (lock-step clock): after a
// reflex, a stop or the end of hand guiding the next motion waits for the arm to stand still
// instead of being refused; a refusal names the one cause that holds; and a motion whose target or
// path leaves the joint range, the soft limits or the safety box is refused before anything moves,
// naming the joint or face, every time -- while moving back towards them stays allowed.
#include <QtTest>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <thread>

#include <xmate/move.h>
#include <xmate/robot.h>

#include "client/connection.h"
#include "client/standstill.h"
#include "model/robot_spec.h"
#include "client_test_support.h"
#include "teach/executor.h"
#include "teach/program.h"

using namespace xmate;
using namespace client_test;
using RCI::robot::RobotState;
using CM = RCI::robot::StartMoveRequest::ControllerMode;
using MM = RCI::robot::StartMoveRequest::MotionGeneratorMode;

namespace {

constexpr double kDeg = M_PI / 180.0;


// Joint 1 at 1 rad/s from where it is (a jerk-limited start), until the controller stops it;
// `calls` counts the callback's calls.
JointControl spinJointOne(std::shared_ptr<std::atomic<int>> calls = std::make_shared<std::atomic<int>>(0)) {
  auto start = std::make_shared<std::array<double, 7>>();
  return [=](RobotState s) -> JointPositions {
    if (*calls == 0) *start = s.q;
    const double t = ++*calls * 1e-3;
    JointPositions out{*start, false};
    const double ramp = 0.2;  // s to reach 1 rad/s, smoothly
    out.q[0] += t < ramp ? t * t * t / (ramp * ramp) - t * t * t * t / (2 * ramp * ramp * ramp) : t - ramp / 2;
    return out;
  };
}

// Starts joint 1 spinning and, 0.3 s of controller time into it (at full speed), ends the motion
// with `stop` (run on another thread); returns what Control() threw ("" if nothing).
QString spinThenStop(Robot& robot, const std::function<void()>& stop) {
  auto calls = std::make_shared<std::atomic<int>>(0);
  std::thread stopper([&] {
    eventually([&] { return calls->load() >= 300; }, 10000);
    try {
      stop();
    } catch (const std::exception&) {  // stopMove() refused: the motion had ended already
    }
  });
  QString thrown;
  robot.startMove(CM::kJointPosition, MM::kJointPosition);
  try {
    robot.Control(spinJointOne(calls));
  } catch (const std::exception& e) {
    thrown = QString::fromStdString(e.what());
  }
  calls->store(1'000'000);
  stopper.join();
  return thrown;
}

bool says(const std::exception& e, const char* text) { return std::string(e.what()).find(text) != std::string::npos; }

// Soft limits `margin_deg` around q on every joint, within the hardware range (degrees, as setJointLimit takes them).
void softLimitsAround(const std::array<double, 7>& q, double margin_deg, std::array<double, 7>& upper,
                      std::array<double, 7>& lower) {
  const auto& spec = model::robotSpec(XMATE7_PRO);
  for (int i = 0; i < 7; ++i) {
    upper[i] = std::min(q[i] / kDeg + margin_deg, spec.q_max[i] / kDeg);
    lower[i] = std::max(q[i] / kDeg - margin_deg, spec.q_min[i] / kDeg);
  }
}

}  // namespace

class TestMotionRequests : public QObject {
  Q_OBJECT

 private slots:
  void standstillWatchFollowsTheStates();
  void moveBackRightAfterEveryKindOfStop();
  void startReadWhileTheArmStillMovedIsAccepted();
  void refusalsNameTheCauseThatHolds();
  void targetsBeyondSoftLimitsAreRefusedBeforeMoving();
  void movingBackTowardsTheLimitsIsAllowed();
  void pathsLeavingTheSafetyBoxAreRefused();
  void executorChecksTheRobotsLimits();
};

void TestMotionRequests::standstillWatchFollowsTheStates() {
  client::StandstillWatch watch;
  RobotState s;
  s.robot_mode = RCI::robot::RobotMode::kIdle;
  s.dq_m[1] = 0.12;
  QVERIFY(!watch.update(s, 7).still);
  QCOMPARE(watch.update(s, 7).fastest_joint, 1);
  QCOMPARE(client::stillStoppingText(watch.update(s, 7)), std::string("the arm is still stopping (joint 2 at 0.12 rad/s)"));
  QVERIFY(client::stoppingOnItsOwn(watch.update(s, 7), s));
  s.robot_mode = RCI::robot::RobotMode::kGuiding;
  QVERIFY(!client::stoppingOnItsOwn(watch.update(s, 7), s));  // hand guiding: the controller says so itself
  s.robot_mode = RCI::robot::RobotMode::kIdle;
  s.dq_m[1] = 0.0;
  s.dq_c[4] = 0.02;  // the commanded velocity counts too (the stop ramp)
  QVERIFY(!watch.update(s, 7).still);
  s.dq_c[4] = 0.0;
  s.dq_m[2] = 0.005;  // settling: at rest, not yet still (a motion waits a little; the window enables it)
  for (uint32_t k = 1; k < client::kStillStates; ++k) QVERIFY(!watch.update(s, 7).at_rest);
  QVERIFY(watch.update(s, 7).at_rest);
  QVERIFY(!watch.update(s, 7).still);
  QVERIFY(client::settling(watch.update(s, 7), s));
  QVERIFY(!client::stoppingOnItsOwn(watch.update(s, 7), s));
  s.dq_m[2] = 0.0;
  for (uint32_t k = 1; k < client::kStillStates; ++k) QVERIFY(!watch.update(s, 7).still);
  QVERIFY(watch.update(s, 7).still);
  QVERIFY(!client::settling(watch.update(s, 7), s));
}

// After a reflex (a command the controller rejects), a collision, a guard stop, stopMove() from
// another thread and the end of hand guiding: recovery (where needed), power on and a MOVEJ back
// work at once, without a retry, while the arm is still coming to rest.
void TestMotionRequests::moveBackRightAfterEveryKindOfStop() {
  auto server = startSim();
  auto robot = robotFor(*server);
  const std::array<double, 7> home = robot->receiveRobotState().q;
  auto moveBack = [&](const char* what) {
    try {
      robot->automaticErrorRecovery();
      robot->setMotorPower(1);
      MOVEJ(0.5, robot->receiveRobotState().q, home, *robot);
    } catch (const std::exception& e) {
      QFAIL(qPrintable(QStringLiteral("after %1: %2").arg(what).arg(e.what())));
    }
  };
  for (int round = 0; round < 3; ++round) {
    // A reflex: the callback jumps the command.
    robot->startMove(CM::kJointPosition, MM::kJointPosition);
    auto spin = spinJointOne();
    int calls = 0;
    QVERIFY_THROWS_EXCEPTION(ControlException, robot->Control(JointControl([&](RobotState s) {
      JointPositions out = spin(s);
      if (++calls > 400) out.q[0] += 0.05;
      return out;
    })));
    moveBack("a reflex");
    // A collision: a hard push in the middle of the motion.
    QVERIFY(!spinThenStop(*robot, [&] { server->setExternalWrench({300, 0, 0, 0, 0, 0}); }).isEmpty());
    server->setExternalWrench({0, 0, 0, 0, 0, 0});
    moveBack("a collision");
    // A guard stop, released at once.
    QVERIFY(!spinThenStop(*robot, [&] { server->setGuardStop(true); }).isEmpty());
    server->setGuardStop(false);
    moveBack("a guard stop");
    // stopMove() from another thread.
    QVERIFY(!spinThenStop(*robot, [&] { robot->stopMove(); }).isEmpty());
    moveBack("stopMove()");
  }
  // The end of hand guiding while the arm still moves: a MOVEJ at once.
  robot->startDrag(1, 3);
  server->setExternalWrench({0, 60, 0, 0, 0, 0});
  QVERIFY(eventually([&] { return std::abs(robot->receiveRobotState().dq_m[0]) > 0.05; }, 3000));
  server->setExternalWrench({0, 0, 0, 0, 0, 0});
  robot->stopDrag();
  moveBack("the end of hand guiding");
}

// A program reads the state right after the end of hand guiding, while the arm still comes to rest,
// and passes its q as the MOVEJ start a moment later: the arm moved on meanwhile (more than the 1e-3
// rad a start may be off), and the MOVEJ starts all the same. A start off by as much at rest is refused.
void TestMotionRequests::startReadWhileTheArmStillMovedIsAccepted() {
  auto server = startSim();
  auto robot = robotFor(*server);
  const std::array<double, 7> home = robot->receiveRobotState().q;
  robot->setMotorPower(1);
  robot->startDrag(1, 3);
  server->setExternalWrench({0, 60, 0, 0, 0, 0});
  QVERIFY(eventually([&] { return std::abs(robot->receiveRobotState().dq_m[0]) > 0.1; }, 3000));
  server->setExternalWrench({0, 0, 0, 0, 0, 0});
  robot->stopDrag();
  const RobotState read = robot->receiveRobotState();
  // Watched without receiveRobotState(), which would hand the program a newer state.
  auto movedSinceRead = [&] {
    RobotState now;
    robot->connection().latestState(now);
    return client::travelBetween(read, now, 7).joint_travel;
  };
  QVERIFY(eventually([&] { return movedSinceRead() > 2e-3; }, 1000));
  try {
    MOVEJ(0.5, read.q, home, *robot);
  } catch (const std::exception& e) {
    QFAIL(e.what());
  }
  std::array<double, 7> off = robot->receiveRobotState().q;
  off[0] += 2e-3;
  try {
    MOVEJ(0.5, off, home, *robot);
    QFAIL("a start 2e-3 rad off at rest was accepted");
  } catch (const MotionException& e) {
    QVERIFY2(says(e, "q_start[0]") && says(e, "pass the current state"), e.what());
  }
}

void TestMotionRequests::refusalsNameTheCauseThatHolds() {
  auto server = startSim();
  auto robot = robotFor(*server);
  const std::array<double, 7> q = robot->receiveRobotState().q;
  std::array<double, 7> target = q;
  target[0] += 0.1;
  auto refusal = [&]() -> std::string {
    try {
      MOVEJ(0.5, robot->receiveRobotState().q, target, *robot);
    } catch (const CommandException& e) {
      return e.what();
    }
    return "not refused";
  };
  const char* causes[] = {"hand guiding is on", "the motors are off", "guard stop", "emergency stop", "error bits"};
  auto only = [&](const std::string& text, const char* cause) {
    QVERIFY2(text.find(cause) != std::string::npos, text.c_str());
    for (const char* other : causes)
      if (std::string(other) != cause) QVERIFY2(text.find(other) == std::string::npos, text.c_str());
    QVERIFY2(text.find("stopDrag") == std::string::npos || std::string(cause) == "hand guiding is on", text.c_str());
  };
  robot->startDrag(1, 3);
  only(refusal(), "hand guiding is on");
  robot->stopDrag();
  robot->setMotorPower(0);
  only(refusal(), "the motors are off");
  robot->setMotorPower(1);
  server->setGuardStop(true);
  only(refusal(), "guard stop");
  server->setGuardStop(false);
  robot->automaticErrorRecovery();
  // The same words for hand guiding asked while the motors are off.
  robot->setMotorPower(0);
  try {
    robot->startDrag(1, 3);
    QFAIL("startDrag with the motors off was accepted");
  } catch (const CommandException& e) {
    only(e.what(), "the motors are off");
  }
  robot->setMotorPower(1);
}

void TestMotionRequests::targetsBeyondSoftLimitsAreRefusedBeforeMoving() {
  auto server = startSim();
  auto robot = robotFor(*server);
  const std::array<double, 7> q = robot->receiveRobotState().q;
  std::array<double, 7> upper{}, lower{};
  softLimitsAround(q, 30, upper, lower);
  upper[2] = q[2] / kDeg + 10;
  robot->setJointLimit(upper, lower, false);
  std::array<double, 7> target = q;
  target[2] += 20 * kDeg;
  for (int k = 0; k < 5; ++k) {
    try {
      MOVEJ(1.0, robot->receiveRobotState().q, target, *robot);
      QFAIL("a MOVEJ beyond a soft limit was started");
    } catch (const MotionException& e) {
      QVERIFY2(says(e, "joint 3 would reach") && says(e, "soft upper limit") && says(e, "at the target"), e.what());
    }
    QVERIFY(maxAbsDiff(robot->receiveRobotState().q, q) < 1e-4);
    QVERIFY(!server->status().sim.motion_active);
  }
  // Within the limits it moves.
  target[2] = q[2] + 5 * kDeg;
  MOVEJ(1.0, robot->receiveRobotState().q, target, *robot);
}

void TestMotionRequests::movingBackTowardsTheLimitsIsAllowed() {
  auto server = startSim();
  auto robot = robotFor(*server);
  const std::array<double, 7> q = robot->receiveRobotState().q;
  std::array<double, 7> upper{}, lower{};
  softLimitsAround(q, 30, upper, lower);
  robot->setJointLimit(upper, lower, false);
  std::array<double, 7> beyond = q;
  beyond[0] += 40 * kDeg;  // 10 deg beyond the soft upper limit of joint 1
  server->placeArm(beyond);
  QVERIFY(eventually([&] { return maxAbsDiff(robot->receiveRobotState().q, beyond) < 1e-4; }));
  std::array<double, 7> further = beyond, back = beyond;
  further[0] += 5 * kDeg;
  back[0] -= 5 * kDeg;  // still beyond the limit, but closer
  try {
    MOVEJ(0.5, robot->receiveRobotState().q, further, *robot);
    QFAIL("a MOVEJ further beyond a soft limit was started");
  } catch (const MotionException& e) {
    QVERIFY2(says(e, "joint 1 would reach") && says(e, "soft upper limit"), e.what());
  }
  MOVEJ(0.5, robot->receiveRobotState().q, back, *robot);
  MOVEJ(0.5, robot->receiveRobotState().q, q, *robot);
}

void TestMotionRequests::pathsLeavingTheSafetyBoxAreRefused() {
  auto server = startSim();
  auto robot = robotFor(*server);
  const RobotState s = robot->receiveRobotState();
  std::array<double, 16> frame{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  frame[3] = s.toolTobase_pos_m[3];
  frame[7] = s.toolTobase_pos_m[7];
  frame[11] = s.toolTobase_pos_m[11];
  robot->setCartesianLimit({0.2, 0.2, 0.2}, frame, true);  // 10 cm each way around the TCP
  cart_pos start, target;
  start.pos = target.pos = s.toolTobase_pos_m;
  target.pos[7] += 0.15;
  try {
    MOVEL(0.5, start, target, *robot);
    QFAIL("a MOVEL out of the safety box was started");
  } catch (const MotionException& e) {
    QVERIFY2(says(e, "through its +y face") && says(e, "0.100 m") && says(e, "at the target"), e.what());
  }
  std::array<double, 7> far = s.q;
  far[0] += 0.5;  // swings the TCP sideways, out of the box
  try {
    MOVEJ(0.5, s.q, far, *robot);
    QFAIL("a MOVEJ out of the safety box was started");
  } catch (const MotionException& e) {
    QVERIFY2(says(e, "the TCP would leave the safety box"), e.what());
  }
  QVERIFY(maxAbsDiff(robot->receiveRobotState().q, s.q) < 1e-4);
  target.pos[7] = s.toolTobase_pos_m[7] + 0.05;  // inside: moves
  start.pos = robot->receiveRobotState().toolTobase_pos_m;
  MOVEL(0.5, start, target, *robot);
}

void TestMotionRequests::executorChecksTheRobotsLimits() {
  auto server = startSim();
  auto robot = robotFor(*server);
  const std::array<double, 7> q = robot->receiveRobotState().q;
  std::array<double, 7> upper{}, lower{};
  softLimitsAround(q, 30, upper, lower);
  upper[3] = q[3] / kDeg + 5;
  robot->setJointLimit(upper, lower, false);
  teach::Program program;
  teach::Instruction move;
  move.type = teach::InstructionType::kMoveJ;
  move.name = "over";
  move.target.has_q = true;
  move.target.q = q;
  move.target.q[3] += 10 * kDeg;
  program.instructions.push_back(move);
  teach::Executor executor;
  const teach::RunReport report = executor.run(*robot, program);  // the options know no soft limits
  QVERIFY2(report.outcome == teach::RunState::kFailed, report.message.c_str());
  QVERIFY2(report.message.find("joint 4 would reach") != std::string::npos, report.message.c_str());
  QVERIFY(maxAbsDiff(robot->receiveRobotState().q, q) < 1e-4);
}

QTEST_GUILESS_MAIN(TestMotionRequests)
#include "test_motion_requests.moc"
