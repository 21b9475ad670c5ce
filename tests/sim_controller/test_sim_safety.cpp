// SPDX-License-Identifier: Apache-2.0
// sim::Controller safety functions and scene interaction: collision detection from the estimated
// external torque (and a wrong setLoad showing up as one), power off and brakes, recovery, the
// Cartesian safety box, soft limits with and without auto_limit, and hand guiding that moves only
// in the allowed directions.
#include <QtTest/QtTest>

#include <cmath>

#include <xmate/cart_motion.h>
#include <xmate/joint_motion.h>
#include <xmate/model.h>

#include "controller_harness.h"

using namespace xmate;
using namespace xmate::sim;
using namespace xmate::sim::test;
using RCI::robot::RobotMode;

namespace {

constexpr uint8_t kOk = 0;

std::array<double, 7> jointTorques(XmateModel& model, const std::array<double, 7>& q, const std::array<double, 6>& f) {
  const auto j = model.Jacobian(q);
  std::array<double, 7> tau{};
  for (size_t i = 0; i < 7; ++i)
    for (size_t r = 0; r < 6; ++r) tau[i] += j[r * 7 + i] * f[r];
  return tau;
}

double rotationAngle(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
}

const std::array<double, 9> kSmallInertia{0.01, 0, 0, 0, 0.01, 0, 0, 0, 0.01};

}  // namespace

class TestSimSafety : public QObject {
  Q_OBJECT

 private slots:
  void collisionPowersOffAndRecovers();
  void collisionThresholdIsTheJointTorque();
  void noCollisionDetectionInImpedanceModes();
  void wrongPayloadLooksLikeACollision();
  void safetyBoxExitPowersOff();
  void autoLimitStopsSmoothlyAtTheSoftLimit();
  void jointDragMovesUnderAWrench();
  void cartesianDragTranslationOnly();
  void cartesianDragRotationOnly();
  void cartesianDragFree();
  void guardStopEndsGuiding();
};

void TestSimSafety::collisionPowersOffAndRecovers() {
  Harness h;
  h.powerOnAndSettle();
  int k = 0;
  for (; k < 300 && h.status().motors_on; ++k) {
    h.controller().setExternalWrench({0, std::min(1.0 * k, 150.0), 0, 0, 0, 0});
    h.idle(1);
  }
  QVERIFY(!h.status().motors_on);
  QCOMPARE(h.errorList(), std::string("kCollision"));
  QCOMPARE(h.state().robot_mode, RobotMode::kReflex);
  h.idle(50);
  for (double v : h.state().dq_m) QCOMPARE(v, 0.0);  // brakes
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), uint8_t(6));  // kReflexAborted
  h.controller().setExternalWrench({});
  QCOMPARE(h.recover(), kOk);
  QCOMPARE(h.setMotorPower(1), kOk);
  h.idle(100);
  QVERIFY(h.status().motors_on);
  QVERIFY2(!h.anyError(), h.errorList().c_str());
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), kOk);
}

void TestSimSafety::collisionThresholdIsTheJointTorque() {
  // Lower J1's threshold to 20 Nm and push slowly sideways: it trips when J^T F on J1 reaches 20 Nm.
  Harness h;
  QCOMPARE(h.status(protocol::SetCollisionBehaviorRequest{{20, 75, 60, 45, 30, 30, 20}}), kOk);
  h.powerOnAndSettle();
  XmateModel model(XMATE7_PRO);
  std::array<double, 6> push{};
  for (int k = 0; k < 3000 && h.status().motors_on; ++k) {
    push = {0, 0.05 * k, 0, 0, 0, 0};  // 50 N/s
    h.controller().setExternalWrench(push);
    h.idle(1);
  }
  QVERIFY(!h.status().motors_on);
  const double tau1 = jointTorques(model, h.state().q, push)[0];
  qInfo("tripped at F_y = %.2f N, J1 external torque %.3f Nm (threshold 20)", push[1], tau1);
  QVERIFY(std::abs(std::abs(tau1) - 20) < 0.1);
  QVERIFY(h.state().errors[15]);
}

