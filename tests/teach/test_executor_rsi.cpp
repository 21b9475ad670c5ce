// SPDX-License-Identifier: Apache-2.0
// The executor on a KUKA over RSI, end to end: rsi::Link + arm::JointStream against the simulated
// KRC (sim::KrcServer on its timed thread) on loopback. A program of MOVEJ, MOVEL and MOVEC on the
// KR 6 R900 sixx reaches its targets; a motion beyond the context's correction limits is refused
// before it moves, naming the axis, the limit and the value; RSI going off in the middle of a motion
// fails the instruction saying so; stop() brakes and ends the run. A PATH is replayed within 1 mrad
// after its lead-in, and refused before it moves when the correction limits do not allow it.
#include <QtTest>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <thread>

#include "model/arm_kinematics.h"
#include "model/robot_spec.h"
#include "../rsi/rsi_test_support.h"
#include "arm/rsi_arm.h"
#include "arm/joint_stream.h"
#include "rsi/link.h"
#include "sim/krc_server.h"
#include "teach/executor.h"
#include "teach/recording.h"
#include "demonstration.h"

using namespace xmate;
using namespace xmate::teach;
using teach_test::pathInstruction;

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

const model::RobotSpec& kr6() { return *model::findRobotSpec("kr6_r900_sixx"); }

// The PC side and a simulated KRC running `context` on loopback.
struct Cell {
  std::unique_ptr<arm::RsiArm> arm;  // as rci-cli run: link, joint stream and the wired IO
  std::unique_ptr<sim::KrcServer> krc;

  explicit Cell(const std::string& context) {
    const arm::RsiArmConfig config = rsi::testing::loopbackArm(context, 200);
    arm = std::make_unique<arm::RsiArm>(config);
    arm->start();
    krc = std::make_unique<sim::KrcServer>(rsi::testing::krcFor(config, arm->link().port(), false));
    krc->start();
    // As rci-cli run does: the program starts once RSI runs.
    arm::StreamState s;
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (!arm->stream().state(s) && std::chrono::steady_clock::now() < end)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ~Cell() {
    krc->stop();
    arm->stop();
  }
  // The joints the KRC's arm has (rad).
  std::array<double, 7> actual() const {
    const sim::KrcStatus s = krc->krc().status();
    std::array<double, 7> q{};
    for (size_t i = 0; i < 6; ++i) q[i] = s.q_deg[i] * kDeg;
    return q;
  }
  std::array<double, 7> start() const {
    const sim::KrcStatus s = krc->krc().status();
    std::array<double, 7> q{};
    for (size_t i = 0; i < 6; ++i) q[i] = s.start_deg[i] * kDeg;
    return q;
  }
};

Target jointsTarget(const std::array<double, 7>& q) {
  Target t;
  t.has_q = true;
  t.q = q;
  return t;
}

Target poseTarget(const std::array<double, 7>& q) {
  Target t;
  t.has_pose = true;
  t.pose = model::ArmKinematics(kr6()).GetCartPose(q);
  return t;
}

std::array<double, 7> offset(const std::array<double, 7>& q, const std::array<double, 6>& deg) {
  std::array<double, 7> out = q;
  for (size_t i = 0; i < 6; ++i) out[i] += deg[i] * kDeg;
  return out;
}

// Waits until the running instruction is `fraction` done (at most 20 s).
void waitForFraction(const Executor& executor, double fraction) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (executor.progress().fraction < fraction && std::chrono::steady_clock::now() < end)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
}

