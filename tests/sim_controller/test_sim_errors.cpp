// SPDX-License-Identifier: Apache-2.0
// sim::Controller error bits: each of the 20 bits (docs/simulator_controller.md, "Error bits")
// provoked by a command stream or a scene event, reported in state().errors (alone, where the
// physics allows), with the motion stopped (robot_mode kReflex) and the bit kept until
// automaticErrorRecovery; then recovered with the controller's own commands and shown usable again
// (a small joint motion towards the valid range, and hand guiding, run without a new error).
#include <QtTest/QtTest>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

#include <xmate/cart_motion.h>
#include <xmate/joint_motion.h>
#include <xmate/model.h>

#include "controller_harness.h"
#include "model/robot_spec.h"
#include "motion_profiles.h"
#include "sim/error_bits.h"

using namespace xmate;
using namespace xmate::sim;
using namespace xmate::sim::test;
using RCI::robot::RobotMode;

namespace {

constexpr uint8_t kOk = 0;

// Steps `cycle(k)` for k = 0, 1, ... until an error bit shows up or max_cycles pass; returns the
// cycle at which it showed, -1 if none did.
int runUntilError(Harness& h, int max_cycles, const std::function<void(int)>& cycle) {
  for (int k = 0; k < max_cycles; ++k) {
    cycle(k);
    if (h.anyError()) return k;
  }
  return -1;
}

// A joint position motion to goal along a quintic (minimum-jerk) profile (the vendor's S-curve
// generator refuses goals beyond the hardware range, where an error may have left a joint), then
// 200 cycles of hold. Returns false when StartMove is refused or an error bit shows.
bool moveTo(Harness& h, const std::array<double, 7>& goal) {
  if (h.startMove(CM::kJointPosition, MG::kJointPosition) != kOk) return false;
  const auto q0 = h.state().q;
  double distance = 0;
  for (size_t i = 0; i < 7; ++i) distance = std::max(distance, std::abs(goal[i] - q0[i]));
  const int cycles = int(std::max(0.3, 4.0 * distance) * 1000);  // peak speed below 0.5 rad/s
  for (int k = 1; k <= cycles && !h.anyError(); ++k) {
    const double t = double(k) / cycles, s = t * t * t * (10 - 15 * t + 6 * t * t);
    std::array<double, 7> q{};
    for (size_t i = 0; i < 7; ++i) q[i] = q0[i] + s * (goal[i] - q0[i]);
    h.stepJoint(q, k == cycles);
  }
  h.idle(200);
  return !h.anyError() && !h.status().motion_active;
}

// After recovery the robot is usable again with the controller's own commands: the operator lets
// go (no scene wrench), the motors come back on if the error switched them off, a small joint
// motion towards `towards` (by default the middle of each joint's range; at most 0.03 rad per
// joint) runs without an error, and so does a moment of hand guiding.
void expectUsableAgain(Harness& h, std::optional<std::array<double, 7>> towards = std::nullopt) {
  h.controller().setExternalWrench({});
  h.idle(1);  // the state after the recovery
  QVERIFY2(!h.anyError(), h.errorList().c_str());
  if (!h.status().motors_on) QCOMPARE(h.setMotorPower(1), kOk);
  h.idle(300);  // a stop ramp still running
  QVERIFY2(!h.anyError(), h.errorList().c_str());
  const auto& spec = xmate::model::robotSpec(h.controller().config().type);
  const auto q = h.state().q;
  std::array<double, 7> goal = q;
  for (size_t i = 0; i < size_t(spec.dof); ++i) {
    const double aim = towards ? (*towards)[i] : 0.5 * (spec.q_min[i] + spec.q_max[i]);
    goal[i] = q[i] + std::clamp(aim - q[i], -0.03, 0.03);
  }
  QVERIFY2(moveTo(h, goal), qPrintable(QString("motion after recovery: %1 (%2)")
                                           .arg(h.errorList().c_str())
                                           .arg(h.controller().lastRefusal().c_str())));
  QCOMPARE(h.startDrag(0, 2), kOk);
  h.idle(300);
  QVERIFY2(!h.anyError(), h.errorList().c_str());
  QCOMPARE(h.empty(protocol::Command::kStopDrag), kOk);
  h.idle(100);
  QVERIFY2(!h.anyError(), h.errorList().c_str());
}

// The bit is set (and, if `alone`, no other), the motion has stopped, the robot is in reflex, and
// the bit stays until recovery, which clears it.
void expectStopped(Harness& h, ErrorBit bit, bool alone = true) {
  QVERIFY2(h.state().errors[size_t(bit)], qPrintable(QString("expected %1, have %2").arg(errorBitName(bit)).arg(h.errorList().c_str())));
  if (alone) QVERIFY2(h.errorList() == errorBitName(bit), qPrintable(QString("expected only %1, have %2").arg(errorBitName(bit)).arg(h.errorList().c_str())));
  QVERIFY(!h.status().motion_active);
  QVERIFY(!h.controller().expectsCommand());
  QCOMPARE(h.state().robot_mode, RobotMode::kReflex);
  h.idle(500);
  QVERIFY(h.state().errors[size_t(bit)]);
  QCOMPARE(h.recover(), kOk);
  h.idle(1);
  QVERIFY(!h.anyError());
}

std::array<double, 7> plus(std::array<double, 7> q, size_t joint, double delta) {
  q[joint] += delta;
  return q;
}

// TCP wrench -> joint torques J(q)^T F with the public model (the test's own computation).
std::array<double, 7> jointTorques(XmateModel& model, const std::array<double, 7>& q, const std::array<double, 6>& f) {
  const auto j = model.Jacobian(q);
  std::array<double, 7> tau{};
  for (size_t i = 0; i < 7; ++i)
    for (size_t r = 0; r < 6; ++r) tau[i] += j[r * 7 + i] * f[r];
  return tau;
}

// A stretched pose: TCP about 1 m from the J1 axis.
SimConfig stretched() {
  SimConfig config;
  config.initial_q = {0, 1.0, 0, 0.5, 0, 0.5, 0};
  return config;
}

}  // namespace

