// SPDX-License-Identifier: Apache-2.0
// The jog's generators without a window: the joint jog's commands on a perfectly tracking arm (rate
// limits, braking before a limit, advancing by elapsed cycles), the RSI correction limits, the
// joint and Cartesian jog against the simulator on its real-time clock while it drops states, and
// both jogs through arm::Arm on both families (what the window's Jog panel runs).
#include <QtTest>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <thread>
#include <type_traits>
#include <utility>

#include <xmate/robot.h>

#include "../rsi/rsi_test_support.h"
#include "arm/rci_arm.h"
#include "arm/rsi_arm.h"
#include "client_test_support.h"
#include "jog/jog.h"
#include "model/arm_kinematics.h"
#include "model/robot_spec.h"
#include "sim/krc_server.h"
#include "sim/server.h"

using namespace xmate;
using namespace xmate::jog;

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

// The jog's watch (called each cycle of the motion) that releases it after `cycles` cycles, as the
// operator lets go of the button -- counted from the motion's first cycle, however long it waited
// for the arm to stand still before it started.
std::function<void()> releaseAfter(JogFlags& flags, int cycles) {
  return [&flags, cycles, n = 0]() mutable {
    if (++n >= cycles) flags.held.store(false);
  };
}

// Runs a jog; returns what ended it ("" when it ended by itself, at rest).
template <class Run>
QString jogUntilReleased(Run run) {
  try {
    run();
  } catch (const std::exception& e) {
    return e.what();
  }
  return QString();
}

}  // namespace

class TestJog : public QObject {
  Q_OBJECT

 private slots:
  void jointJogBrakesBeforeLimit();
  void jointJogAdvancesByElapsedCycles();
  void correctionLimitsNarrowJogLimits();
  void jogsKeepGoingThroughLostStates();
  void jogsThroughTheArmOfAnXmate();
  void jogsThroughTheArmOfAKuka();
};

void TestJog::jointJogBrakesBeforeLimit() {
  // The command sequence on a perfectly tracking arm: within the SPEC rate limits, stops before the
  // limit while held, ends with MotionFinished at rest after release.
  const auto& spec = model::robotSpec(XMATE7_PRO);
  std::array<double, 7> lower_deg{}, upper_deg{};
  for (int i = 0; i < 7; ++i) {
    lower_deg[i] = -90;
    upper_deg[i] = 30;
  }
  const JointLimitsRad limits = jogLimits(spec, true, lower_deg, upper_deg);
  JogFlags flags;
  JointJog jog(spec, 1, +1, 1.0, limits, flags);
  RCI::robot::RobotState state{};
  state.q[1] = 0.0;
  double v_prev = 0, a_prev = 0, q_prev = 0;
  double max_v = 0, max_a = 0, max_j = 0;
  bool finished = false;
  for (int cycle = 0; cycle < 20000 && !finished; ++cycle) {
    if (cycle == 8000) flags.held.store(false);
    const JointPositions cmd = jog.next(state);
    finished = cmd.motion_finished;
    const double v = (cmd.q[1] - q_prev) / 0.001, a = (v - v_prev) / 0.001, j = (a - a_prev) / 0.001;
    if (cycle > 0) {
      max_v = std::max(max_v, std::abs(v));
      max_a = std::max(max_a, std::abs(a));
      max_j = std::max(max_j, std::abs(j));
    }
    QVERIFY(cmd.q[1] <= limits.upper[1] + 1e-9);
    q_prev = cmd.q[1];
    v_prev = v;
    a_prev = a;
    state.q = cmd.q;
  }
  QVERIFY(finished);
  QVERIFY(q_prev > limits.upper[1] - 0.01);  // it got close to the limit
  QVERIFY(max_v <= spec.dq_max[1] + 1e-9);
  QVERIFY(max_a <= spec.ddq_max[1] + 1e-6);
  QVERIFY(max_j <= spec.jerk_max[1]);
  QVERIFY(std::abs(v_prev) < 1e-9);
}