void TestSimSafety::noCollisionDetectionInImpedanceModes() {
  Harness h;
  h.powerOnAndSettle();
  QCOMPARE(h.status(protocol::SetJointImpedanceRequest{{3000, 3000, 3000, 3000, 300, 300, 300}}), kOk);
  QCOMPARE(h.startMove(CM::kJointImpedance, MG::kJointPosition), kOk);
  const auto hold = h.state().q;
  for (int k = 0; k < 400; ++k) {
    h.controller().setExternalWrench({0, std::min(1.0 * k, 150.0), 0, 0, 0, 0});
    h.stepJoint(hold);
  }
  QVERIFY2(!h.anyError(), h.errorList().c_str());
  QVERIFY(std::abs(h.status().external_joint_torque[0]) > 75);  // seen, but not a collision here
  QVERIFY(h.status().motors_on);
}

void TestSimSafety::wrongPayloadLooksLikeACollision() {
  const std::array<double, 7> sensitive{25, 25, 25, 20, 10, 10, 10};
  // 5 kg really on the flange, declared: nothing happens, even in motion.
  {
    Harness h;
    h.controller().setActualPayload(5.0, {0, 0, 0.1}, kSmallInertia);
    QCOMPARE(h.status(protocol::SetLoadRequest{5.0, {0, 0, 0.1}, kSmallInertia}), kOk);
    QCOMPARE(h.status(protocol::SetCollisionBehaviorRequest{sensitive}), kOk);
    h.powerOnAndSettle(500);
    QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), kOk);
    const auto q0 = h.state().q;
    JointMotionGenerator gen(0.3, {0.3, 0.7, 0.2, 1.3, 0.4, 1.2, 0.5});
    gen.calculateSynchronizedValues_joint(q0);
    bool finished = false;
    for (int k = 0; !finished; ++k) {
      std::array<double, 7> delta{}, q{};
      finished = gen.calculateDesiredValues_joint(0.001 * k, delta);
      for (size_t i = 0; i < 7; ++i) q[i] = q0[i] + delta[i];
      h.stepJoint(q, finished);
      QVERIFY2(!h.anyError(), h.errorList().c_str());
    }
    double largest = 0;
    for (double t : h.status().external_joint_torque) largest = std::max(largest, std::abs(t));
    QVERIFY(largest < 1e-3);
  }
  // The same 5 kg, but setLoad says nothing: the estimate sees the undeclared weight, and the
  // detector trips once the thresholds are below it.
  {
    Harness h;
    h.controller().setActualPayload(5.0, {0, 0, 0.1}, kSmallInertia);
    QCOMPARE(h.status().actual_payload_mass, 5.0);
    QVERIFY(!h.status().actual_payload_follows_load);
    h.powerOnAndSettle(300);
    QVERIFY2(!h.anyError(), h.errorList().c_str());  // the default thresholds are above it
    XmateModel model(XMATE7_PRO);
    model.SetCoor({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0.1, 0, 0, 0, 1});  // "TCP" at the payload's centre
    const auto weight = jointTorques(model, h.state().q, {0, 0, -5.0 * 9.81, 0, 0, 0});
    const auto estimate = h.status().external_joint_torque;
    qInfo("estimated external torque on J2: %.3f Nm; weight of the undeclared load: %.3f Nm", estimate[1], weight[1]);
    for (size_t i = 0; i < 7; ++i) QVERIFY(std::abs(estimate[i] - weight[i]) < 0.01 * 49.05);
    QCOMPARE(h.status(protocol::SetCollisionBehaviorRequest{sensitive}), kOk);
    h.idle(2);
    QVERIFY(!h.status().motors_on);
    QCOMPARE(h.errorList(), std::string("kCollision"));
  }
}