class TestSimErrors : public QObject {
  Q_OBJECT

 private slots:
  void bit0ActualJointPosition();
  void bit1ActualCartesianPosition();
  void bit2ActualElbow();
  void bit3ActualJointVelocity();
  void bit4ActualCartesianVelocity();
  void bit5ActualJointAcceleration();
  void bit6ActualCartesianAcceleration();
  void bit7CommandJointPosition();
  void bit8CommandCartesianPosition();
  void bit9CommandElbow();
  void bit10CommandJointVelocity();
  void bit11CommandCartesianVelocity();
  void bit12CommandJointAcceleration();
  void bit13CommandCartesianAcceleration();
  void bit14CommandAccelerationDiscontinuity();
  void bit15Collision();
  void bit16InvalidFrame();
  void bit17TorqueDiscontinuity();
  void bit18TorqueRange();
  void bit19Instability();
  void bit19ByEmergencyStop();
  void firstCommandMustStartAtTheCurrentPosition();
};

void TestSimErrors::bit0ActualJointPosition() {
  // Joint impedance with a soft J1 and a push sideways: the arm yields past the 10 deg soft limit
  // while the command stays at 0.
  Harness h;
  QCOMPARE(h.status(protocol::SetJointLimitRequest{{10, 120, 170, 120, 170, 120, 360}, {-170, -120, -170, -120, -170, -120, -360}, false}), kOk);
  QCOMPARE(h.status(protocol::SetJointImpedanceRequest{{10, 3000, 3000, 3000, 300, 300, 300}}), kOk);
  h.powerOnAndSettle();
  QCOMPARE(h.startMove(CM::kJointImpedance, MG::kJointPosition), kOk);
  const auto hold = h.state().q;
  const int k = runUntilError(h, 3000, [&](int k) {
    h.controller().setExternalWrench({0, std::min(0.1 * k, 20.0), 0, 0, 0, 0});  // a push growing over 0.2 s
    h.stepJoint(hold);
  });
  QVERIFY2(k > 0, qPrintable(QString("k = %1, errors: %2").arg(k).arg(h.errorList().c_str())));
  expectStopped(h, kActualJointPositionLimitsViolation);
  // J1 is still beyond its soft limit: once the push is gone, moving it further out is refused with
  // bit 7 ...
  h.controller().setExternalWrench({});
  h.idle(300);
  QVERIFY(h.state().q[0] > 10 * M_PI / 180);
  QVERIFY(!moveTo(h, plus(h.state().q, 0, 0.02)));
  QCOMPARE(h.errorList(), std::string("kCommandJointPositionLimitsViolation"));
  QCOMPARE(h.recover(), kOk);
  // ... and bringing it back in works (the usual check moves every joint towards its range's middle).
  expectUsableAgain(h);
  QVERIFY(moveTo(h, plus(h.state().q, 0, 5 * M_PI / 180 - h.state().q[0])));  // all the way in
  QVERIFY(std::abs(h.state().q[0] - 5 * M_PI / 180) < 1e-4);
}

