// SPDX-License-Identifier: Apache-2.0
// Each setting's range check accepts the documented edge values, refuses what lies beyond, and
// says in its message which parameter and index were wrong and what range is allowed.
#include <QtTest>

#include <cmath>
#include <limits>

#include "model/parameter_checks.h"

using namespace xmate;
using namespace xmate::model;

namespace {
constexpr std::array<double, 16> kIdentity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
bool says(const std::string& msg, const char* part) { return msg.find(part) != std::string::npos; }
}  // namespace

class TestParameterChecks : public QObject {
  Q_OBJECT

 private slots:
  void collisionThresholds() {
    const auto& pro = robotSpec(XMATE7_PRO);
    QVERIFY(checkCollisionThresholds(pro, pro.collision_threshold_max).empty());
    auto t = pro.collision_threshold_max;
    t[2] = 60.5;
    const std::string e = checkCollisionThresholds(pro, t);
    QVERIFY2(says(e, "upper_torque_thresholds_nominal[2]") && says(e, "(0, 60]"), e.c_str());
    t = pro.collision_threshold_max;
    t[0] = 0;
    QVERIFY(!checkCollisionThresholds(pro, t).empty());
    const auto& six = robotSpec(XMATE3);
    QVERIFY(checkCollisionThresholds(six, six.collision_threshold_max).empty());
    t = six.collision_threshold_max;
    t[6] = 1;
    QVERIFY(says(checkCollisionThresholds(six, t), "must be 0 on the 6-axis"));
  }

  void impedances() {
    const auto& pro = robotSpec(XMATE3_PRO);
    QVERIFY(checkJointImpedance(pro, {0, 0, 0, 0, 0, 0, 0}).empty());
    QVERIFY(checkJointImpedance(pro, pro.joint_stiffness_max).empty());
    QVERIFY(says(checkJointImpedance(pro, {3000, 3000, 3000, 3000, 301, 300, 300}), "K_theta[4]"));
    QVERIFY(checkCartesianImpedance({3000, 3000, 3000, 300, 300, 300}).empty());
    QVERIFY(says(checkCartesianImpedance({3000, 3000, 3000, 300, 300, 301}), "K_x[5]"));
    QVERIFY(says(checkCartesianImpedance({-1, 0, 0, 0, 0, 0}), "K_x[0]"));
  }

  void filters() {
    QVERIFY(checkFilters(10, 100, 1000).empty());
    QVERIFY(says(checkFilters(0.5, 50, 50), "joint_hz"));
    QVERIFY(says(checkFilters(50, std::nan(""), 50), "cartesian_hz is not a finite"));
  }

  // Editors mark the refused field from the problem's fields, not by reading its sentence.
  void problemsNameTheirParameter() {
    QCOMPARE(checkFilters(50, 50, 2000).parameter, std::string("torque_hz"));
    QCOMPARE(checkFilters(50, 50, 2000).index, -1);
    const auto& pro = robotSpec(XMATE7_PRO);
    auto t = pro.collision_threshold_max;
    t[4] = 1000;
    const ParameterProblem thresholds = checkCollisionThresholds(pro, t);
    QCOMPARE(thresholds.parameter, std::string("upper_torque_thresholds_nominal"));
    QCOMPARE(thresholds.index, 4);
    const std::array<double, 9> asymmetric{0.01, 0.002, 0, 0, 0.01, 0, 0, 0, 0.01};
    QCOMPARE(checkLoad(pro, 1.0, {0, 0, 0.6}, asymmetric).parameter, std::string("center"));
    QCOMPARE(checkLoad(pro, 1.0, {0, 0, 0.6}, asymmetric).index, 2);
    QCOMPARE(checkLoad(pro, 1.0, {0, 0, 0.1}, asymmetric).parameter, std::string("inertia"));
    std::array<double, 7> upper{}, lower{};
    for (int i = 0; i < 7; ++i) upper[i] = 10, lower[i] = -10;
    lower[3] = 20;
    const ParameterProblem soft = checkSoftLimits(pro, upper, lower);
    QCOMPARE(soft.parameter, std::string("lower"));
    QCOMPARE(soft.index, 3);
    QCOMPARE(checkCartesianLimit({0.5, 0, 0.5}, kIdentity).parameter, std::string("size"));
    QCOMPARE(checkCartesianLimit({0.5, 0, 0.5}, kIdentity).index, 1);
    QCOMPARE(checkDrag(3, 1).parameter, std::string("drag_space"));
  }