void TestSimSafety::safetyBoxExitPowersOff() {
  Harness h;
  h.powerOnAndSettle();
  const Eigen::Isometry3d start = poseOf(h.state().toolTobase_pos_m);
  Eigen::Isometry3d box = Eigen::Isometry3d::Identity();
  box.translation() = start.translation();
  QCOMPARE(h.status(protocol::SetCartesianLimitRequest{{0.3, 0.3, 0.3}, rowMajor(box), true}), kOk);
  CartMotionGenerator gen(0.5, 0.3);
  gen.calculateSynchronizedValues_cart(0);
  QCOMPARE(h.startMove(CM::kCartesianPosition, MG::kCartesianPosition), kOk);
  double s = 0;
  for (int k = 0; k < 5000 && h.status().motors_on; ++k) {
    gen.calculateDesiredValues_cart(0.001 * k, &s);
    Eigen::Isometry3d pose = start;
    pose.translation().z() -= s;
    h.stepCartesian(pose);
  }
  QVERIFY(!h.status().motors_on);
  QCOMPARE(h.errorList(), std::string("kActualCartesianPositionLimitsViolation"));
  h.idle(200);
  const double depth = start.translation().z() - poseOf(h.state().toolTobase_pos_m).translation().z();
  qInfo("left the box at 0.15 m below the start; braked to rest at %.4f m", depth);
  QVERIFY(depth > 0.15 && depth < 0.16);
  // Still outside: after recovery the motors come back on -- being outside is no error, only going
  // further out is (docs/simulator_controller.md, "There is always a way back").
  QCOMPARE(h.recover(), kOk);
  QCOMPARE(h.setMotorPower(1), kOk);
  h.idle(100);
  QVERIFY(h.status().motors_on);
  QVERIFY2(!h.anyError(), h.errorList().c_str());
  // A straight line along z by dz from where the TCP is; true if it ran without an error.
  const auto lineZ = [&](double dz) {
    if (h.startMove(CM::kCartesianPosition, MG::kCartesianPosition) != kOk) return false;
    const Eigen::Isometry3d from = poseOf(h.state().toolTobase_pos_m);
    CartMotionGenerator line(0.3, std::abs(dz));
    line.calculateSynchronizedValues_cart(0);
    bool finished = false;
    for (int k = 0; !finished && !h.anyError(); ++k) {
      double s = 0;
      finished = line.calculateDesiredValues_cart(0.001 * k, &s);
      Eigen::Isometry3d pose = from;
      pose.translation().z() += std::copysign(s, dz);
      h.stepCartesian(pose, finished);
    }
    h.idle(200);
    return !h.anyError();
  };
  QVERIFY(!lineZ(-0.01));  // further out
  QCOMPARE(h.errorList(), std::string("kActualCartesianPositionLimitsViolation"));
  QVERIFY(!h.status().motors_on);
  QCOMPARE(h.recover(), kOk);
  QCOMPARE(h.setMotorPower(1), kOk);
  h.idle(100);
  QVERIFY2(lineZ(0.05), h.errorList().c_str());  // back in
  const double inside = start.translation().z() - poseOf(h.state().toolTobase_pos_m).translation().z();
  qInfo("moved back in: %.4f m below the start (the face at 0.15)", inside);
  QVERIFY(inside < 0.15);
}