void TestJog::jointJogAdvancesByElapsedCycles() {
  // A lost state (message_id 150 never arrives) must not shift the plan: at message_id 151 the jog
  // commands what it would have without the loss -- the controller extrapolated the lost command.
  const auto& spec = model::robotSpec(XMATE7_PRO);
  const JointLimitsRad limits = jogLimits(spec, false, {}, {});
  JogFlags flags_a, flags_b;
  JointJog every(spec, 0, +1, 0.5, limits, flags_a), lossy(spec, 0, +1, 0.5, limits, flags_b);
  RCI::robot::RobotState state{};
  JointPositions a{}, b{};
  for (uint64_t id = 100; id <= 300; ++id) {
    state.message_id = id;
    a = every.next(state);
    if (id != 150) b = lossy.next(state);
    if (id == 151) QCOMPARE(b.q[0], a.q[0]);
  }
  QVERIFY(a.q[0] > 0.001);  // it was moving
  QCOMPARE(b.q[0], a.q[0]);
}

// The joint and the Cartesian jog against the simulator on its real-time clock while it drops 2 % of
// its states (a third in pairs) and three in a row now and then: each jog ramps up, runs, ramps down
// after the release and ends without an error bit.
void TestJog::jogsKeepGoingThroughLostStates() {
  using CM = RCI::robot::StartMoveRequest::ControllerMode;
  using MM = RCI::robot::StartMoveRequest::MotionGeneratorMode;
  sim::ServerConfig config;
  config.bind_ip = "127.0.0.1";
  config.port = 0;
  config.clock = sim::ClockMode::kRealTime;
  sim::Server server(config);
  server.start();
  sim::StateLoss loss;
  loss.probability = 0.02;
  loss.pair_share = 0.3;
  loss.seed = 5;
  server.setStateLoss(loss);
  Robot robot("127.0.0.1", server.port(), XMATE7_PRO);
  robot.setMotorPower(1);
  const auto& spec = model::robotSpec(XMATE7_PRO);
  const JointLimitsRad limits = jogLimits(spec, false, {}, {});
  auto releaseLater = [&server](JogFlags& flags) {
    return std::thread([&server, &flags] {
      for (int k = 0; k < 4; ++k) {
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
        server.dropStates(3);
      }
      flags.held.store(false);
    });
  };
  // One jog, released after 0.8 s (with 3 states in a row dropped every 0.2 s); "" when it ended at
  // rest, else what stopped it.
  auto jogOnce = [&](auto make_jog, CM controller, MM generator) -> std::string {
    JogFlags flags;
    auto jog = make_jog(flags);
    std::thread release = releaseLater(flags);
    std::string failure;
    try {
      robot.startMove(controller, generator);
      if constexpr (std::is_same_v<decltype(jog), JointJog>)
        robot.Control(JointControl([&jog](RCI::robot::RobotState s) { return jog.next(s); }));
      else
        robot.Control(CartesianControl([&jog](RCI::robot::RobotState s) { return jog.next(s); }));
    } catch (const std::exception& e) {
      failure = e.what();
    }
    release.join();
    return failure;
  };
  // A stop this machine caused (its own stall of the client's loop, not a lost state) is repeated.
  client_test::MachineStalls stalls;
  for (int direction : {+1, -1}) {
    const std::string failure = client_test::excusingMachineStalls(robot, stalls, 0, [&] {
      return jogOnce([&](JogFlags& flags) { return JointJog(spec, 0, direction, 1.0, limits, flags); },
                     CM::kJointPosition, MM::kJointPosition);
    });
    SKIP_IF_THE_MACHINE_STALLED(stalls);
    QVERIFY2(failure.empty(), failure.c_str());
  }
  // Towards the base, sideways and about z: away from the stretched arm, where a Cartesian jog at full
  // speed runs into the joint velocity limits whether states are lost or not.
  for (const auto& [axis, direction] : {std::pair{0, -1}, std::pair{1, +1}, std::pair{5, +1}}) {
    const std::string failure = client_test::excusingMachineStalls(robot, stalls, 0, [&] {
      return jogOnce([&](JogFlags& flags) { return CartesianJog(axis, direction, 1.0, spec.dof, limits, flags); },
                     CM::kCartesianPosition, MM::kCartesianPosition);
    });
    SKIP_IF_THE_MACHINE_STALLED(stalls);
    QVERIFY2(failure.empty(), qPrintable(QStringLiteral("Cartesian jog along axis %1: %2").arg(axis).arg(failure.c_str())));
  }
  QVERIFY(server.status().counters.states_dropped > 10);
}

