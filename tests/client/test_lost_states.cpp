// SPDX-License-Identifier: Apache-2.0
// Lost states on the simulator's real-time clock, as on a PC without a real-time kernel: the
// simulator drops 1, 2 or 3 states in a row at chosen points of a motion (and at random, 2 %, while
// several motions run), and MOVEJ, MOVEL and MOVEC at speed 1.0, the teach executor (MOVEJ and
// PATH) and the vendor manual's programs -- callbacks that keep time with `time += 0.001` per call
// -- all complete without an error bit. Robot::Control calls the callback once for every missed
// message_id, in order, before it answers the newest state. A stop after a stall of the machine
// (the client's thread not run for 15 ms or more) is repeated, within a budget (MachineStalls).
#include <QtTest>

#include <atomic>
#include <cmath>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include <xmate/joint_motion.h>
#include <xmate/move.h>
#include <xmate/robot.h>

#include "client_test_support.h"
#include "teach/executor.h"
#include "teach/path.h"
#include "teach/program.h"

using namespace xmate;
using namespace client_test;
using RCI::robot::RobotState;
using CM = RCI::robot::StartMoveRequest::ControllerMode;
using MM = RCI::robot::StartMoveRequest::MotionGeneratorMode;

namespace {

constexpr double kJointTolerance = 1e-4;     // rad
constexpr double kPositionTolerance = 1e-4;  // m
// Where in the motion states are dropped: ms after the simulator reports it running. 3 hits the
// first jerk phase; 100-180 the end of the acceleration of a 1 s MOVEJ at full speed (the command
// near its top velocity with acceleration left: the hardest place to bridge); the rest cruise and
// braking.
const int kLossPoints[] = {3, 60, 100, 140, 180, 400, 700};
const int kLossRuns[] = {1, 2, 3};

SimOptions realTimeClock() {
  SimOptions o;
  o.clock = sim::ClockMode::kRealTime;
  return o;
}

bool settlesAt(Robot& robot, const std::array<double, 7>& q) {
  return eventually([&] { return maxAbsDiff(robot.receiveRobotState().q, q) < kJointTolerance; }, 3000);
}

// Runs `move` while the simulator drops `run` states in a row `at_ms` into the motion; "" when the
// move completed, else what went wrong.
template <class Move>
QString moveWithLoss(sim::Server& server, int at_ms, int run, Move&& move) {
  const QString what = QStringLiteral("%1 states lost at %2 ms: ").arg(run).arg(at_ms);
  try {
    DuringMotion loss(server, [&server, run] { server.dropStates(run); }, at_ms);
    move();
  } catch (const std::exception& e) {
    return what + e.what();
  }
  return {};
}

// moveWithLoss, repeated from where it began after a stop the machine caused (MachineStalls).
template <class Move>
QString moveWithLossExcused(Robot& robot, sim::Server& server, MachineStalls& stalls, int at_ms, int run, Move&& move) {
  return QString::fromStdString(excusingMachineStalls(robot, stalls, 0, [&] {
    return moveWithLoss(server, at_ms, run, move).toStdString();
  }));
}

// What `call` threw, or "" (for excusingMachineStalls).
template <class Call>
std::string failureOf(Call&& call) {
  try {
    call();
  } catch (const std::exception& e) {
    return e.what();
  }
  return {};
}

// Random loss of 2 % of the states (a third of them in pairs) until destroyed.
struct RandomLoss {
  sim::Server& server;
  explicit RandomLoss(sim::Server& s, uint32_t seed) : server(s) {
    sim::StateLoss loss;
    loss.probability = 0.02;
    loss.pair_share = 0.3;
    loss.seed = seed;
    server.setStateLoss(loss);
  }
  ~RandomLoss() { server.setStateLoss(sim::StateLoss{}); }
};

// Two poses about 1 s apart at full speed: joints 1, 2 and 4 move together.
std::array<double, 7> awayFrom(const std::array<double, 7>& home) {
  std::array<double, 7> away = home;
  away[0] += 1.2;
  away[1] += 0.4;
  away[3] -= 0.6;
  return away;
}

// The vendor manual's joint program (section 2.5): a synchronised S-curve to a goal, its clock a
// counter of callback calls.
void manualJointProgram(Robot& robot, const std::array<double, 7>& goal) {
  JointMotionGenerator generator(0.5, goal, robot.type());
  std::array<double, 7> init_position{}, joint_delta{};
  bool init = true;
  double time = 0;
  robot.startMove(CM::kJointPosition, MM::kJointPosition);
  robot.Control(JointControl([&](RobotState s) -> JointPositions {
    time += 0.001;
    if (init) {
      init_position = s.q;
      init = false;
    }
    generator.calculateSynchronizedValues_joint(init_position);
    JointPositions output{};
    const bool finished = generator.calculateDesiredValues_joint(time, joint_delta);
    for (int i = 0; i < 7; ++i) output.q[i] = init_position[i] + joint_delta[i];
    return finished ? MotionFinished(output) : output;
  }));
}

// The vendor manual's Cartesian program (section 2.5.1): the TCP's height along the arc of 0.2 m
// radius (z only, as in the manual), its clock a counter of callback calls; here for `seconds` (the
// manual's runs until stopped).
void manualCartesianProgram(Robot& robot, double seconds) {
  std::array<double, 16> init_position{};
  double init_psi = 0;
  bool init = true;
  double time = 0;
  robot.startMove(CM::kCartesianPosition, MM::kCartesianPosition);
  robot.Control(CartesianControl([&](RobotState s) -> CartesianPose {
    time += 0.001;
    if (init) {
      init_position = s.toolTobase_pos_m;
      init_psi = s.psi_m;
      init = false;
    }
    constexpr double kRadius = 0.2;
    const double angle = M_PI / 4 * (1 - std::cos(M_PI / 5 * time));
    CartesianPose output{};
    output.toolTobase_pos_c = init_position;
    output.toolTobase_pos_c[11] += kRadius * (std::cos(angle) - 1);
    output.psi_c = init_psi;
    return time >= seconds - 1e-9 ? MotionFinished(output) : output;
  }));
}

// A torque program in the manual's style: a small sinusoidal torque on the last joint on top of
// the controller's gravity compensation, for `seconds`.
void manualTorqueProgram(Robot& robot, double seconds) {
  double time = 0;
  robot.startMove(CM::kTorque, MM::kIdle);
  robot.Control(TorqueControl([&](RobotState) -> Torques {
    time += 0.001;
    Torques output{};
    output.tau[6] = 0.5 * std::sin(2 * M_PI * time) * std::sin(M_PI * time / seconds);
    return time >= seconds - 1e-9 ? MotionFinished(output) : output;
  }));
}

teach::Program pathProgram(const std::array<double, 7>& home) {
  teach::Program program;
  teach::Instruction path;
  path.type = teach::InstructionType::kPath;
  path.name = "wave";
  path.speed = 1.0;
  path.path.rate_hz = 100;
  for (int k = 0; k <= 150; ++k) {  // 1.5 s: joints 1 and 4 out and back
    std::array<double, 7> q = home;
    const double s = 0.5 * (1 - std::cos(2 * M_PI * k / 150.0));
    q[0] += 0.8 * s;
    q[3] -= 0.5 * s;
    path.path.q.push_back(q);
  }
  program.instructions.push_back(path);
  return program;
}

}  // namespace

