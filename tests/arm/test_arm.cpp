// SPDX-License-Identifier: Apache-2.0
// arm::Arm on both families with the same checks: the newest state arrives in SI units (its TCP
// where the model puts it at its joints), every cycle comes through takeSamples in order and none
// is lost, a joint motion streamed at the controller's cycle ends where it was sent, and digital
// outputs and inputs reach the (simulated) controller; the range a motion can reach, and a TCP
// motion where the controller has Cartesian control of its own. The xMate: RciArm on the lock-step
// RCI simulator; the KUKA: RsiArm against the simulated KRC in lock-step, on loopback.
#include <QtTest>

#include <chrono>
#include <cmath>
#include <memory>
#include <thread>
#include <vector>

#include "arm/rci_arm.h"
#include "arm/rsi_arm.h"
#include "client_test_support.h"
#include "../rsi/rsi_test_support.h"
#include "model/arm_kinematics.h"
#include "sim/krc_server.h"

using namespace xmate;
using namespace xmate::arm;
using namespace client_test;
using xmate::rsi::testing::krcFor;
using xmate::rsi::testing::loopbackArm;
using xmate::rsi::testing::waitFor;

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

// Joint `axis` by `delta` (rad) from wherever the motion starts, on a smooth (cosine) profile of
// `cycles` controller cycles, then one more cycle holding the end.
class SwingAxis : public JointMotion {
 public:
  SwingAxis(size_t axis, double delta, int cycles) : axis_(axis), delta_(delta), cycles_(cycles) {}
  bool command(const ArmSample& now, std::array<double, 7>& q) override {
    if (calls_ == 0) start_ = now.q_command;
    const double s = std::min(1.0, double(calls_) / cycles_);
    q = start_;
    q[axis_] += delta_ * 0.5 * (1 - std::cos(3.14159265358979323846 * s));
    return ++calls_ > cycles_;
  }
  std::array<double, 7> target() const {
    std::array<double, 7> q = start_;
    q[axis_] += delta_;
    return q;
  }

 private:
  size_t axis_;
  double delta_;
  int cycles_;
  int calls_ = 0;
  std::array<double, 7> start_{};
};

// The TCP 2 cm down along base z on a smooth (cosine) profile of 500 cycles, from the measured pose.
class LowerTcp : public CartesianMotion {
 public:
  bool command(const ArmState& now, std::array<double, 16>& pose) override {
    if (calls_ == 0) start_ = now.tcp;
    const double s = std::min(1.0, double(calls_) / 500);
    pose = start_;
    pose[11] -= 0.02 * 0.5 * (1 - std::cos(3.14159265358979323846 * s));
    return ++calls_ > 500;
  }
  double startZ() const { return start_[11]; }

 private:
  int calls_ = 0;
  std::array<double, 16> start_{};
};

// The checks every arm passes. `outputs` / `inputs` read and set the simulated controller's IO.
void exercise(Arm& arm, const std::function<bool(size_t)>& output_on_controller,
              const std::function<void(size_t, bool)>& set_input_on_controller) {
  ArmState state;
  QVERIFY2(waitFor([&] { return arm.latest(state); }), "no state arrived");
  // The TCP where the model puts it at the measured joints (units: rad and m on both families).
  model::ArmKinematics model(arm.spec());
  const std::array<double, 16> fk = model.GetCartPose(state.sample.q);
  for (size_t i : {3u, 7u, 11u}) QVERIFY2(std::abs(fk[i] - state.tcp[i]) < 1e-3, qPrintable(QString::number(i)));
  for (size_t i : {0u, 5u, 10u}) QVERIFY2(std::abs(fk[i] - state.tcp[i]) < 1e-3, qPrintable(QString::number(i)));

  // A joint motion of 10 degrees on the first axis ends there.
  std::vector<ArmSample> samples(8192);
  arm.takeSamples(samples.data(), samples.size());  // what came before
  SwingAxis swing(0, 10 * kDeg, 400);
  arm.runJointMotion(swing);
  QVERIFY(waitFor([&] {
    arm.latest(state);
    return std::abs(state.sample.q[0] - swing.target()[0]) < 1e-4;
  }));
  // Every cycle of it came through, in order.
  const size_t n = arm.takeSamples(samples.data(), samples.size());
  QVERIFY2(n >= 400, qPrintable(QString::number(n)));
  for (size_t i = 1; i < n; ++i) {
    QCOMPARE(samples[i].cycle, samples[i - 1].cycle + 1);
    QVERIFY(samples[i].time >= samples[i - 1].time);
  }
  QCOMPARE(arm.samplesDropped(), uint64_t(0));
  double peak = 0;
  for (size_t i = 0; i < n; ++i) peak = std::max(peak, samples[i].q[0] - samples[0].q[0]);
  QVERIFY2(peak > 9.9 * kDeg && peak < 10.01 * kDeg, qPrintable(QString::number(peak / kDeg)));

  // Digital IO, by the names the arm gives.
  QVERIFY(has(arm.capabilities(), Capability::kDigitalIo));
  QVERIFY(arm.outputNames().size() >= 3 && arm.inputNames().size() >= 3);
  arm.setOutput(2, true);
  QVERIFY2(waitFor([&] { return output_on_controller(2); }), arm.outputNames()[2].c_str());
  set_input_on_controller(1, true);
  QVERIFY2(waitFor([&] { return arm.input(1); }), arm.inputNames()[1].c_str());
  set_input_on_controller(1, false);
  QVERIFY(waitFor([&] { return !arm.input(1); }));
  QVERIFY_THROWS_EXCEPTION(std::runtime_error, arm.setOutput(arm.outputNames().size(), true));
}

}  // namespace