void TestSimErrors::bit1ActualCartesianPosition() {
  // A joint motion that carries the TCP out of the safety box: power off.
  Harness h;
  h.powerOnAndSettle();
  Eigen::Isometry3d box = poseOf(h.state().toolTobase_pos_m);
  box.linear().setIdentity();
  QCOMPARE(h.status(protocol::SetCartesianLimitRequest{{0.2, 0.2, 0.2}, rowMajor(box), true}), kOk);
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), kOk);
  const auto q0 = h.state().q;
  JointMotionGenerator gen(0.3, plus(q0, 0, 0.5));
  gen.calculateSynchronizedValues_joint(q0);
  const int k = runUntilError(h, 5000, [&](int k) {
    std::array<double, 7> delta{};
    gen.calculateDesiredValues_joint(0.001 * k, delta);
    h.stepJoint(plus(q0, 0, delta[0]));
  });
  QVERIFY2(k > 0, qPrintable(QString("k = %1, errors: %2").arg(k).arg(h.errorList().c_str())));
  const Eigen::Vector3d local = box.inverse() * poseOf(h.state().toolTobase_pos_m).translation();
  QVERIFY(local.cwiseAbs().maxCoeff() > 0.1);
  QVERIFY(!h.status().motors_on);  // leaving the box powers the motors off
  expectStopped(h, kActualCartesianPositionLimitsViolation);
  // Back on, the TCP still outside the box: no error for being there; J1 back towards the start
  // brings it in, turning it further out trips bit 1 again.
  expectUsableAgain(h, q0);
  QVERIFY(!moveTo(h, plus(h.state().q, 0, 0.05)));
  QVERIFY(h.state().errors[kActualCartesianPositionLimitsViolation]);
  QVERIFY(!h.status().motors_on);
  QCOMPARE(h.recover(), kOk);
  expectUsableAgain(h, q0);
}

void TestSimErrors::bit2ActualElbow() {
  // A Cartesian motion (impedance, soft in translation, holding its start pose) pushed along -x in
  // the vertical plane through J1: when the wrist centre crosses the J1 axis the arm angle's
  // reference plane turns over and psi jumps by pi. (Hand guiding cannot carry it across: it is held
  // off the axis, test_sim_walls.)
  SimConfig config;
  config.initial_q = {0, 0.3, 0, -0.55, 0, 1.0, 0};  // wrist centre 2-3 cm in front of the J1 axis
  Harness h(config);
  QCOMPARE(h.status(protocol::SetCartesianImpedanceRequest{{100, 100, 100, 300, 300, 300}}), kOk);
  h.powerOnAndSettle();
  QCOMPARE(h.startMove(CM::kCartesianImpedance, MG::kCartesianPosition), kOk);
  const Eigen::Isometry3d start = poseOf(h.state().toolTobase_pos_m);
  const double psi0 = h.state().psi_m;
  h.controller().setExternalWrench({-30, 0, 0, 0, 0, 0});
  const int k = runUntilError(h, 3000, [&](int) { h.stepCartesian(start); });
  QVERIFY2(k > 0, qPrintable(QString("k = %1, errors: %2").arg(k).arg(h.errorList().c_str())));
  qInfo("psi %.3f -> %.3f after %d ms of the motion", psi0, h.state().psi_m, k);
  QVERIFY(std::abs(std::remainder(h.state().psi_m - psi0, 2 * M_PI)) > 2.0);
  QVERIFY(!h.status().motion_active);
  QVERIFY2(h.state().errors[kActualCartesianMotionGeneratorElbowLimitViolation], h.errorList().c_str());
  QCOMPARE(h.errorList(), std::string("kActualCartesianMotionGeneratorElbowLimitViolation"));
  QCOMPARE(h.state().robot_mode, RobotMode::kReflex);
  QCOMPARE(h.recover(), kOk);
  expectUsableAgain(h);
}