  void load() {
    const auto& p3 = robotSpec(XMATE3_PRO);
    const std::array<double, 9> I{0.01, 0, 0, 0, 0.01, 0, 0, 0, 0.01};
    QVERIFY(checkLoad(p3, 3.0, {0, 0, 0.1}, I).empty());
    QVERIFY(says(checkLoad(p3, 3.5, {0, 0, 0.1}, I), "mass"));
    QVERIFY(checkLoad(robotSpec(XMATE7_PRO), 3.5, {0, 0, 0.1}, I).empty());
    QVERIFY(says(checkLoad(p3, 1, {0, 0.6, 0}, I), "center[1]"));
    QVERIFY(says(checkLoad(p3, 1, {0, 0, 0}, {0.01, 0.001, 0, 0, 0.01, 0, 0, 0, 0.01}), "symmetric"));
    QVERIFY(says(checkLoad(p3, 1, {0, 0, 0}, {0.01, 0, 0, 0, 0.01, 0, 0, 0, 0.05}), "triangle"));
    QVERIFY(says(checkLoad(p3, 1, {0, 0, 0}, {-0.01, 0, 0, 0, 0.01, 0, 0, 0, 0.01}), "positive semi-definite"));
  }

  void poses() {
    QVERIFY(checkHomogeneous("f", "p", kIdentity).empty());
    auto bad = kIdentity;
    bad[15] = 2;
    QVERIFY(says(checkHomogeneous("f", "p", bad), "last row"));
    bad = kIdentity;
    bad[0] = 1.001;
    QVERIFY(says(checkHomogeneous("f", "p", bad), "orthonormal"));
    bad = kIdentity;
    bad[5] = -1;  // a reflection, not a rotation
    bad[10] = 1;
    bad[0] = 1;
    QVERIFY(!checkHomogeneous("f", "p", bad).empty());
    bad = kIdentity;
    bad[3] = std::numeric_limits<double>::infinity();
    QVERIFY(says(checkHomogeneous("f", "p", bad), "not a finite"));
    auto tool = kIdentity;
    tool[11] = 0.6;
    QVERIFY(says(checkToolFrame(tool), "0.6 m from the flange"));
    tool[11] = 0.2;
    QVERIFY(checkToolFrame(tool).empty());
  }

  void safetyBoxAndSoftLimits() {
    QVERIFY(checkCartesianLimit({1, 1, 1}, kIdentity).empty());
    QVERIFY(says(checkCartesianLimit({1, 0, 1}, kIdentity), "size[1]"));
    const auto& pro = robotSpec(XMATE7_PRO);
    const std::array<double, 7> up{170, 120, 170, 120, 170, 120, 360}, lo{-170, -120, -170, -120, -170, -120, -360};
    QVERIFY(checkSoftLimits(pro, up, lo).empty());
    auto u2 = up;
    u2[1] = 121;
    QVERIFY(says(checkSoftLimits(pro, u2, lo), "upper[1]"));
    auto l2 = lo;
    l2[3] = 130;
    QVERIFY(!checkSoftLimits(pro, up, l2).empty());
    auto l3 = lo;
    l3[0] = 170;
    QVERIFY(says(checkSoftLimits(pro, up, l3), "must be below"));
  }

  void wrenchFrameDragPower() {
    QVERIFY(checkDesiredWrench({0, 0, 10, 0, 0, 0}).empty());
    QVERIFY(says(checkDesiredWrench({0, 0, 61, 0, 0, 0}), "tau[2]"));
    QVERIFY(says(checkDesiredWrench({0, 0, 0, 0, 0, -11}), "tau[5]"));
    QVERIFY(checkForceFrame(kIdentity, 2).empty());
    QVERIFY(says(checkForceFrame(kIdentity, 0), "fc_type"));
    QVERIFY(checkDrag(1, 3).empty());
    QVERIFY(checkDrag(2, 1).empty());
    QVERIFY(says(checkDrag(1, 1), "joint-space drag"));
    QVERIFY(says(checkDrag(3, 3), "drag_space"));
    QVERIFY(says(checkDrag(2, 4), "drag_type"));
    QVERIFY(checkMotorPower(1).empty() && checkMotorPower(0).empty());
    QVERIFY(says(checkMotorPower(2), "setMotorPower"));
  }
};

QTEST_APPLESS_MAIN(TestParameterChecks)
#include "test_parameter_checks.moc"