class TestArm : public QObject {
  Q_OBJECT

 private slots:
  void anXmate();
  void aKuka();
};

void TestArm::anXmate() {
  auto server = startSim();
  auto robot = robotFor(*server);
  QVERIFY(robot->setMotorPower(1));
  RciArm arm(*robot);
  QCOMPARE(arm.spec().name, std::string_view("xmate7_pro"));
  QVERIFY(has(arm.capabilities(), Capability::kJointTorques));
  QVERIFY(has(arm.capabilities(), Capability::kBuiltInGuiding));
  QVERIFY(!has(arm.capabilities(), Capability::kCorrectionLimits));
  QCOMPARE(arm.cycleSeconds(), 0.001);
  QCOMPARE(arm.outputNames().front(), std::string("DO0_0"));
  exercise(
      arm, [&](size_t k) -> bool { return server->status().sim.digital_out[k]; },
      [&](size_t k, bool level) { server->setDigitalInput(int(k), level); });
  // The range a motion can reach: the model's joint range, in any session.
  const MotionBounds bounds = arm.motionBounds();
  QCOMPARE(bounds.lower[0], arm.spec().q_min[0]);
  QCOMPARE(bounds.upper[6], arm.spec().q_max[6]);
  QCOMPARE(bounds.session, 0u);
  // A TCP motion through the controller's Cartesian control ends where it was sent.
  QVERIFY(has(arm.capabilities(), Capability::kCartesianMotion));
  LowerTcp lower;
  arm.runCartesianMotion(lower);
  ArmState state;
  QVERIFY(waitFor([&] {
    arm.latest(state);
    return std::abs(state.tcp[11] - (lower.startZ() - 0.02)) < 1e-4;
  }));
}

void TestArm::aKuka() {
  const RsiArmConfig config = loopbackArm("resources/rsi/rci_replay.rsi.xml", 2000);
  RsiArm arm(config);
  arm.start();
  sim::KrcServer krc(krcFor(config, arm.link().port(), true));  // lock-step: repeatable under load
  krc.start();
  QCOMPARE(arm.spec().name, std::string_view("kr6_r900_sixx"));
  const Capabilities c = arm.capabilities();
  QVERIFY(has(c, Capability::kMotorCurrents) && has(c, Capability::kGearTorques) && has(c, Capability::kCorrectionLimits));
  QVERIFY(!has(c, Capability::kJointTorques) && !has(c, Capability::kPowerControl));
  QCOMPARE(arm.cycleSeconds(), 0.004);
  QCOMPARE(arm.outputNames().front(), std::string("$OUT[1]"));
  exercise(
      arm, [&](size_t k) -> bool { return (krc.krc().status().digout >> k) & 1u; },
      [&](size_t k, bool level) { krc.krc().setDigitalInput(int(k) + 1, level); });
  // Gear torques under gravity, in Nm, where the context wires GEARTORQUE1.
  ArmState state;
  QVERIFY(arm.latest(state));
  QVERIFY2(std::abs(state.sample.gear_torque[1]) > 1, qPrintable(QString::number(state.sample.gear_torque[1])));
  // The session as the samples taken show it (the window's status bar): running, at 4 ms.
  std::vector<ArmSample> samples(4096);
  QVERIFY(waitFor([&] {
    arm.takeSamples(samples.data(), samples.size());
    return arm.sessionStatus().phase == rsi::SessionPhase::kRunning && arm.sessionStatus().cycle_ms == 4;
  }));
  // Bounds of this session's reach: the start pose plus the context's +-90 deg, within the axis ranges.
  std::array<double, 7> lower{}, upper{};
  QVERIFY(arm.stream().reachableBounds(lower, upper));
  arm::StreamState s;
  QVERIFY(arm.stream().state(s));
  QVERIFY(std::abs(lower[0] - std::max(s.q_on[0] - 90 * kDeg, arm.spec().q_min[0])) < 1e-9);
  QVERIFY(std::abs(upper[1] - std::min(s.q_on[1] + 90 * kDeg, arm.spec().q_max[1])) < 1e-9);
  QCOMPARE(lower[6], 0.0);
  // The same as the arm's motion bounds, for this RSI session.
  const MotionBounds bounds = arm.motionBounds();
  QCOMPARE(bounds.lower[0], lower[0]);
  QCOMPARE(bounds.upper[1], upper[1]);
  QCOMPARE(bounds.session, s.session);
  // No Cartesian control of its own: a TCP motion is refused, saying so.
  QVERIFY(!has(c, Capability::kCartesianMotion));
  LowerTcp tcp_motion;
  try {
    arm.runCartesianMotion(tcp_motion);
    QFAIL("a TCP motion was accepted");
  } catch (const std::runtime_error& e) {
    QVERIFY2(QString(e.what()).contains("no Cartesian control"), e.what());
  }
  krc.stop();
  arm.stop();
}

QTEST_GUILESS_MAIN(TestArm)
#include "test_arm.moc"