void TestSimErrors::bit3ActualJointVelocity() {
  // Joint impedance with J1 free (K = 0): a sideways push spins it up past its velocity limit.
  Harness h;
  QCOMPARE(h.status(protocol::SetJointImpedanceRequest{{0, 3000, 3000, 3000, 300, 300, 300}}), kOk);
  h.powerOnAndSettle();
  QCOMPARE(h.startMove(CM::kJointImpedance, MG::kJointPosition), kOk);
  const auto hold = h.state().q;
  const int k = runUntilError(h, 3000, [&](int k) {
    h.controller().setExternalWrench({0, std::min(0.1 * k, 20.0), 0, 0, 0, 0});
    h.stepJoint(hold);
  });
  QVERIFY2(k > 0, qPrintable(QString("k = %1, errors: %2").arg(k).arg(h.errorList().c_str())));
  QVERIFY(std::abs(h.state().dq_m[0]) > 2.175);
  expectStopped(h, kActualJointVelocityLimitsViolation);
  expectUsableAgain(h);
}

void TestSimErrors::bit4ActualCartesianVelocity() {
  // Torque mode, stretched arm: the test's own velocity loop spins J1 to 1.8 rad/s; the TCP, 1 m out,
  // passes 1.65 m/s (the 1.5 m/s limit + 10 %) while J1 stays below its limit.
  Harness h(stretched());
  h.powerOnAndSettle();
  QCOMPARE(h.status(protocol::SetFiltersRequest{100, 100, 1000}), kOk);
  QCOMPARE(h.startMove(CM::kTorque, MG::kIdle), kOk);
  const auto q0 = h.state().q;
  const int k = runUntilError(h, 3000, [&](int k) {
    const double v_ref = std::min(3.0 * 0.001 * k, 1.8);
    std::array<double, 7> tau{};
    tau[0] = 40.0 * (v_ref - h.state().dq_m[0]);
    for (size_t i = 1; i < 7; ++i) {  // the other joints held by the client's own PD
      const double kp = i < 4 ? 600 : 60, kd = i < 4 ? 40 : 2;
      tau[i] = kp * (q0[i] - h.state().q[i]) - kd * h.state().dq_m[i];
    }
    h.stepTorque(tau);
  });
  QVERIFY2(k > 0, qPrintable(QString("k = %1, errors: %2").arg(k).arg(h.errorList().c_str())));
  qInfo("J1 at %.3f rad/s when the TCP speed tripped", h.state().dq_m[0]);
  QVERIFY(std::abs(h.state().dq_m[0]) < 2.175);
  expectStopped(h, kActualCartesianVelocityLimitsViolation);
  expectUsableAgain(h);
}

void TestSimErrors::bit5ActualJointAcceleration() {
  // Joint impedance; a sudden 5 Nm twist about the tool axis: the light wrist joint accelerates
  // far beyond 1.5 x 20 rad/s^2.
  Harness h;
  h.powerOnAndSettle();
  QCOMPARE(h.startMove(CM::kJointImpedance, MG::kJointPosition), kOk);
  const auto hold = h.state().q;
  h.stepJoint(hold);
  const Eigen::Vector3d axis = poseOf(h.state().toolTobase_pos_m).linear().col(2);
  h.controller().setExternalWrench({0, 0, 0, 5 * axis.x(), 5 * axis.y(), 5 * axis.z()});
  const int k = runUntilError(h, 100, [&](int) { h.stepJoint(hold); });
  QVERIFY(k >= 0);
  expectStopped(h, kActualJointAccelerationLimitsViolation);
  expectUsableAgain(h);
}