void TestSimSafety::autoLimitStopsSmoothlyAtTheSoftLimit() {
  Harness h;
  QCOMPARE(h.status(protocol::SetJointLimitRequest{{10, 120, 170, 120, 170, 120, 360}, {-170, -120, -170, -120, -170, -120, -360}, true}), kOk);
  h.powerOnAndSettle();
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), kOk);
  const auto q0 = h.state().q;
  std::array<double, 7> goal = q0;
  goal[0] = 0.5;  // 28.6 deg, far beyond the 10 deg soft limit
  JointMotionGenerator out(0.5, goal);
  out.calculateSynchronizedValues_joint(q0);
  const double limit = 10 * M_PI / 180;
  double highest = -1, fastest_decel = 0, previous_v = 0;
  bool finished = false;
  std::array<double, 7> q{};
  for (int k = 0; !finished; ++k) {
    std::array<double, 7> delta{};
    finished = out.calculateDesiredValues_joint(0.001 * k, delta);
    for (size_t i = 0; i < 7; ++i) q[i] = q0[i] + delta[i];
    h.stepJoint(q);
    QVERIFY2(!h.anyError(), h.errorList().c_str());
    highest = std::max(highest, h.state().q[0]);
    fastest_decel = std::max(fastest_decel, (previous_v - h.state().dq_m[0]) / 0.001);
    previous_v = h.state().dq_m[0];
  }
  for (int k = 0; k < 300; ++k) h.stepJoint(q);
  qInfo("command to %.3f rad; J1 stopped at %.5f rad (soft limit %.5f), hardest braking %.2f rad/s^2", goal[0],
        h.state().q[0], limit, fastest_decel);
  QVERIFY(highest <= limit + 1e-4);
  QVERIFY(std::abs(h.state().q[0] - limit) < 1e-4);
  QVERIFY(fastest_decel < 15);  // J1's acceleration limit
  // Back inside: the arm follows the command again.
  JointMotionGenerator back(0.5, q0);
  back.calculateSynchronizedValues_joint(q);
  finished = false;
  for (int k = 0; !finished; ++k) {
    std::array<double, 7> delta{}, p{};
    finished = back.calculateDesiredValues_joint(0.001 * k, delta);
    for (size_t i = 0; i < 7; ++i) p[i] = q[i] + delta[i];
    h.stepJoint(p, finished);
    QVERIFY2(!h.anyError(), h.errorList().c_str());
  }
  h.idle(300);
  QVERIFY(std::abs(h.state().q[0] - q0[0]) < 1e-6);
  // A motion that ends beyond the limit leaves the arm resting at the limit.
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), kOk);
  const auto again = h.state().q;
  out.calculateSynchronizedValues_joint(again);
  finished = false;
  for (int k = 0; !finished; ++k) {
    std::array<double, 7> delta{}, p{};
    finished = out.calculateDesiredValues_joint(0.001 * k, delta);
    for (size_t i = 0; i < 7; ++i) p[i] = again[i] + delta[i];
    h.stepJoint(p, finished);
  }
  h.idle(1000);
  QVERIFY2(!h.anyError(), h.errorList().c_str());
  QVERIFY(std::abs(h.state().q[0] - limit) < 1e-6);
}

void TestSimSafety::jointDragMovesUnderAWrench() {
  Harness h;
  h.powerOnAndSettle();
  QCOMPARE(h.startDrag(0, 2), kOk);
  XmateModel model(XMATE7_PRO);
  const auto q0 = h.state().q;
  const std::array<double, 6> push{0, 10, 0, 0, 0, 0};
  h.controller().setExternalWrench(push);
  h.idle(500);
  const auto tau = jointTorques(model, h.state().q, push);
  qInfo("joint drag: J1 %.4f rad/s under %.3f Nm (damping 20 Nm s/rad -> %.4f)", h.state().dq_m[0], tau[0],
        tau[0] / 20);
  // Not exact: the push also turns J3, J5 and J7, and their motion couples back through M(q).
  QVERIFY(std::abs(h.state().dq_m[0] - tau[0] / 20) < 0.1 * std::abs(tau[0] / 20));
  QVERIFY(h.state().q[0] - q0[0] > 0.05);
  QCOMPARE(h.state().robot_mode, RobotMode::kGuiding);
  // Let go: the arm comes to rest and stays (gravity compensated).
  h.controller().setExternalWrench({});
  h.idle(3000);  // the slowest damped mode decays with ~0.2 s
  const auto rest = h.state().q;
  h.idle(1000);
  double drift = 0;
  for (size_t i = 0; i < 7; ++i) drift = std::max(drift, std::abs(h.state().q[i] - rest[i]));
  QVERIFY(drift < 1e-6);
  QVERIFY2(!h.anyError(), h.errorList().c_str());
}