class TestLostStates : public QObject {
  Q_OBJECT

 private slots:
  void controlCallsTheCallbackForEveryMissedState();
  void movejAtFullSpeedThroughLostStates();
  void movelAndMovecAtFullSpeedThroughLostStates();
  void manualProgramsThroughLostStates();
  void executorThroughLostStates();
  void randomLossAtFullSpeed();
  void heavyLossOnTheLockStepClock();
  void handGuidingIntoTheWallsAndBackThroughLostStates();
};

void TestLostStates::controlCallsTheCallbackForEveryMissedState() {
  auto server = startSim(realTimeClock());
  auto robot = robotFor(*server);
  std::vector<uint64_t> ids;
  ids.reserve(2000);
  robot->startMove(CM::kJointPosition, MM::kJointPosition);
  {
    DuringMotion loss(*server, [&] { server->dropStates(3); }, 100);
    DuringMotion again(*server, [&] { server->dropStates(1); }, 300);
    robot->Control(JointControl([&, start = std::array<double, 7>{}](RobotState s) mutable -> JointPositions {
      if (ids.empty()) start = s.q;
      ids.push_back(s.message_id);
      JointPositions out{start, false};
      return ids.size() >= 600 ? MotionFinished(out) : out;
    }));
  }
  QVERIFY(server->status().counters.states_dropped >= 4);
  for (size_t k = 1; k < ids.size(); ++k)
    QVERIFY2(ids[k] == ids[k - 1] + 1, qPrintable(QStringLiteral("call %1 saw message_id %2 after %3")
                                                       .arg(k)
                                                       .arg(ids[k])
                                                       .arg(ids[k - 1])));
}