void TestSimErrors::bit6ActualCartesianAcceleration() {
  // Torque mode, stretched arm with a 0.5 m tool: J1 accelerated at ~11 rad/s^2 (within its
  // limits) swings the TCP at more than 1.5 x 10 m/s^2.
  Harness h(stretched());
  Eigen::Isometry3d tool = Eigen::Isometry3d::Identity();
  tool.translation() = Eigen::Vector3d(0, 0, 0.5);
  QCOMPARE(h.status(protocol::SetCoorRequest{rowMajor(tool)}), kOk);
  QCOMPARE(h.status(protocol::SetFiltersRequest{100, 100, 1000}), kOk);
  h.powerOnAndSettle();
  QCOMPARE(h.startMove(CM::kTorque, MG::kIdle), kOk);
  // Accelerate J1 alone: tau = M(q) [a, 0, ..., 0] (+ J1's rotor inertia), a ramped up to 12 rad/s^2
  // over 0.1 s; the other joints' share of M keeps them still.
  XmateModel model(XMATE7_PRO);
  const int k = runUntilError(h, 400, [&](int k) {
    const double a = std::min(120.0 * 0.001 * k, 12.0);
    const auto m = model.MassMatrix(h.state().q);
    std::array<double, 7> tau{};
    for (size_t i = 0; i < 7; ++i) tau[i] = m[i * 7 + 0] * a;
    tau[0] += 0.1 * a;
    h.stepTorque(tau);
  });
  QVERIFY2(k > 0, qPrintable(QString("k = %1, errors: %2").arg(k).arg(h.errorList().c_str())));
  qInfo("J1 at %.3f rad/s when the TCP acceleration tripped", h.state().dq_m[0]);
  expectStopped(h, kActualCartesianAccelerationLimitsViolation);
  expectUsableAgain(h);
}

void TestSimErrors::bit7CommandJointPosition() {
  Harness h;
  QCOMPARE(h.status(protocol::SetJointLimitRequest{{5, 120, 170, 120, 170, 120, 360}, {-170, -120, -170, -120, -170, -120, -360}, false}), kOk);
  h.powerOnAndSettle();
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), kOk);
  const auto q0 = h.state().q;
  JointMotionGenerator gen(0.3, plus(q0, 0, 0.2));  // to 11.5 deg
  gen.calculateSynchronizedValues_joint(q0);
  double commanded = 0;
  const int k = runUntilError(h, 5000, [&](int k) {
    std::array<double, 7> delta{};
    gen.calculateDesiredValues_joint(0.001 * k, delta);
    commanded = q0[0] + delta[0];
    h.stepJoint(plus(q0, 0, delta[0]));
  });
  QVERIFY2(k > 0, qPrintable(QString("k = %1, errors: %2").arg(k).arg(h.errorList().c_str())));
  QVERIFY(commanded > 5 * M_PI / 180 && commanded < 5 * M_PI / 180 + 0.01);  // tripped right at the limit
  expectStopped(h, kCommandJointPositionLimitsViolation);
  expectUsableAgain(h);
}

void TestSimErrors::bit8CommandCartesianPosition() {
  // A Cartesian line pulling the wrist centre towards the shoulder: the elbow would have to fold
  // beyond J4's range -- outside the workspace.
  Harness h;
  h.powerOnAndSettle();
  const Eigen::Isometry3d start = poseOf(h.state().toolTobase_pos_m);
  const Eigen::Vector3d shoulder(0, 0, xmate::model::robotSpec(XMATE7_PRO).dh[0].d);
  const Eigen::Vector3d wrist = start.translation() - 0.2755 * start.linear().col(2);
  const Eigen::Vector3d direction = (shoulder - wrist).normalized();
  CartMotionGenerator gen(0.3, 0.5);
  gen.calculateSynchronizedValues_cart(0);
  QCOMPARE(h.startMove(CM::kCartesianPosition, MG::kCartesianPosition), kOk);
  const int k = runUntilError(h, 10000, [&](int k) {
    double s = 0;
    gen.calculateDesiredValues_cart(0.001 * k, &s);
    Eigen::Isometry3d pose = start;
    pose.translation() += s * direction;
    h.stepCartesian(pose);
  });
  QVERIFY2(k > 0, qPrintable(QString("k = %1, errors: %2").arg(k).arg(h.errorList().c_str())));
  qInfo("J4 at %.1f deg when the pose left the workspace", h.state().q[3] * 180 / M_PI);
  expectStopped(h, kCommandCartesianPositionLimitsViolation);
  expectUsableAgain(h);
}