void TestSimSafety::cartesianDragTranslationOnly() {
  Harness h;
  h.powerOnAndSettle();
  const Eigen::Isometry3d start = poseOf(h.state().toolTobase_pos_m);
  QCOMPARE(h.startDrag(1, 0), kOk);
  h.controller().setExternalWrench({10, 0, 0, 0, 0, 2});  // a push along x and a twist about z
  h.idle(1000);
  const Eigen::Isometry3d end = poseOf(h.state().toolTobase_pos_m);
  const Eigen::Vector3d moved = end.translation() - start.translation();
  qInfo("translation-only drag, 1 s: moved (%.4f, %.4f, %.4f) m, turned %.4f rad; v_x %.4f m/s", moved.x(),
        moved.y(), moved.z(), rotationAngle(start, end), h.state().toolTobase_vel_c[0]);
  QVERIFY(moved.x() > 0.07);                           // free: about F / 100 N s/m = 0.1 m/s
  QVERIFY(std::abs(moved.y()) < 0.1 * moved.x());
  QVERIFY(std::abs(moved.z()) < 0.1 * moved.x());
  QVERIFY(rotationAngle(start, end) < 2.0 / 300 * 1.5);  // held: about M / K = 6.7 mrad
  QVERIFY2(!h.anyError(), h.errorList().c_str());
}

void TestSimSafety::cartesianDragRotationOnly() {
  Harness h;
  h.powerOnAndSettle();
  const Eigen::Isometry3d start = poseOf(h.state().toolTobase_pos_m);
  QCOMPARE(h.startDrag(1, 1), kOk);
  h.controller().setExternalWrench({10, 0, 0, 0, 0, 1});
  h.idle(1000);
  const Eigen::Isometry3d end = poseOf(h.state().toolTobase_pos_m);
  const double moved = (end.translation() - start.translation()).norm();
  const Eigen::AngleAxisd turn(end.linear() * start.linear().transpose());
  qInfo("rotation-only drag, 1 s: moved %.4f m, turned %.4f rad about (%.2f, %.2f, %.2f)", moved, turn.angle(),
        turn.axis().x(), turn.axis().y(), turn.axis().z());
  QVERIFY(moved < 10.0 / 3000 * 1.5);  // held: about F / K = 3.3 mm
  QVERIFY(turn.angle() > 0.07);        // free: about M / 10 Nm s/rad = 0.1 rad/s
  QVERIFY(turn.axis().z() > 0.95);
  QVERIFY2(!h.anyError(), h.errorList().c_str());
}

void TestSimSafety::cartesianDragFree() {
  Harness h;
  h.powerOnAndSettle();
  const Eigen::Isometry3d start = poseOf(h.state().toolTobase_pos_m);
  QCOMPARE(h.startDrag(1, 2), kOk);
  h.controller().setExternalWrench({0, 0, -10, 0, 0, 1});
  h.idle(1000);
  const Eigen::Isometry3d end = poseOf(h.state().toolTobase_pos_m);
  QVERIFY(start.translation().z() - end.translation().z() > 0.07);
  QVERIFY(rotationAngle(start, end) > 0.07);
  QVERIFY2(!h.anyError(), h.errorList().c_str());
}

void TestSimSafety::guardStopEndsGuiding() {
  Harness h;
  h.powerOnAndSettle();
  QCOMPARE(h.startDrag(1, 2), kOk);
  h.controller().setExternalWrench({10, 0, 0, 0, 0, 0});
  h.idle(300);
  h.controller().setGuardStop(true);
  h.idle(300);
  QVERIFY(!h.status().dragging);
  QVERIFY(h.status().motors_on);
  const auto q = h.state().q;
  h.idle(300);
  for (size_t i = 0; i < 7; ++i) QVERIFY(std::abs(h.state().q[i] - q[i]) < 1e-3);  // held against the push
  QCOMPARE(h.startDrag(1, 2), uint8_t(1));
}

QTEST_APPLESS_MAIN(TestSimSafety)
#include "test_sim_safety.moc"