void TestJog::correctionLimitsNarrowJogLimits() {
  // The intersection alone: joint range vs. +-10 deg around q_on = 30 deg.
  const auto& spec = *model::findRobotSpec("kr6_r900_sixx");
  const JointLimitsRad joints = jogLimits(spec, false, {}, {});
  rsi::AxisCorrectionLimits corr;
  for (size_t i = 0; i < 6; ++i) {
    corr.lower[i] = -10 * kDeg;
    corr.upper[i] = 10 * kDeg;
  }
  std::array<double, 6> q_on{};
  q_on[0] = 30 * kDeg;
  q_on[1] = spec.q_min[1] + 2 * kDeg;  // near the joint's own lower limit: that one stays
  const JointLimitsRad l = withinCorrectionLimits(joints, q_on, corr);
  QVERIFY(std::abs(l.upper[0] - (40 * kDeg - kJogLimitMargin)) < 1e-12);
  QVERIFY(std::abs(l.lower[0] - (20 * kDeg + kJogLimitMargin)) < 1e-12);
  QCOMPARE(l.lower[1], joints.lower[1]);
  QVERIFY(std::abs(l.upper[1] - (q_on[1] + 10 * kDeg - kJogLimitMargin)) < 1e-12);

  // The jog at the RSI cycle (4 ms) within them: brakes before the limit, ends at rest.
  JogFlags flags;
  JointJog jog(spec, 0, +1, 1.0, l, flags, 0.004);
  std::array<double, 7> start{}, q{};
  start[0] = q_on[0];
  bool last = false;
  double max_q = -1e9;
  for (uint64_t cycle = 1; cycle < 5000 && !last; ++cycle) {
    if (cycle == 3000) flags.held.store(false);
    last = jog.advance(cycle, start, q);
    max_q = std::max(max_q, q[0]);
  }
  QVERIFY(last);
  QVERIFY(max_q <= l.upper[0] + 1e-9);
  QVERIFY(max_q > l.upper[0] - 0.5 * kDeg);
}

// The joint jog (JointJogMotion) and the Cartesian jog through the controller's Cartesian control
// (CartesianJogMotion) on RciArm: each moves while held and ends at rest after the release.
void TestJog::jogsThroughTheArmOfAnXmate() {
  auto server = client_test::startSim();
  auto robot = client_test::robotFor(*server);
  QVERIFY(robot->setMotorPower(1));
  arm::RciArm rci(*robot);
  const auto& spec = rci.spec();
  const JointLimitsRad limits = withinBounds(jogLimits(spec, false, {}, {}), rci.motionBounds(), spec.dof);
  arm::ArmState before, after;
  // The first state after power-on may still be on its way (a loaded machine: seen in CI).
  QVERIFY(rsi::testing::waitFor([&] { return rci.latest(before); }));
  {
    JogFlags flags;
    JointJog jog(spec, 1, -1, 0.5, limits, flags, rci.cycleSeconds());
    JointJogMotion motion(jog, releaseAfter(flags, 400));  // 0.4 s
    const QString thrown = jogUntilReleased([&] { rci.runJointMotion(motion); });
    QVERIFY2(thrown.isEmpty(), qPrintable(thrown));
  }
  QVERIFY(rsi::testing::waitFor([&] { return rci.latest(after) && after.sample.cycle > before.sample.cycle; }));
  QVERIFY2(after.sample.q[1] < before.sample.q[1] - 0.05, qPrintable(QString::number(after.sample.q[1] - before.sample.q[1])));
  QVERIFY(std::abs(after.sample.q[0] - before.sample.q[0]) < 1e-6);
  before = after;
  {
    JogFlags flags;
    CartesianJog jog(2, -1, 0.5, spec.dof, limits, flags);
    CartesianJogMotion motion(jog, releaseAfter(flags, 400));  // 0.4 s
    const QString thrown = jogUntilReleased([&] { rci.runCartesianMotion(motion); });
    QVERIFY2(thrown.isEmpty(), qPrintable(thrown));
  }
  QVERIFY(rci.latest(after));
  QVERIFY2(after.tcp[11] < before.tcp[11] - 0.01, qPrintable(QString::number(after.tcp[11] - before.tcp[11])));
  QVERIFY(std::abs(after.tcp[3] - before.tcp[3]) < 1e-3 && std::abs(after.tcp[7] - before.tcp[7]) < 1e-3);
}