void TestSimErrors::bit9CommandElbow() {
  // Constant pose, arm angle accelerated at 12 rad/s^2 (limit 10).
  Harness h;
  h.powerOnAndSettle();
  const Eigen::Isometry3d pose = poseOf(h.state().toolTobase_pos_m);
  const double psi0 = h.state().psi_m;
  QCOMPARE(h.startMove(CM::kCartesianPosition, MG::kCartesianPosition), kOk);
  const JerkRamp ramp{4000, 12};
  const int k = runUntilError(h, 1000, [&](int k) { h.stepCartesian(pose, false, true, psi0 + ramp.positionAt(0.001 * k)); });
  QVERIFY2(k > 0, qPrintable(QString("k = %1, errors: %2").arg(k).arg(h.errorList().c_str())));
  QVERIFY(std::abs(ramp.accelerationAt(0.001 * k) - 10) < 4000 * 0.0011);  // tripped as it passed 10 rad/s^2
  expectStopped(h, kCommandCartesianMotionGeneratorElbowLimitViolation);
  expectUsableAgain(h);
}

void TestSimErrors::bit10CommandJointVelocity() {
  Harness h;
  h.powerOnAndSettle();
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), kOk);
  const auto q0 = h.state().q;
  const JerkRamp ramp{4000, 14};
  const int k = runUntilError(h, 1000, [&](int k) { h.stepJoint(plus(q0, 0, ramp.positionAt(0.001 * k))); });
  QVERIFY2(k > 0, qPrintable(QString("k = %1, errors: %2").arg(k).arg(h.errorList().c_str())));
  QVERIFY(std::abs(ramp.velocityAt(0.001 * k) - 2.175) < 14 * 0.0015);  // tripped as it passed 2.175 rad/s
  expectStopped(h, kCommandJointVelocityLimitsViolation);
  expectUsableAgain(h);
}

void TestSimErrors::bit11CommandCartesianVelocity() {
  // Spin about the flange axis: only J7 turns; the TCP's angular velocity passes 2.5 rad/s before
  // J7 reaches its 2.61 rad/s.
  Harness h;
  h.powerOnAndSettle();
  const Eigen::Isometry3d start = poseOf(h.state().toolTobase_pos_m);
  QCOMPARE(h.startMove(CM::kCartesianPosition, MG::kCartesianPosition), kOk);
  const JerkRamp ramp{10000, 24};
  const int k = runUntilError(h, 1000, [&](int k) {
    Eigen::Isometry3d pose = start;
    pose.linear() = start.linear() * Eigen::AngleAxisd(ramp.positionAt(0.001 * k), Eigen::Vector3d::UnitZ()).toRotationMatrix();
    h.stepCartesian(pose);
  });
  QVERIFY2(k > 0, qPrintable(QString("k = %1, errors: %2").arg(k).arg(h.errorList().c_str())));
  QVERIFY(std::abs(ramp.velocityAt(0.001 * k) - 2.5) < 24 * 0.0015);
  expectStopped(h, kCommandCartesianVelocityLimitsViolation);
  expectUsableAgain(h);
}

void TestSimErrors::bit12CommandJointAcceleration() {
  Harness h;
  h.powerOnAndSettle();
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), kOk);
  const auto q0 = h.state().q;
  const JerkRamp ramp{4000, 16};
  const int k = runUntilError(h, 1000, [&](int k) { h.stepJoint(plus(q0, 0, ramp.positionAt(0.001 * k))); });
  QVERIFY2(k > 0, qPrintable(QString("k = %1, errors: %2").arg(k).arg(h.errorList().c_str())));
  QVERIFY(std::abs(ramp.accelerationAt(0.001 * k) - 15) < 4000 * 0.0015);
  expectStopped(h, kCommandJointAccelerationLimitsViolation);
  expectUsableAgain(h);
}