void TestLostStates::movejAtFullSpeedThroughLostStates() {
  auto server = startSim(realTimeClock());
  auto robot = robotFor(*server);
  const std::array<double, 7> home = robot->receiveRobotState().q;
  const std::array<double, 7> away = awayFrom(home);
  MachineStalls stalls;
  bool forth = true;
  for (int at : kLossPoints)
    for (int run : kLossRuns) {
      const std::array<double, 7>& target = forth ? away : home;
      const QString failure = moveWithLossExcused(*robot, *server, stalls, at, run, [&] {
        MOVEJ(1.0, robot->receiveRobotState().q, target, *robot);
      });
      SKIP_IF_THE_MACHINE_STALLED(stalls);
      QVERIFY2(failure.isEmpty(), qPrintable(failure));
      QVERIFY(settlesAt(*robot, target));
      forth = !forth;
    }
}

void TestLostStates::movelAndMovecAtFullSpeedThroughLostStates() {
  auto server = startSim(realTimeClock());
  auto robot = robotFor(*server);
  cart_pos home, away, mid;
  home.pos = robot->receiveRobotState().toolTobase_pos_m;
  away = mid = home;
  away.pos[3] += 0.15;  // a quarter circle of 0.15 m radius in the x-z plane, centred 0.15 m below home
  away.pos[11] -= 0.15;
  mid.pos[3] += 0.15 * std::sqrt(0.5);
  mid.pos[11] -= 0.15 * (1 - std::sqrt(0.5));
  MachineStalls stalls;
  bool forth = true;
  for (int at : kLossPoints)
    for (int run : kLossRuns) {
      cart_pos start, target = forth ? away : home;
      start.pos = robot->receiveRobotState().toolTobase_pos_m;
      const bool arc = (at + run) % 2 == 0;
      const QString failure = moveWithLossExcused(*robot, *server, stalls, at, run, [&] {
        if (arc) {
          cart_pos via = mid;
          MOVEC(1.0, start, via, target, *robot);
        } else {
          MOVEL(1.0, start, target, *robot);
        }
      });
      SKIP_IF_THE_MACHINE_STALLED(stalls);
      QVERIFY2(failure.isEmpty(), qPrintable((arc ? "MOVEC, " : "MOVEL, ") + failure));
      QVERIFY(eventually([&] {
        return distance(robot->receiveRobotState().toolTobase_pos_m, target.pos) < kPositionTolerance;
      }, 3000));
      forth = !forth;
    }
}

void TestLostStates::manualProgramsThroughLostStates() {
  auto server = startSim(realTimeClock());
  auto robot = robotFor(*server);
  const std::array<double, 7> home = robot->receiveRobotState().q;
  std::array<double, 7> goal = home;
  goal[0] += 0.5;
  goal[3] -= 0.3;
  RandomLoss loss(*server, 11);
  MachineStalls stalls;
  const std::function<void()> programs[] = {
      [&] { manualJointProgram(*robot, goal); },
      [&] { manualJointProgram(*robot, home); },
      [&] { manualCartesianProgram(*robot, 10.0); },  // one period: down and back up to rest
      [&] { manualTorqueProgram(*robot, 1.0); },
  };
  for (const auto& program : programs) {
    const std::string failure = excusingMachineStalls(*robot, stalls, 0, [&] { return failureOf(program); });
    SKIP_IF_THE_MACHINE_STALLED(stalls);
    QVERIFY2(failure.empty(), failure.c_str());
  }
  QVERIFY(server->status().counters.states_lost > 0);
}

void TestLostStates::executorThroughLostStates() {
  auto server = startSim(realTimeClock());
  auto robot = robotFor(*server);
  const std::array<double, 7> home = robot->receiveRobotState().q;
  const teach::Program program = pathProgram(home);
  teach::Executor executor;
  MachineStalls stalls;
  for (int at : {3, 150, 500, 900})
    for (int run : kLossRuns) {
      const std::string failure = excusingMachineStalls(*robot, stalls, 0, [&]() -> std::string {
        DuringMotion loss(*server, [&] { server->dropStates(run); }, at);
        const teach::RunReport report = executor.run(*robot, program);
        return report.outcome == teach::RunState::kFinished ? std::string() : report.message;
      });
      SKIP_IF_THE_MACHINE_STALLED(stalls);
      QVERIFY2(failure.empty(), qPrintable(QStringLiteral("%1 lost at %2 ms: %3").arg(run).arg(at).arg(
                                    QString::fromStdString(failure))));
    }
}

void TestLostStates::randomLossAtFullSpeed() {
  auto server = startSim(realTimeClock());
  auto robot = robotFor(*server);
  const std::array<double, 7> home = robot->receiveRobotState().q;
  const std::array<double, 7> away = awayFrom(home);
  RandomLoss loss(*server, 7);
  MachineStalls stalls;
  for (int k = 0; k < 10; ++k) {
    const std::array<double, 7>& target = k % 2 == 0 ? away : home;
    const std::string failure = excusingMachineStalls(*robot, stalls, 0, [&] {
      return failureOf([&] { MOVEJ(1.0, robot->receiveRobotState().q, target, *robot); });
    });
    SKIP_IF_THE_MACHINE_STALLED(stalls);
    QVERIFY2(failure.empty(), qPrintable(QStringLiteral("MOVEJ %1: %2").arg(k).arg(failure.c_str())));
    QVERIFY(settlesAt(*robot, target));
  }
  QVERIFY(server->status().counters.states_lost > 0);
}