// On RsiArm (the simulated KRC in lock-step): the joint jog within the correction limits of this RSI
// session, and the Cartesian jog through the admittance guide (GuidedCartesianJogMotion, JogPush).
void TestJog::jogsThroughTheArmOfAKuka() {
  const arm::RsiArmConfig config = rsi::testing::loopbackArm("resources/rsi/rci_replay.rsi.xml", 2000);
  arm::RsiArm rsi_arm(config);
  rsi_arm.start();
  sim::KrcServer krc(rsi::testing::krcFor(config, rsi_arm.link().port(), true));
  krc.start();
  arm::ArmState before, after;
  QVERIFY(rsi::testing::waitFor([&] { return rsi_arm.latest(before); }));
  const auto& spec = rsi_arm.spec();
  const arm::MotionBounds bounds = rsi_arm.motionBounds();
  QVERIFY(bounds.session != 0);
  const JointLimitsRad limits = withinBounds(jogLimits(spec, false, {}, {}), bounds, spec.dof);
  {
    JogFlags flags;
    JointJog jog(spec, 0, +1, 0.5, limits, flags, rsi_arm.cycleSeconds());
    JointJogMotion motion(jog, releaseAfter(flags, 100), bounds.session);  // 0.4 s of 4 ms cycles
    const QString thrown = jogUntilReleased([&] { rsi_arm.runJointMotion(motion); });
    QVERIFY2(thrown.isEmpty(), qPrintable(thrown));
    QVERIFY(!motion.sessionChanged());
  }
  QVERIFY(rsi_arm.latest(after));
  QVERIFY2(after.sample.q_command[0] > before.sample.q_command[0] + 0.05,
           qPrintable(QString::number(after.sample.q_command[0] - before.sample.q_command[0])));
  before = after;
  {
    JogFlags flags;
    const guide::GuideParameters parameters = cartesianJogParameters(2, 0.5);
    const JogPush push(rsi_arm, 2, +1, parameters);
    guide::AdmittanceGuide guide(model::ArmKinematics(spec), push, rsi_arm.cycleSeconds(), parameters);
    guide.setJointBounds(limits.lower, limits.upper);
    GuidedCartesianJogMotion motion(guide, flags, releaseAfter(flags, 150));  // 0.6 s
    const QString thrown = jogUntilReleased([&] { rsi_arm.runJointMotion(motion); });
    QVERIFY2(thrown.isEmpty(), qPrintable(thrown));
  }
  QVERIFY(rsi::testing::waitFor([&] { return rsi_arm.latest(after) && after.tcp[11] > before.tcp[11] + 0.01; }));
  krc.stop();
  rsi_arm.stop();
}

QTEST_APPLESS_MAIN(TestJog)
#include "test_jog.moc"