void TestSimErrors::bit13CommandCartesianAcceleration() {
  Harness h;
  h.powerOnAndSettle();
  const Eigen::Isometry3d start = poseOf(h.state().toolTobase_pos_m);
  QCOMPARE(h.startMove(CM::kCartesianPosition, MG::kCartesianPosition), kOk);
  const JerkRamp ramp{4000, 11};
  const int k = runUntilError(h, 1000, [&](int k) {
    Eigen::Isometry3d pose = start;
    pose.translation().z() -= ramp.positionAt(0.001 * k);
    h.stepCartesian(pose);
  });
  QVERIFY2(k > 0, qPrintable(QString("k = %1, errors: %2").arg(k).arg(h.errorList().c_str())));
  QVERIFY(std::abs(ramp.accelerationAt(0.001 * k) - 10) < 4000 * 0.0015);
  expectStopped(h, kCommandCartesianAccelerationLimitsViolation);
  expectUsableAgain(h);
}

void TestSimErrors::bit14CommandAccelerationDiscontinuity() {
  // From rest straight into 14 rad/s^2 (within the 15 rad/s^2 limit): the acceleration jump is a
  // jerk of 14 / 1 ms.
  Harness h;
  h.powerOnAndSettle();
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), kOk);
  const auto q0 = h.state().q;
  const int k = runUntilError(h, 100, [&](int k) {
    const double t = 0.001 * k;
    h.stepJoint(plus(q0, 0, 0.5 * 14 * t * t));
  });
  QVERIFY(k >= 0 && k < 5);
  expectStopped(h, kCommandJointAccelerationDiscontinuity);
  // The same start with the jerk ramped in (4000 rad/s^3) is accepted.
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), kOk);
  const auto q1 = h.state().q;
  const JerkRamp ramp{4000, 14};
  for (int k = 0; k < 100; ++k) h.stepJoint(plus(q1, 0, ramp.positionAt(0.001 * k)));
  QVERIFY2(!h.anyError(), h.errorList().c_str());
  QCOMPARE(h.stopMove(), kOk);
  expectUsableAgain(h);
}

void TestSimErrors::bit15Collision() {
  // A sideways push growing to 150 N at the TCP during a joint motion: |tau_ext| exceeds the thresholds, the motors go
  // off and the brakes stop the arm.
  Harness h;
  h.powerOnAndSettle();
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), kOk);
  const auto q0 = h.state().q;
  int k = runUntilError(h, 200, [&](int k) {
    h.controller().setExternalWrench({0, std::min(1.0 * k, 150.0), 0, 0, 0, 0});  // 1000 N/s ramp
    h.stepJoint(q0);
  });
  QVERIFY2(k > 0, qPrintable(QString("k = %1, errors: %2").arg(k).arg(h.errorList().c_str())));
  QVERIFY(!h.status().motors_on);
  const auto tau_ext = h.status().external_joint_torque;
  const auto& max = xmate::model::robotSpec(XMATE7_PRO).collision_threshold_max;
  bool over = false;
  for (size_t i = 0; i < 7; ++i) over = over || std::abs(tau_ext[i]) > max[i];
  QVERIFY(over);
  expectStopped(h, kCollision);
  expectUsableAgain(h);
}

void TestSimErrors::bit16InvalidFrame() {
  Harness h;
  h.powerOnAndSettle();
  QCOMPARE(h.startMove(CM::kCartesianPosition, MG::kCartesianPosition), kOk);
  auto pose = h.state().toolTobase_pos_m;
  h.stepCommand([&] {
    RobotCommand c;
    c.motion.toolTobase_pos_c = pose;
    return c;
  }());
  pose[0] *= 1.01;  // no longer a rotation
  RobotCommand c;
  c.motion.toolTobase_pos_c = pose;
  h.stepCommand(c);
  expectStopped(h, kCartesianPositionMotionGeneratorInvalidFrame);
  expectUsableAgain(h);
}

void TestSimErrors::bit17TorqueDiscontinuity() {
  Harness h;
  h.powerOnAndSettle();
  QCOMPARE(h.startMove(CM::kTorque, MG::kIdle), kOk);
  std::array<double, 7> tau{};
  tau[6] = 0.9;  // 0.9 Nm in 1 ms: 900 Nm/s, within 1000 Nm/s
  h.stepTorque(tau);
  QVERIFY(!h.anyError());
  tau[6] = 2.0;  // +1.1 Nm in 1 ms
  h.stepTorque(tau);
  expectStopped(h, kCommandTorqueDiscontinuity);
  expectUsableAgain(h);
}