// Lock-step clock (states lost, never late), 5 % lost at random with pairs and a burst of 5 every
// 300 ms: MOVEJ, MOVEL and MOVEC at full speed with the soak's strokes, over several loss patterns.
// Every command stays within the limits, whatever the gaps fall on.
void TestLostStates::heavyLossOnTheLockStepClock() {
  SimOptions o;
  o.lockstep_timeout_ms = 50;
  auto server = startSim(o);
  auto robot = robotFor(*server);
  const std::array<double, 7> home = robot->receiveRobotState().q;
  std::array<double, 7> away = home;
  const std::array<double, 7> stroke{0.4, 0.25, -0.3, 0.35, 0.3, -0.3, 0.5};
  for (int i = 0; i < 7; ++i) away[i] += stroke[i];
  auto shifted = [](const cart_pos& from, double dx, double dy, double dz) {
    cart_pos to = from;
    to.pos[3] += dx;
    to.pos[7] += dy;
    to.pos[11] += dz;
    return to;
  };
  auto here = [&] {
    cart_pos p;
    p.pos = robot->receiveRobotState().toolTobase_pos_m;
    return p;
  };
  for (uint32_t seed = 1; seed <= 6; ++seed) {
    sim::StateLoss loss;
    loss.probability = 0.05;
    loss.pair_share = 0.3;
    loss.burst_states = 5;
    loss.burst_every_ms = 300;
    loss.seed = seed;
    server->setStateLoss(loss);
    for (int k = 0; k < 10; ++k) {
      try {
        MOVEJ(1.0, robot->receiveRobotState().q, k % 2 == 0 ? away : home, *robot);
        if (k % 2 == 0) continue;
        cart_pos start = here(), end = shifted(start, 0.08, 0.06, -0.1);
        MOVEL(1.0, start, end, *robot);
        start = here(), end = shifted(start, -0.08, -0.06, 0.1);
        MOVEL(1.0, start, end, *robot);
        start = here();
        cart_pos via = shifted(start, 0.08, 0, -0.08);
        end = shifted(start, 0, 0, -0.16);
        MOVEC(1.0, start, via, end, *robot);
        start = here(), via = shifted(start, 0.08, 0, 0.08), end = shifted(start, 0, 0, 0.16);
        MOVEC(1.0, start, via, end, *robot);
      } catch (const std::exception& e) {
        QFAIL(qPrintable(QStringLiteral("loss pattern %1, stroke %2: %3").arg(seed).arg(k).arg(e.what())));
      }
    }
  }
  QVERIFY(server->status().counters.loss_bursts > 0);
}

// Hand guiding on the real-time clock under 2 % random loss: from q = (0, 30, 0, 60, 0, 90, 0) deg a
// steady 60 N push along -x (towards the J1 axis, into the wrist-axis wall and the arm angle's
// limit) in Cartesian and then in joint guiding raises no error bit; after each the arm comes to
// rest, guiding ends and a MOVEJ takes it back to where it started.
void TestLostStates::handGuidingIntoTheWallsAndBackThroughLostStates() {
  constexpr double kDeg = M_PI / 180.0;
  auto server = startSim(realTimeClock());
  const std::array<double, 7> start{0, 30 * kDeg, 0, 60 * kDeg, 0, 90 * kDeg, 0};
  server->placeArm(start);
  auto robot = robotFor(*server);
  RandomLoss loss(*server, 5);
  for (int space : {2, 1}) {  // Cartesian, then joint guiding; free (translation and rotation)
    robot->startDrag(space, 3);
    server->setExternalWrench({-60, 0, 0, 0, 0, 0});
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(3);
    while (std::chrono::steady_clock::now() < until) {
      const RobotState s = robot->receiveRobotState();
      QVERIFY2(!anyError(s), qPrintable(QStringLiteral("guiding space %1: error bits while pushed").arg(space)));
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    server->setExternalWrench({});
    QVERIFY(maxAbsDiff(robot->receiveRobotState().q, start) > 0.05);  // the push moved the arm
    robot->stopDrag();
    MOVEJ(0.5, robot->receiveRobotState().q, start, *robot);  // waits for standstill first
    QVERIFY(settlesAt(*robot, start));
  }
  QVERIFY(server->status().counters.states_lost > 0);
}

QTEST_GUILESS_MAIN(TestLostStates)
#include "test_lost_states.moc"
