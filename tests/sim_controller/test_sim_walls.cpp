// SPDX-License-Identifier: Apache-2.0
// sim::Controller limits that leave a way back: while hand guiding, joint limits and the safety box
// are walls (a spring, then the brakes) that no pull carries the arm through, without an error bit;
// the 7-axis arm angle's rate is limited below its monitor and the wrist centre kept off the J1 axis;
// a joint or TCP beyond a limit (placed there by the scene) may be guided or jogged back, and only
// motion further out is refused with its bit.
#include <QtTest/QtTest>

#include <algorithm>
#include <cmath>

#include <xmate/model.h>

#include "controller_harness.h"
#include "model/robot_spec.h"
#include "sim/drag_walls.h"
#include "sim/error_bits.h"
#include "sim/safety.h"

using namespace xmate;
using namespace xmate::sim;
using namespace xmate::sim::test;
using RCI::robot::RobotMode;

namespace {

constexpr uint8_t kOk = 0;
constexpr double kDeg = M_PI / 180.0;
constexpr double kWithin = 1e-9;  // rad or m: "at the limit" allows only rounding

const model::RobotSpec& spec() { return model::robotSpec(XMATE7_PRO); }

// Soft limits `degrees` around q for every joint (clipped to the hardware range); 0 keeps a joint's
// hardware range.
protocol::SetJointLimitRequest limitsAround(const std::array<double, 7>& q, double degrees) {
  protocol::SetJointLimitRequest r;
  for (size_t i = 0; i < 7; ++i) {
    const double low = spec().q_min[i] / kDeg, high = spec().q_max[i] / kDeg;
    r.upper[i] = degrees > 0 ? std::min(high, q[i] / kDeg + degrees) : high;
    r.lower[i] = degrees > 0 ? std::max(low, q[i] / kDeg - degrees) : low;
  }
  return r;
}

// The scene's wrench rises linearly to `wrench` over ramp_ms, then stays for hold_ms; every cycle
// `each` sees the state. Returns false (and stops) as soon as an error bit shows.
bool pull(Harness& h, const std::array<double, 6>& wrench, int ramp_ms, int hold_ms,
          const std::function<void()>& each = [] {}) {
  for (int k = 1; k <= ramp_ms + hold_ms; ++k) {
    const double s = ramp_ms > 0 ? std::min(1.0, double(k) / ramp_ms) : 1.0;
    std::array<double, 6> w{};
    for (size_t i = 0; i < 6; ++i) w[i] = s * wrench[i];
    h.controller().setExternalWrench(w);
    h.idle(1);
    each();
    if (h.anyError()) return false;
  }
  return true;
}

// Largest excursion of any joint beyond the limits of `r` (rad; <= 0 when inside).
double beyondLimits(const RobotState& s, const protocol::SetJointLimitRequest& r) {
  double worst = -INFINITY;
  for (size_t i = 0; i < 7; ++i)
    worst = std::max({worst, s.q[i] - r.upper[i] * kDeg, r.lower[i] * kDeg - s.q[i]});
  return worst;
}

// How many joints rest at one of their limits (within 1e-6 rad).
int jointsAtLimits(const RobotState& s, const protocol::SetJointLimitRequest& r) {
  int n = 0;
  for (size_t i = 0; i < 7; ++i)
    n += std::abs(s.q[i] - r.upper[i] * kDeg) < 1e-6 || std::abs(s.q[i] - r.lower[i] * kDeg) < 1e-6;
  return n;
}

Eigen::Vector3d tcpPosition(const Harness& h) { return poseOf(h.state().toolTobase_pos_m).translation(); }

// A joint position motion from the current q to goal along a quintic (minimum-jerk) profile --
// the vendor's S-curve generator refuses goals beyond the hardware range, which these tests need --
// then 200 cycles of hold. Returns the cycle at which an error bit showed, -1 if none did, -2 if
// StartMove was refused.
int jog(Harness& h, const std::array<double, 7>& goal) {
  if (h.startMove(CM::kJointPosition, MG::kJointPosition) != kOk) return -2;
  const auto q0 = h.state().q;
  double distance = 0;
  for (size_t i = 0; i < 7; ++i) distance = std::max(distance, std::abs(goal[i] - q0[i]));
  const int cycles = int(std::max(0.5, 4.0 * distance) * 1000);  // peak speed below 0.5 rad/s
  for (int k = 1; k <= cycles; ++k) {
    const double t = double(k) / cycles, s = t * t * t * (10 - 15 * t + 6 * t * t);
    std::array<double, 7> q{};
    for (size_t i = 0; i < 7; ++i) q[i] = q0[i] + s * (goal[i] - q0[i]);
    h.stepJoint(q, k == cycles);
    if (h.anyError()) return k;
  }
  h.idle(200);
  return h.anyError() ? 0 : -1;
}

std::array<double, 7> with(std::array<double, 7> q, size_t joint, double value) {
  q[joint] = value;
  return q;
}

// The strongest pull of the window: Shift+drag in the 3D view (RobotView::kPullMaxForce, N).
constexpr double kStrongestPull = 60.0;
// Bit 2 trips above this measured arm-angle rate (rad/s).
const double kElbowRateMonitor = kActualVelocityFactor * model::controllerCartesianLimits().v_elbow;

std::array<double, 7> degrees(const std::array<double, 7>& q_deg) {
  std::array<double, 7> q{};
  for (size_t i = 0; i < 7; ++i) q[i] = q_deg[i] * kDeg;
  return q;
}

// The wrist centre's distance from the J1 axis (the base z axis), m; no tool set.
double wristAxisRadius(const RobotState& s) {
  const Eigen::Isometry3d flange = poseOf(s.toolTobase_pos_m);
  return (flange.translation() - spec().dh[6].d * flange.linear().col(2)).head<2>().norm();
}

// Watches a pull: the fastest measured arm-angle rate (the rate bit 2 watches, from psi_m) and the
// wrist centre's closest approach to the J1 axis.
struct ArmAngleWatch {
  explicit ArmAngleWatch(const Harness& harness)
      : h(&harness), psi(harness.state().psi_m), closest(wristAxisRadius(harness.state())) {}
  void operator()() {
    fastest = std::max(fastest, std::abs(std::remainder(h->state().psi_m - psi, 2 * M_PI)) / 0.001);
    psi = h->state().psi_m;
    closest = std::min(closest, wristAxisRadius(h->state()));
  }
  const Harness* h;
  double psi;
  double closest;
  double fastest = 0;
};

double farthestJoint(const std::array<double, 7>& a, const std::array<double, 7>& b) {
  double d = 0;
  for (size_t i = 0; i < 7; ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

}  // namespace

class TestSimWalls : public QObject {
  Q_OBJECT

 private slots:
  void jointWallIsASpringWithinTheMotorsStrength();
  void startingInsideAWallDoesNotMoveTheArm();
  void overpoweringPullIsHeldAtTheJointLimits();
  void wristMomentOf500NmIsHeld();
  void hardwareLimitHoldsInCartesianGuiding();
  void releasedFromTheWallItComesBackSlowly();
  void hardTwistSaturatesTheGuidingSpeed();
  void safetyBoxIsAWallInCartesianGuiding();
  void safetyBoxIsAWallInJointGuiding();
  void jointBeyondItsLimitGuidesAndJogsBack();
  void jointBeyondItsLimitInCartesianMotion();
  void tcpOutsideTheBoxPowersOnAndComesBack();
  void placeArmChecksItsArgument();
  void cartesianPushTowardsTheJ1AxisIsHeldAtTheWristAxisWall();
  void jointGuidingIsHeldAtTheWristAxisWall();
  void pullsEverywhereKeepTheArmAngleRateBelowItsMonitor();
  void guidingStartedCloseToTheJ1AxisStaysAndLeaves();
};

void TestSimWalls::jointWallIsASpringWithinTheMotorsStrength() {
  // J1 10 deg from its soft limit; a 10 N push turns it (as in test_sim_safety) into the wall,
  // where it comes to rest on the spring, short of the limit.
  Harness h;
  h.powerOnAndSettle();
  const auto q0 = h.state().q;
  auto limits = limitsAround(q0, 0);
  limits.upper[0] = q0[0] / kDeg + 10;
  QCOMPARE(h.status(limits), kOk);
  QCOMPARE(h.startDrag(0, 2), kOk);
  QVERIFY2(pull(h, {0, 10, 0, 0, 0, 0}, 0, 4000), h.errorList().c_str());
  const double limit = limits.upper[0] * kDeg, q = h.state().q[0];
  qInfo("J1 rests %.3f deg before its limit (the wall begins 5 deg before it), |dq| %.2e rad/s", (limit - q) / kDeg,
        std::abs(h.state().dq_m[0]));
  QVERIFY(q > limit - 5 * kDeg);   // in the wall
  QVERIFY(q < limit - 3 * kDeg);   // held by the spring, far from the limit
  QVERIFY(std::abs(h.state().dq_m[0]) < 1e-3);
  QCOMPARE(h.state().robot_mode, RobotMode::kGuiding);
}

void TestSimWalls::startingInsideAWallDoesNotMoveTheArm() {
  // Guiding starts 2 deg from J6's hardware limit (inside the 5 deg wall): the spring begins where
  // the arm is, so nothing moves by itself.
  SimConfig config;
  config.initial_q = {0, 0.5236, 0, 1.0472, 0, 118 * kDeg, 0};
  Harness h(config);
  h.powerOnAndSettle();
  const auto q0 = h.state().q;
  QCOMPARE(h.startDrag(0, 2), kOk);
  h.idle(1000);
  double moved = 0;
  for (size_t i = 0; i < 7; ++i) moved = std::max(moved, std::abs(h.state().q[i] - q0[i]));
  QVERIFY2(moved < 1e-6, qPrintable(QString("moved %1 rad").arg(moved)));
  QVERIFY2(!h.anyError(), h.errorList().c_str());
}

void TestSimWalls::overpoweringPullIsHeldAtTheJointLimits() {
  // Every joint 3 deg from soft limits on both sides; 500 N (ramped in over 0.5 s so no joint is
  // flung past its speed limit on the way) for 3 s: far more than the motors can resist.
  Harness h;
  h.powerOnAndSettle();
  const auto limits = limitsAround(h.state().q, 3);
  QCOMPARE(h.status(limits), kOk);
  QCOMPARE(h.startDrag(0, 2), kOk);
  double worst = -INFINITY;
  QVERIFY2(pull(h, {0, 500, 0, 0, 0, 0}, 500, 3000, [&] { worst = std::max(worst, beyondLimits(h.state(), limits)); }),
           h.errorList().c_str());
  qInfo("500 N: %d joints at a limit, the farthest %.2e rad beyond", jointsAtLimits(h.state(), limits), worst);
  QVERIFY(worst <= kWithin);
  QVERIFY(jointsAtLimits(h.state(), limits) >= 2);
  QVERIFY(h.status().dragging);
  QVERIFY(h.status().motors_on);
  // Pulled back, it leaves the walls.
  const auto held = h.state().q;
  QVERIFY2(pull(h, {0, -20, 0, 0, 0, 0}, 0, 1000), h.errorList().c_str());
  double moved = 0;
  for (size_t i = 0; i < 7; ++i) moved = std::max(moved, std::abs(h.state().q[i] - held[i]));
  qInfo("pulled back with 20 N for 1 s: the farthest joint moved %.2f deg", moved / kDeg);
  QVERIFY(moved > 1 * kDeg);
  QVERIFY(beyondLimits(h.state(), limits) <= kWithin);
}

void TestSimWalls::wristMomentOf500NmIsHeld() {
  Harness h;
  h.powerOnAndSettle();
  const auto limits = limitsAround(h.state().q, 3);
  QCOMPARE(h.status(limits), kOk);
  QCOMPARE(h.startDrag(0, 2), kOk);
  double worst = -INFINITY;
  QVERIFY2(pull(h, {0, 0, 0, 0, 0, 500}, 500, 3000, [&] { worst = std::max(worst, beyondLimits(h.state(), limits)); }),
           h.errorList().c_str());
  qInfo("500 Nm about z: %d joints at a limit, the farthest %.2e rad beyond", jointsAtLimits(h.state(), limits),
        worst);
  QVERIFY(worst <= kWithin);
  QVERIFY(jointsAtLimits(h.state(), limits) >= 1);
}

void TestSimWalls::hardwareLimitHoldsInCartesianGuiding() {
  // The operator's case: J6 near its 120 deg hardware limit, Cartesian free guiding, pulled hard.
  // The other joints are kept within 4 deg so that the pull ends at walls, not in a too-fast swing.
  SimConfig config;
  config.initial_q = {0, 0.5236, 0, 1.0472, 0, 117 * kDeg, 0};
  Harness h(config);
  h.powerOnAndSettle();
  auto limits = limitsAround(h.state().q, 4);
  limits.upper[5] = 120;  // J6: the hardware limit
  QCOMPARE(h.status(limits), kOk);
  QCOMPARE(h.startDrag(1, 2), kOk);
  double worst = -INFINITY;
  // 500 Nm about y turns J2, J4 and J6 (parallel axes in this pose) up into their walls.
  QVERIFY2(pull(h, {0, 0, 0, 0, 500, 0}, 500, 2000, [&] { worst = std::max(worst, beyondLimits(h.state(), limits)); }),
           h.errorList().c_str());
  qInfo("500 Nm about y: J6 at %.4f deg, %d joints at a limit", h.state().q[5] / kDeg, jointsAtLimits(h.state(), limits));
  QVERIFY(std::abs(h.state().q[5] - 120 * kDeg) < 1e-6);
  // A gentle twist back (10 Nm: about 1 rad/s in free Cartesian guiding) brings it out of the wall.
  QVERIFY2(pull(h, {0, 0, 0, 0, -10, 0}, 0, 300), h.errorList().c_str());
  qInfo("twisted back: J6 at %.3f deg", h.state().q[5] / kDeg);
  QVERIFY(h.state().q[5] < 119 * kDeg);
  QVERIFY(worst <= kWithin);
  QVERIFY(h.state().q[5] <= 120 * kDeg + kWithin);
  QVERIFY(h.status().dragging);
}

void TestSimWalls::releasedFromTheWallItComesBackSlowly() {
  // Pushed against the wall and let go: the spring pushes the joint back out, no faster than about
  // the wall's return speed (0.5 rad/s), far below the velocity limit (no bit 3).
  Harness h;
  h.powerOnAndSettle();
  const auto limits = limitsAround(h.state().q, 3);
  QCOMPARE(h.status(limits), kOk);
  QCOMPARE(h.startDrag(0, 2), kOk);
  QVERIFY2(pull(h, {0, 0, 0, 0, 0, 200}, 300, 500), h.errorList().c_str());
  double fastest = 0;
  QVERIFY2(pull(h, {}, 0, 1500, [&] {
             for (size_t i = 0; i < 7; ++i) fastest = std::max(fastest, std::abs(h.state().dq_m[i]));
           }),
           h.errorList().c_str());
  qInfo("released from the walls: fastest joint %.3f rad/s", fastest);
  QVERIFY(fastest < 0.8);
  QVERIFY(fastest > 0.01);  // it did come back out
}

void TestSimWalls::hardTwistSaturatesTheGuidingSpeed() {
  // A 40 Nm twist about z on the free arm in joint-space guiding would spin the wrist (damped
  // 5 Nm s/rad) far beyond its rated speed and trip bit 3; the guiding speed limit saturates every
  // joint below the velocity monitor's threshold instead, and the TCP below 1 m/s.
  Harness h;
  h.powerOnAndSettle();
  QCOMPARE(h.startDrag(0, 2), kOk);
  double worst_ratio = 0, fastest_tcp = 0;
  auto previous = tcpPosition(h);
  QVERIFY2(pull(h, {0, 0, 0, 0, 0, 40}, 100, 1500, [&] {
             for (size_t i = 0; i < 7; ++i)
               worst_ratio = std::max(worst_ratio, std::abs(h.state().dq_m[i]) / spec().dq_max[i]);
             const auto now = tcpPosition(h);
             fastest_tcp = std::max(fastest_tcp, (now - previous).norm() * 1000.0);
             previous = now;
           }),
           h.errorList().c_str());
  qInfo("40 Nm twist: fastest joint at %.2f x its rated speed, TCP at most %.2f m/s", worst_ratio, fastest_tcp);
  QVERIFY(worst_ratio < 0.95);
  QVERIFY(worst_ratio > 0.5);  // it was pushed hard: the limit, not the push, set the speed
  QVERIFY(fastest_tcp < 1.0);
  QVERIFY(h.status().dragging);
}

void TestSimWalls::safetyBoxIsAWallInCartesianGuiding() {
  Harness h;
  h.powerOnAndSettle();
  Eigen::Isometry3d box = Eigen::Isometry3d::Identity();
  box.translation() = tcpPosition(h);
  QCOMPARE(h.status(protocol::SetCartesianLimitRequest{{0.2, 0.2, 0.2}, rowMajor(box), true}), kOk);
  QCOMPARE(h.startDrag(1, 0), kOk);  // translation
  double farthest = 0;
  QVERIFY2(pull(h, {500, 0, 0, 0, 0, 0}, 1000, 3000,
                [&] { farthest = std::max(farthest, tcpPosition(h).x() - box.translation().x()); }),
           h.errorList().c_str());
  qInfo("500 N along x, face 0.1 m away: the TCP reached %.5f m, rests at %.5f m", farthest,
        tcpPosition(h).x() - box.translation().x());
  QVERIFY(farthest <= 0.1);
  QVERIFY(farthest > 0.095);  // at the face
  QVERIFY(h.status().motors_on);
  const double held = tcpPosition(h).x();
  QVERIFY2(pull(h, {-20, 0, 0, 0, 0, 0}, 0, 1000), h.errorList().c_str());
  qInfo("pulled back with 20 N for 1 s: %.4f m", held - tcpPosition(h).x());
  QVERIFY(held - tcpPosition(h).x() > 0.05);
}

void TestSimWalls::safetyBoxIsAWallInJointGuiding() {
  // Joint-space guiding, a 10 cm box face 3 cm below the TCP, pushed down with 300 N: the joints
  // must stop together so that the TCP stays inside (joints within 10 deg, so none is flung).
  Harness h;
  h.powerOnAndSettle();
  QCOMPARE(h.status(limitsAround(h.state().q, 10)), kOk);
  Eigen::Isometry3d box = Eigen::Isometry3d::Identity();
  box.translation() = tcpPosition(h) + Eigen::Vector3d(0, 0, 0.02);
  QCOMPARE(h.status(protocol::SetCartesianLimitRequest{{0.1, 0.1, 0.1}, rowMajor(box), true}), kOk);
  QCOMPARE(h.startDrag(0, 2), kOk);
  double deepest = 0;
  QVERIFY2(pull(h, {0, 0, -300, 0, 0, 0}, 1000, 3000,
                [&] { deepest = std::max(deepest, box.translation().z() - tcpPosition(h).z()); }),
           h.errorList().c_str());
  qInfo("300 N down, face 0.03 m below: the TCP reached %.5f m below the centre (face at 0.05)", deepest);
  QVERIFY(deepest <= 0.05);
  QVERIFY(deepest > 0.045);
  QVERIFY(h.status().motors_on);
}

void TestSimWalls::jointBeyondItsLimitGuidesAndJogsBack() {
  // The operator's trap: J6 ended 0.69 deg beyond its 120 deg limit. (The other joints are kept
  // within 3 deg, so that the push on J6 does not swing them instead.)
  Harness h;
  h.powerOnAndSettle();
  auto limits = limitsAround(h.state().q, 3);
  limits.upper[5] = 120;
  limits.lower[5] = -120;
  QCOMPARE(h.status(limits), kOk);
  const auto outside = with(h.state().q, 5, 120.69 * kDeg);
  h.controller().placeArm(outside);
  h.idle(50);
  QVERIFY2(!h.anyError(), h.errorList().c_str());
  // Guiding starts; pushing further out is held where it is (+ the 0.3 deg allowance), no error.
  QCOMPARE(h.startDrag(0, 2), kOk);
  XmateModel model(XMATE7_PRO);
  const auto jac = model.Jacobian(h.state().q);
  // A moment about J6's axis (column 5 of the angular Jacobian), in the direction that turns it up.
  const std::array<double, 6> up{0, 0, 0, 30 * jac[3 * 7 + 5], 30 * jac[4 * 7 + 5], 30 * jac[5 * 7 + 5]};
  double highest = 0;
  QVERIFY2(pull(h, up, 200, 1000, [&] { highest = std::max(highest, h.state().q[5]); }), h.errorList().c_str());
  qInfo("J6 pushed further out: at most %.4f deg (placed at 120.69)", highest / kDeg);
  QVERIFY(highest <= 120.69 * kDeg + 0.005 + kWithin);
  // ... and guided back in freely.
  const std::array<double, 6> down{0, 0, 0, -up[3] / 10, -up[4] / 10, -up[5] / 10};
  QVERIFY2(pull(h, down, 0, 1000), h.errorList().c_str());
  qInfo("guided back: J6 at %.3f deg", h.state().q[5] / kDeg);
  QVERIFY(h.state().q[5] < 119 * kDeg);
  h.controller().setExternalWrench({});
  QCOMPARE(h.empty(protocol::Command::kStopDrag), kOk);
  h.idle(500);

  // Placed outside again: a jog further out is refused with bit 7 ...
  h.controller().placeArm(outside);
  h.idle(20);
  QVERIFY(jog(h, with(outside, 5, 121.5 * kDeg)) >= 0);
  QVERIFY2(h.state().errors[kCommandJointPositionLimitsViolation], h.errorList().c_str());
  QCOMPARE(h.errorList(), std::string("kCommandJointPositionLimitsViolation"));
  // ... recovery, and a jog back in runs without an error.
  QCOMPARE(h.recover(), kOk);
  h.idle(100);
  QCOMPARE(jog(h, with(outside, 5, 115 * kDeg)), -1);
  QVERIFY(std::abs(h.state().q[5] - 115 * kDeg) < 1e-4);
  // Once back inside, the limit is the limit again.
  QVERIFY(jog(h, with(h.state().q, 5, 120.3 * kDeg)) >= 0);
  QVERIFY(h.state().errors[kCommandJointPositionLimitsViolation]);
}

void TestSimWalls::jointBeyondItsLimitInCartesianMotion() {
  // Beyond the hardware range the IK searches the allowance too: a Cartesian motion that keeps the
  // pose runs (J6 stays where it is), a jog back in then works.
  Harness h;
  h.powerOnAndSettle();
  h.controller().placeArm(with(h.state().q, 5, 120.5 * kDeg));
  h.idle(20);
  QCOMPARE(h.startMove(CM::kCartesianPosition, MG::kCartesianPosition), kOk);
  const Eigen::Isometry3d pose = poseOf(h.state().toolTobase_pos_m);
  for (int k = 0; k < 200; ++k) h.stepCartesian(pose, k == 199);
  h.idle(100);
  QVERIFY2(!h.anyError(), h.errorList().c_str());
  QVERIFY(std::abs(h.state().q[5] - 120.5 * kDeg) < 1e-3);
}

void TestSimWalls::tcpOutsideTheBoxPowersOnAndComesBack() {
  Harness h;
  const Eigen::Vector3d start = tcpPosition(h);
  // Motors off: a box whose +x face is 3 cm behind the TCP (accepted while unpowered).
  Eigen::Isometry3d box = Eigen::Isometry3d::Identity();
  box.translation() = start - Eigen::Vector3d(0.13, 0, 0);
  QCOMPARE(h.status(protocol::SetCartesianLimitRequest{{0.2, 0.6, 0.2}, rowMajor(box), true}), kOk);
  // Powering on outside is no error: the robot may come back.
  QCOMPARE(h.setMotorPower(1), kOk);
  h.idle(100);
  QVERIFY2(!h.anyError(), h.errorList().c_str());
  QVERIFY(h.status().motors_on);
  // J1 turns the TCP (0.5 m out along x) sideways and a little back in x: allowed...
  const auto q0 = h.state().q;
  QCOMPARE(jog(h, with(q0, 0, 0.3)), -1);
  const double x_turned = tcpPosition(h).x();
  qInfo("J1 0.3 rad: x %.4f -> %.4f m (face at %.4f)", start.x(), x_turned, box.translation().x() + 0.1);
  QVERIFY(x_turned < start.x());
  // ... turning back towards the start moves it out again (beyond the allowance): bit 1, power off.
  QVERIFY(jog(h, q0) >= 0);
  QVERIFY2(h.state().errors[kActualCartesianPositionLimitsViolation], h.errorList().c_str());
  QVERIFY(!h.status().motors_on);
  QCOMPARE(h.recover(), kOk);
  QCOMPARE(h.setMotorPower(1), kOk);
  h.idle(100);
  QVERIFY2(!h.anyError(), h.errorList().c_str());
  // Guided back into the box: pulled along -x, the TCP comes in; pushed out again, it is held.
  QCOMPARE(h.startDrag(1, 0), kOk);
  QVERIFY2(pull(h, {-20, 0, 0, 0, 0, 0}, 0, 3000), h.errorList().c_str());
  const double face = box.translation().x() + 0.1;
  qInfo("guided in: x %.4f m, face %.4f m", tcpPosition(h).x(), face);
  QVERIFY(tcpPosition(h).x() < face - 0.01);
  double farthest = -INFINITY;
  QVERIFY2(pull(h, {300, 0, 0, 0, 0, 0}, 1000, 2000, [&] { farthest = std::max(farthest, tcpPosition(h).x()); }),
           h.errorList().c_str());
  QVERIFY(farthest <= face);
}

void TestSimWalls::placeArmChecksItsArgument() {
  Harness h;
  auto q = h.state().q;
  q[1] = 121 * kDeg;
  h.controller().placeArm(q);  // beyond the hardware limit: allowed
  QCOMPARE(h.state().q[1], q[1]);
  q[1] = 135 * kDeg;
  QVERIFY_THROWS_EXCEPTION(std::invalid_argument, h.controller().placeArm(q));
  q[1] = NAN;
  QVERIFY_THROWS_EXCEPTION(std::invalid_argument, h.controller().placeArm(q));
}

void TestSimWalls::cartesianPushTowardsTheJ1AxisIsHeldAtTheWristAxisWall() {
  // The operator's case: Cartesian free guiding (startDrag(2, 3)) from (0, 30, 0, 60, 0, 90, 0)
  // pushed along -x with the window's strongest pull. The wrist centre heads for the J1 axis, where
  // the arm angle turns over by pi (bit 2 after about 1.5 s without the wall); it is held at the
  // wrist-axis wall instead, and comes back out when pulled.
  Harness h;
  h.powerOnAndSettle();
  const auto q0 = h.state().q;
  QCOMPARE(h.startDrag(1, 2), kOk);
  ArmAngleWatch watch(h);
  QVERIFY2(pull(h, {-kStrongestPull, 0, 0, 0, 0, 0}, 0, 3000, std::ref(watch)), h.errorList().c_str());
  qInfo("%.0f N along -x for 3 s: wrist centre at least %.4f m from the J1 axis (now %.4f), |psi rate| at most "
        "%.2f rad/s (bit 2 above %.2f)",
        kStrongestPull, watch.closest, wristAxisRadius(h.state()), watch.fastest, kElbowRateMonitor);
  QVERIFY(watch.fastest < kElbowRateMonitor);
  QVERIFY(watch.closest >= kWristAxisHoldRadius - 1e-3);
  QVERIFY(watch.closest < kWristAxisHoldRadius + kWristAxisWallWidth);  // it did reach the wall
  QCOMPARE(h.state().robot_mode, RobotMode::kGuiding);
  // Released, the spring lets it out slowly; pulled back along +x it leaves the wall.
  const double held = wristAxisRadius(h.state());
  QVERIFY2(pull(h, {}, 0, 500, std::ref(watch)), h.errorList().c_str());
  QVERIFY2(pull(h, {30, 0, 0, 0, 0, 0}, 0, 1500, std::ref(watch)), h.errorList().c_str());
  qInfo("pulled back with 30 N for 1.5 s: the wrist centre %.4f -> %.4f m from the axis", held,
        wristAxisRadius(h.state()));
  QVERIFY(wristAxisRadius(h.state()) > held + 0.1);
  QVERIFY(watch.fastest < kElbowRateMonitor);
  // stopDrag, and a joint motion (MOVEJ) back to where guiding started.
  h.controller().setExternalWrench({});
  QCOMPARE(h.empty(protocol::Command::kStopDrag), kOk);
  h.idle(300);
  QCOMPARE(jog(h, q0), -1);
  QVERIFY(farthestJoint(h.state().q, q0) < 1e-3);
}

void TestSimWalls::jointGuidingIsHeldAtTheWristAxisWall() {
  // Joint-space guiding from the same pose pushed up: the wrist centre would cross the J1 axis
  // (the arm angle turning over by pi); the wall holds it off the axis here too.
  Harness h;
  h.powerOnAndSettle();
  const auto q0 = h.state().q;
  QCOMPARE(h.startDrag(0, 2), kOk);
  ArmAngleWatch watch(h);
  QVERIFY2(pull(h, {0, 0, kStrongestPull, 0, 0, 0}, 0, 3000, std::ref(watch)), h.errorList().c_str());
  qInfo("%.0f N up for 3 s: wrist centre at least %.4f m from the J1 axis, |psi rate| at most %.2f rad/s",
        kStrongestPull, watch.closest, watch.fastest);
  QVERIFY(watch.fastest < kElbowRateMonitor);
  QVERIFY(watch.closest >= kWristAxisHoldRadius - 1e-3);
  QVERIFY(watch.closest < kWristAxisHoldRadius + kWristAxisWallWidth);
  // Released: the spring brings it out of the wall no faster than about its return speed.
  double fastest_joint = 0;
  QVERIFY2(pull(h, {}, 0, 1000, [&] {
             watch();
             for (size_t i = 0; i < 7; ++i) fastest_joint = std::max(fastest_joint, std::abs(h.state().dq_m[i]));
           }),
           h.errorList().c_str());
  qInfo("released: fastest joint %.3f rad/s, wrist centre %.4f m from the axis", fastest_joint,
        wristAxisRadius(h.state()));
  QVERIFY(fastest_joint < 0.8);
  QVERIFY(wristAxisRadius(h.state()) >= kWristAxisHoldRadius);
  h.controller().setExternalWrench({});
  QCOMPARE(h.empty(protocol::Command::kStopDrag), kOk);
  h.idle(300);
  QCOMPARE(jog(h, q0), -1);
  QVERIFY(farthestJoint(h.state().q, q0) < 1e-3);
}

void TestSimWalls::pullsEverywhereKeepTheArmAngleRateBelowItsMonitor() {
  // The window's strongest pull along 26 directions (axes, face and space diagonals), for 3 s each,
  // in Cartesian and joint-space guiding, from four poses: the default one, two from which such a
  // pull swings the elbow beyond its rate monitor without the limit, and one with the wrist centre
  // 1.5 cm from the J1 axis (inside the wall). No error bit, the arm-angle rate below the monitor.
  const std::array<std::array<double, 7>, 4> poses{{{0, 30, 0, 60, 0, 90, 0},
                                                    {20, -20, 30, 80, -10, 60, 30},
                                                    {-127, 20, -121, 5, -112, 51, 182},
                                                    {129, -40, 2, 82, 22, -50, 235}}};
  // RCI_WALL_PULLS=axes (the sanitizer build, ~20x slower): the 6 axis directions only.
  const bool axes_only = qEnvironmentVariable("RCI_WALL_PULLS") == "axes";
  double fastest = 0;
  int runs = 0;
  for (int space : {1, 0}) {  // wire numbering: Cartesian (bit 2 watches it), then joint space
    for (const auto& pose : poses) {
      SimConfig config;
      config.initial_q = degrees(pose);
      QString name = space == 1 ? "Cartesian guiding from (" : "joint guiding from (";
      for (size_t i = 0; i < 7; ++i) name += QString::number(pose[i]) + (i < 6 ? ", " : ") deg");
      double fastest_here = 0, start_radius = 0;
      for (int x = -1; x <= 1; ++x) {
        for (int y = -1; y <= 1; ++y) {
          for (int z = -1; z <= 1; ++z) {
            if (x == 0 && y == 0 && z == 0) continue;
            if (axes_only && std::abs(x) + std::abs(y) + std::abs(z) != 1) continue;
            const Eigen::Vector3d f = kStrongestPull * Eigen::Vector3d(x, y, z).normalized();
            Harness h(config);
            h.powerOnAndSettle();
            QCOMPARE(h.startDrag(space, 2), kOk);
            start_radius = wristAxisRadius(h.state());
            ArmAngleWatch watch(h);
            const bool clean = pull(h, {f.x(), f.y(), f.z(), 0, 0, 0}, 0, 3000, std::ref(watch));
            const QString where = QString("%1, pulled (%2, %3, %4) N: errors %5, |psi rate| up to %6 rad/s")
                                      .arg(name)
                                      .arg(f.x(), 0, 'f', 1)
                                      .arg(f.y(), 0, 'f', 1)
                                      .arg(f.z(), 0, 'f', 1)
                                      .arg(QString::fromStdString(h.errorList()))
                                      .arg(watch.fastest);
            QVERIFY2(clean, qPrintable(where));
            QVERIFY2(watch.fastest < kElbowRateMonitor, qPrintable(where));
            QVERIFY2(watch.closest >= std::min(kWristAxisHoldRadius, start_radius) - 1e-3, qPrintable(where));
            QVERIFY2(h.status().dragging, qPrintable(where));
            fastest_here = std::max(fastest_here, watch.fastest);
            ++runs;
          }
        }
      }
      qInfo("%s (wrist centre %.3f m from the J1 axis): |psi rate| at most %.2f rad/s", qPrintable(name),
            start_radius, fastest_here);
      fastest = std::max(fastest, fastest_here);
    }
  }
  qInfo("%d pulls of %.0f N: |psi rate| at most %.2f rad/s (%.2f x v_elbow; bit 2 above %.2f)", runs, kStrongestPull,
        fastest, fastest / model::controllerCartesianLimits().v_elbow, kElbowRateMonitor);
}

void TestSimWalls::guidingStartedCloseToTheJ1AxisStaysAndLeaves() {
  // Guiding starts with the wrist centre 2.5 cm from the J1 axis, inside the wall: nothing moves by
  // itself; pushed towards the axis it is held where it started, and pulled away it leaves.
  SimConfig config;
  config.initial_q = degrees({0, -11.4, 0, 20, 0, 60, 0});
  Harness h(config);
  h.powerOnAndSettle();
  const auto q0 = h.state().q;
  const double start_radius = wristAxisRadius(h.state());
  QVERIFY(start_radius < kWristAxisHoldRadius);
  QCOMPARE(h.startDrag(1, 2), kOk);
  h.idle(1000);
  const double moved = farthestJoint(h.state().q, q0);
  QVERIFY2(moved < 1e-6, qPrintable(QString("moved %1 rad").arg(moved)));
  ArmAngleWatch watch(h);
  // The wrist centre lies behind the axis (-x): a push along +x drives it towards the axis.
  QVERIFY2(pull(h, {kStrongestPull, 0, 0, 0, 0, 0}, 0, 3000, std::ref(watch)), h.errorList().c_str());
  qInfo("started %.4f m from the J1 axis; pushed towards it: at least %.4f m, |psi rate| at most %.2f rad/s",
        start_radius, watch.closest, watch.fastest);
  QVERIFY(watch.closest >= start_radius - 1e-3);
  QVERIFY(watch.fastest < kElbowRateMonitor);
  QVERIFY2(pull(h, {-kStrongestPull, 0, 0, 0, 0, 0}, 0, 1500, std::ref(watch)), h.errorList().c_str());
  qInfo("pulled away: %.4f m from the axis", wristAxisRadius(h.state()));
  QVERIFY(wristAxisRadius(h.state()) > kWristAxisHoldRadius + kWristAxisWallWidth);
  QVERIFY(watch.fastest < kElbowRateMonitor);
}

QTEST_APPLESS_MAIN(TestSimWalls)
#include "test_sim_walls.moc"