void TestSimErrors::bit18TorqueRange() {
  // The scene pushes down on the TCP and the client's torque holds the arm against it (both ramp
  // up together), until J2 is asked for more than 85 Nm.
  Harness h;
  h.powerOnAndSettle();
  QCOMPARE(h.status(protocol::SetFiltersRequest{100, 100, 1000}), kOk);
  QCOMPARE(h.startMove(CM::kTorque, MG::kIdle), kOk);
  XmateModel model(XMATE7_PRO);
  std::array<double, 7> last{};
  const int k = runUntilError(h, 1000, [&](int k) {
    const std::array<double, 6> push{0, 0, -1.0 * k, 0, 0, 0};  // 1000 N/s
    h.controller().setExternalWrench(push);
    const auto held = jointTorques(model, h.state().q, push);
    for (size_t i = 0; i < 7; ++i) last[i] = -held[i];
    h.stepTorque(last);
  });
  QVERIFY2(k > 0, qPrintable(QString("k = %1, errors: %2").arg(k).arg(h.errorList().c_str())));
  qInfo("J2 torque %.2f Nm when it tripped; the arm moved %.3g rad", last[1],
        std::abs(h.state().q[1] - 0.5236));
  QVERIFY(std::abs(last[1]) > 85 && std::abs(last[1]) < 86.5);
  // The motion stops and the controller holds position against the push, which now is a collision
  // too (every collision threshold is below the joint's torque limit), so both bits are set.
  QVERIFY(h.state().errors[kCollision]);
  expectStopped(h, kCommandTorqueRangeViolation, /*alone=*/false);
  expectUsableAgain(h);
}

void TestSimErrors::bit19Instability() {
  Harness h;
  h.powerOnAndSettle();
  QCOMPARE(h.startMove(CM::kTorque, MG::kIdle), kOk);
  h.stepTorque({});
  const int k = runUntilError(h, 100, [&](int) { h.lose(); });
  QCOMPARE(k, 15);  // the 16th lost command in a row (default threshold 15)
  expectStopped(h, kInstabilityDetection);
  expectUsableAgain(h);
}

void TestSimErrors::bit19ByEmergencyStop() {
  // The e-stop pressed during a motion: bit 19, motors off. Recovery needs the button released
  // first; then the motors come back with setMotorPower(1).
  Harness h;
  h.powerOnAndSettle();
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), kOk);
  const auto q0 = h.state().q;
  h.stepJoint(q0);
  h.controller().setEmergencyStop(true);
  h.idle(1);
  QCOMPARE(h.errorList(), std::string("kInstabilityDetection"));
  QVERIFY(!h.status().motors_on);
  QCOMPARE(h.recover(), uint8_t(protocol::ErrorRecoveryStatus::kManualRecoveryRequired));
  QCOMPARE(h.setMotorPower(1), uint8_t(1));
  h.controller().setEmergencyStop(false);
  QCOMPARE(h.recover(), kOk);
  h.idle(1);
  QVERIFY(!h.anyError());
  expectUsableAgain(h);
}

void TestSimErrors::firstCommandMustStartAtTheCurrentPosition() {
  Harness h;
  h.powerOnAndSettle();
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), kOk);
  h.stepJoint(plus(h.state().q, 2, 0.05));  // 5 cm... 50 mrad away: 50 rad/s
  QVERIFY(h.state().errors[kCommandJointVelocityLimitsViolation]);
  QVERIFY(!h.status().motion_active);
  // Half a milliradian away (a hold error, or q_c instead of q): accepted as the start.
  QCOMPARE(h.recover(), kOk);
  h.idle(5);
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), kOk);
  const auto start = plus(h.state().q, 2, 5e-4);
  h.stepJoint(start);
  h.stepJoint(start);
  QVERIFY2(!h.anyError(), h.errorList().c_str());
}

QTEST_APPLESS_MAIN(TestSimErrors)
#include "test_sim_errors.moc"