double maxDifference(const std::array<double, 7>& a, const std::array<double, 7>& b) {
  double m = 0;
  for (size_t i = 0; i < 6; ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

Program kukaProgram() {
  Program p;
  p.robot = &kr6();
  return p;
}

// A demonstration from q0 (teach_test::demonstration), each axis out by out_and_back[i] degrees
// and back.
JointPath demonstration(const std::array<double, 7>& q0, const std::array<double, 6>& out_and_back, double seconds) {
  std::array<double, 7> rad{};
  for (size_t i = 0; i < 6; ++i) rad[i] = out_and_back[i] * kDeg;
  return teach_test::demonstration(q0, rad, {}, seconds);
}

}  // namespace

class TestExecutorRsi : public QObject {
  Q_OBJECT

 private slots:
  void programReachesItsTargets();
  void beyondTheCorrectionLimitIsRefusedBeforeMoving();
  void rsiGoingOffFailsTheMotion();
  void stopBrakesAndEndsTheRun();
  void digitalSignalsGoThroughTheContext();
  void withoutWiredSignalsSetDoSaysSo();
  void pathIsReplayedOnTheSimulatedKrc();
  void pathBeyondTheCorrectionLimitsIsRefusedNamingItsTime();
};

void TestExecutorRsi::programReachesItsTargets() {
  Cell cell("resources/rsi/rci_replay.rsi.xml");
  const std::array<double, 7> home = cell.start();
  const std::array<double, 7> j1 = offset(home, {20, 10, -15, 30, -20, 45});
  const std::array<double, 7> l2 = offset(home, {25, 15, -25, 30, -10, 45});
  const std::array<double, 7> via = offset(home, {15, 20, -30, 30, -10, 45});
  const std::array<double, 7> c3 = offset(home, {5, 15, -25, 30, -10, 45});
  Program p = kukaProgram();
  p.instructions.push_back(moveJ(jointsTarget(j1), 0.5, "J1"));
  p.instructions.push_back(moveL(poseTarget(l2), 0.5, "L2"));
  p.instructions.push_back(moveC(poseTarget(via), poseTarget(c3), 0.5, "C3"));
  p.instructions.push_back(moveJ(jointsTarget(home), 1.0, "home"));

  Executor executor;
  const RunReport report = executor.run(*cell.arm, p, {});
  QVERIFY2(report.outcome == RunState::kFinished, report.message.c_str());
  const std::array<std::array<double, 7>, 4> expected{j1, l2, c3, home};
  for (size_t i = 0; i < expected.size(); ++i) {
    const InstructionReport& r = report.instructions[i];
    QCOMPARE(r.status, InstructionStatus::kDone);
    QVERIFY2(maxDifference(r.q, expected[i]) < 1e-4, qPrintable(QString("instruction %1").arg(i + 1)));
    QVERIFY(r.settled);
    QVERIFY(r.duration > 0);
  }
  QVERIFY(maxDifference(cell.actual(), home) < 1e-4);
  const sim::KrcStatus s = cell.krc->krc().status();
  QCOMPARE(s.last_stop, sim::KrcStop::kNone);  // no clamp, monitor or timeout stopped RSI
  QCOMPARE(s.session, 1u);
}

void TestExecutorRsi::beyondTheCorrectionLimitIsRefusedBeforeMoving() {
  Cell cell("resources/rsi/rci_axis_corr.rsi.xml");  // +-5 deg
  const std::array<double, 7> home = cell.start();
  Program p = kukaProgram();
  p.instructions.push_back(moveJ(jointsTarget(offset(home, {3, 0, 0, 0, 0, 0})), 0.5, "near"));
  p.instructions.push_back(moveJ(jointsTarget(offset(home, {3, 0, 0, 0, 12, 0})), 0.5, "far"));
  Executor executor;
  const RunReport report = executor.run(*cell.arm, p, {});
  QCOMPARE(report.outcome, RunState::kFailed);
  QCOMPARE(report.failed_instruction, 1L);
  const QString message = QString::fromStdString(report.message);
  QVERIFY2(message.startsWith("instruction 2 (MOVEJ \"far\"): A5 would need a correction of") &&
               message.contains("beyond AXISCORR1's UpperLimA5 = 5.0 deg"),
           qPrintable(message));
  // It stayed where "near" left it.
  QVERIFY(maxDifference(cell.actual(), offset(home, {3, 0, 0, 0, 0, 0})) < 1e-4);
}

void TestExecutorRsi::rsiGoingOffFailsTheMotion() {
  Cell cell("resources/rsi/rci_replay.rsi.xml");
  const std::array<double, 7> home = cell.start();
  Program p = kukaProgram();
  p.instructions.push_back(moveJ(jointsTarget(offset(home, {80, 0, 0, 0, 0, 0})), 0.1, "slow"));
  Executor executor;
  std::thread operator_thread([&] {
    waitForFraction(executor, 0.2);
    cell.krc->krc().suspendSending(3000);  // RSI off without a timeout, e.g. the KRL program ended
  });
  const RunReport report = executor.run(*cell.arm, p, {});
  operator_thread.join();
  QCOMPARE(report.outcome, RunState::kFailed);
  QVERIFY2(QString::fromStdString(report.message).startsWith("instruction 1 (MOVEJ \"slow\"): RSI stopped during the motion"),
           report.message.c_str());
}

void TestExecutorRsi::stopBrakesAndEndsTheRun() {
  Cell cell("resources/rsi/rci_replay.rsi.xml");
  const std::array<double, 7> home = cell.start();
  const std::array<double, 7> far = offset(home, {80, 0, 0, 0, 0, 0});
  Program p = kukaProgram();
  p.instructions.push_back(moveJ(jointsTarget(far), 0.3, "far"));
  p.instructions.push_back(moveJ(jointsTarget(home), 0.3, "back"));
  Executor executor;
  std::thread operator_thread([&] {
    waitForFraction(executor, 0.3);
    executor.stop();
  });
  const RunReport report = executor.run(*cell.arm, p, {});
  operator_thread.join();
  QVERIFY2(report.outcome == RunState::kStopped, report.message.c_str());
  QCOMPARE(report.instructions[0].status, InstructionStatus::kStopped);
  QCOMPARE(report.instructions[1].status, InstructionStatus::kNotRun);
  // Stopped on the way: past where stop() was asked, short of the target, and at rest there.
  const double a1 = cell.actual()[0] - home[0];
  QVERIFY2(a1 > 0.3 * 80 * kDeg && a1 < 80 * kDeg - 1e-3, qPrintable(QString::number(a1 / kDeg)));
  QVERIFY(report.instructions[0].settled);
}

// SET_DO sets the KRC's $OUT through DIGOUT1, WAIT_DI waits for $IN through DIGIN1, and a signal
// the context does not wire fails its instruction naming the ones it does.
void TestExecutorRsi::digitalSignalsGoThroughTheContext() {
  Cell cell("resources/rsi/rci_replay.rsi.xml");
  Program p = kukaProgram();
  Instruction on;
  on.type = InstructionType::kSetDo;
  on.signal = 3;
  on.value = true;
  Instruction wait;
  wait.type = InstructionType::kWaitDi;
  wait.signal = 2;
  wait.value = true;
  wait.timeout_ms = 10000;
  Instruction unwired = on;
  unwired.signal = 20;
  p.instructions = {on, wait, unwired};
  Executor executor;
  std::thread operator_thread([&] {
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (executor.progress().instruction < 1 && std::chrono::steady_clock::now() < end)
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    std::this_thread::sleep_for(std::chrono::milliseconds(100));  // it is waiting now
    cell.krc->krc().setDigitalInput(2, true);
  });
  const RunReport report = executor.run(*cell.arm, p, {});
  operator_thread.join();
  QCOMPARE(report.instructions[0].status, InstructionStatus::kDone);
  QCOMPARE(report.instructions[1].status, InstructionStatus::kDone);
  QVERIFY2(report.instructions[1].duration >= 0.1, qPrintable(QString::number(report.instructions[1].duration)));
  QVERIFY(cell.krc->krc().status().digout & (1u << 2));  // $OUT[3]
  QCOMPARE(report.outcome, RunState::kFailed);
  QCOMPARE(report.failed_instruction, 2L);
  QVERIFY2(QString::fromStdString(report.message)
               .contains("$OUT[20] is not wired to the PC in the RSI context (wired to the PC: $OUT[1], $OUT[2]"),
           report.message.c_str());
}

void TestExecutorRsi::withoutWiredSignalsSetDoSaysSo() {
  Cell cell("resources/rsi/rci_axis_corr.rsi.xml");  // no DIGIN / DIGOUT
  QVERIFY(!cell.arm->digitalIo());
  Program p = kukaProgram();
  Instruction on;
  on.type = InstructionType::kSetDo;
  on.signal = 1;
  on.value = true;
  p.instructions = {on};
  Executor executor;
  const RunReport report = executor.run(*cell.arm, p, {});
  QCOMPARE(report.outcome, RunState::kFailed);
  QVERIFY2(QString::fromStdString(report.message).contains("the RSI context wires no digital inputs or outputs to the PC"),
           report.message.c_str());
}

// A PATH from elsewhere: the joint move to its start, then the path at the demonstrated pace and at
// half of it, within 1 mrad of the demonstration and with no stop of RSI.
void TestExecutorRsi::pathIsReplayedOnTheSimulatedKrc() {
  Cell cell("resources/rsi/rci_replay.rsi.xml");
  // A brisk sweep: 20 to 40 deg out and back in 2 s on every axis.
  const JointPath path = demonstration(offset(cell.start(), {10, 5, -5, 0, 0, 0}), {20, 10, -15, 25, -20, 40}, 2.0);
  Program p = kukaProgram();
  p.instructions.push_back(pathInstruction(path, 1.0, "sweep"));
  p.instructions.push_back(pathInstruction(path, 0.5, "again"));
  // The fastest joint of the demonstration (rad/s) at its own pace.
  double fastest = 0;
  for (size_t k = 1; k < path.q.size(); ++k) fastest = std::max(fastest, maxDifference(path.q[k], path.q[k - 1]) * path.rate_hz);
  const uint64_t late_before = cell.krc->krc().status().answers_late;
  Executor executor;
  const RunReport report = executor.run(*cell.arm, p, {});
  // An answer this machine did not send in time (a busy or sanitised test box) leaves the arm one
  // RSI cycle behind the path for that cycle: a real deviation, which the report shows and the
  // tolerance allows (the fastest joint's travel in one cycle, per late answer).
  const uint64_t late = cell.krc->krc().status().answers_late - late_before;
  const double allowance = 1e-3 + double(late) * fastest * cell.arm->cycleSeconds();
  QVERIFY2(report.outcome == RunState::kFinished, report.message.c_str());
  QCOMPARE(report.notices.size(), size_t(1));
  QVERIFY2(report.notices[0].message ==
               "instruction 1 (PATH \"sweep\"): first moves to the start of the path with a joint move (largest joint "
               "change 10.0 deg)",
           report.notices[0].message.c_str());
  for (size_t i = 0; i < 2; ++i) {
    const InstructionReport& r = report.instructions[i];
    qInfo("%s: %.3f s (nominal %.3f s), lead-in %.3f s, deviation %.3f mrad / %.3f mm (%llu late answers in the run)",
          i ? "again" : "sweep", r.duration, r.nominal_duration, r.lead_in, r.path_joint_deviation * 1e3,
          r.path_tcp_deviation * 1e3, static_cast<unsigned long long>(late));
    QCOMPARE(r.status, InstructionStatus::kDone);
    QVERIFY2(r.path_joint_deviation > 0 && r.path_joint_deviation < allowance,
             qPrintable(QString("%1 rad (allowed %2 with %3 late answers)").arg(r.path_joint_deviation).arg(allowance).arg(late)));
    QVERIFY(r.duration > 0.98 * r.nominal_duration && r.duration < 1.05 * r.nominal_duration + 0.05);
    QVERIFY(maxDifference(r.q, path.q.back()) < 1e-4);
    QVERIFY(r.settled);
  }
  QVERIFY(report.instructions[0].lead_in > 0.1);
  QCOMPARE(report.instructions[1].lead_in, 0.0);  // the first ended where the second starts
  QCOMPARE(cell.krc->krc().status().last_stop, sim::KrcStop::kNone);
}

// The context lets A5 move 5 deg from where RSI was switched on; a path that takes it 12 deg out is
// refused before anything moves, naming the first sample beyond the limit by its time in the path.
void TestExecutorRsi::pathBeyondTheCorrectionLimitsIsRefusedNamingItsTime() {
  Cell cell("resources/rsi/rci_axis_corr.rsi.xml");
  const std::array<double, 7> home = cell.start();
  const JointPath path = demonstration(home, {0, 0, 0, 0, 12, 0}, 2.0);
  size_t first = 0;
  while (path.q[first][4] - home[4] <= 5 * kDeg + 1e-9) ++first;
  Program p = kukaProgram();
  p.instructions.push_back(pathInstruction(path, 1.0, "reach"));
  Executor executor;
  const RunReport report = executor.run(*cell.arm, p, {});
  QCOMPARE(report.outcome, RunState::kRefused);
  QCOMPARE(report.problems.size(), size_t(1));
  char expected[160];
  std::snprintf(expected, sizeof expected,
                "instruction 1 (PATH \"reach\"): at t = %.3f s of the path (sample %zu): A5 at %.2f deg is outside what "
                "this session can reach",
                double(first) / 100, first, path.q[first][4] / kDeg);
  QVERIFY2(QString::fromStdString(report.message).contains(expected), qPrintable(QString::fromStdString(report.message) + "\nexpected: " + expected));
  QVERIFY(maxDifference(cell.actual(), home) < 1e-6);  // nothing moved
}

QTEST_GUILESS_MAIN(TestExecutorRsi)
#include "test_executor_rsi.moc"
