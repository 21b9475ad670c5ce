// SPDX-License-Identifier: Apache-2.0
// Tests of JointMotionGenerator (xmate/joint_motion.h): every plan sampled at 1 ms, for random
// start/goal pairs on every model and speed ratios 0.05, 0.3 and 1.
#include <cmath>
#include <random>

#include <QtTest>

#include <xmate/exception.h>
#include <xmate/joint_motion.h>

#include "allocation_counter.h"
#include "model/robot_spec.h"
#include "sampled_limits.h"

using namespace xmate;
using planning_test::DifferenceMaxima;
using planning_test::kCycle;
using planning_test::withinLimit;
using Joints = std::array<double, 7>;
using JointVector = Eigen::Matrix<double, 7, 1>;

namespace {

// A random configuration inside the joint range (zero in unused entries).
Joints randomJoints(const model::RobotSpec& spec, std::mt19937_64& rng) {
  Joints q{};
  for (int i = 0; i < spec.dof; ++i)
    q[i] = std::uniform_real_distribution<double>(spec.q_min[i], spec.q_max[i])(rng);
  return q;
}

// A goal near q: a random direction scaled by 10^U(-4, 0) of the way to a random configuration,
// so that short moves (which never reach the velocity or acceleration limit) are covered too.
Joints nearbyGoal(const model::RobotSpec& spec, const Joints& q, std::mt19937_64& rng) {
  const Joints far = randomJoints(spec, rng);
  const double fraction = std::pow(10.0, std::uniform_real_distribution<double>(-4, 0)(rng));
  Joints goal{};
  for (int i = 0; i < spec.dof; ++i) goal[i] = q[i] + fraction * (far[i] - q[i]);
  return goal;
}

JointVector toVector(const Joints& q) { return Eigen::Map<const JointVector>(q.data()); }

// Samples one plan every cycle and checks every requirement of docs/planning.md on it.
void checkPlan(const model::RobotSpec& spec, double speed_ratio, const Joints& q_start,
               const Joints& q_goal) {
  JointMotionGenerator generator(speed_ratio, q_goal, spec.type);
  generator.calculateSynchronizedValues_joint(q_start);
  const double T = generator.GetTime();
  const JointVector delta_total = toVector(q_goal) - toVector(q_start);

  DifferenceMaxima<7> differences;
  JointVector previous_dq = JointVector::Zero(), previous_ddq = JointVector::Zero();
  const long last = static_cast<long>(std::ceil(T / kCycle)) + 3;
  for (long k = -2; k <= last; ++k) {
    const double t = k * kCycle;
    Joints delta{}, dq{}, ddq{};
    const bool finished = generator.calculateDesiredValues_joint(t, delta);
    generator.calculateDerivatives_joint(t, dq, ddq);
    QCOMPARE(finished, t >= T);
    const JointVector d = toVector(delta);
    differences.add(d);

    // All joints on one straight line in joint space: delta_i / delta_total_i is the same for all.
    double fraction = -1;
    for (int i = 0; i < spec.dof; ++i) {
      if (delta_total(i) == 0) {
        QCOMPARE(d(i), 0.0);
        continue;
      }
      const double f = d(i) / delta_total(i);
      if (fraction < 0) fraction = f;
      QVERIFY2(std::abs(f - fraction) <= 1e-12, "joints are not phase-synchronised");
    }
    for (int i = spec.dof; i < 7; ++i) QCOMPARE(d(i), 0.0);

    // Velocity and acceleration continuous: a step between cycles is bounded by the next limit.
    for (int i = 0; i < spec.dof; ++i) {
      QVERIFY(std::abs(dq[i] - previous_dq(i)) <= spec.ddq_max[i] * speed_ratio * kCycle * (1 + 1e-9));
      QVERIFY(std::abs(ddq[i] - previous_ddq(i)) <= spec.jerk_max[i] * speed_ratio * kCycle * (1 + 1e-9));
    }
    previous_dq = toVector(dq);
    previous_ddq = toVector(ddq);
    if (QTest::currentTestFailed()) return;
  }
  // Each joint within its own velocity, acceleration and jerk limit, by finite differences.
  const std::array<const std::array<double, 7>*, 3> limits{&spec.dq_max, &spec.ddq_max, &spec.jerk_max};
  const std::array<const char*, 3> quantities{"velocity", "acceleration", "jerk"};
  for (int order = 1; order <= 3; ++order) {
    for (int i = 0; i < spec.dof; ++i) {
      const double measured = differences.maxComponent(order, i);
      const double limit = (*limits[order - 1])[i] * speed_ratio;
      QVERIFY2(withinLimit(measured, limit, differences.roundingBound(order)),
               qPrintable(QString("joint %1 %2 %3 > limit %4")
                              .arg(i + 1)
                              .arg(quantities[order - 1])
                              .arg(measured)
                              .arg(limit)));
    }
  }

  // Exact end point, and everyone arrives together: one cycle before the end no joint is there yet.
  Joints end{};
  QVERIFY(generator.calculateDesiredValues_joint(T, end));
  for (int i = 0; i < 7; ++i) QCOMPARE(end[i], i < spec.dof ? q_goal[i] - q_start[i] : 0.0);
  if (T > kCycle) {
    Joints before_end{}, dq{}, ddq{};
    QVERIFY(!generator.calculateDesiredValues_joint(T - kCycle, before_end));
    generator.calculateDerivatives_joint(T - kCycle, dq, ddq);
    for (int i = 0; i < spec.dof; ++i) {
      if (delta_total(i) == 0) continue;
      QVERIFY(before_end[i] != end[i]);
      QVERIFY(dq[i] * delta_total(i) > 0);  // still moving towards the goal
    }
  }
}

}  // namespace

class TestJointMotion : public QObject {
  Q_OBJECT

 private slots:
  void randomPlansStayWithinLimits_data() {
    QTest::addColumn<int>("type");
    QTest::addColumn<double>("speed_ratio");
    for (XmateType type : model::allRobotTypes())
      for (double r : {0.05, 0.3, 1.0})
        QTest::addRow("%s r=%g", model::robotSpec(type).name.data(), r) << int(type) << r;
  }
  void randomPlansStayWithinLimits() {
    QFETCH(int, type);
    QFETCH(double, speed_ratio);
    const model::RobotSpec& spec = model::robotSpec(static_cast<XmateType>(type));
    std::mt19937_64 rng(1000 * type + static_cast<int>(speed_ratio * 100));
    for (int n = 0; n < 50; ++n) {
      const Joints q_start = randomJoints(spec, rng);
      const Joints q_goal = n % 2 ? randomJoints(spec, rng) : nearbyGoal(spec, q_start, rng);
      checkPlan(spec, speed_ratio, q_start, q_goal);
      if (QTest::currentTestFailed()) {
        qWarning() << "failed on plan" << n;
        return;
      }
    }
  }

  // A long move reaches the limiting joint's velocity limit: the plan is not needlessly slow.
  void longMoveReachesTheVelocityLimit() {
    const model::RobotSpec& spec = model::robotSpec(XMATE7_PRO);
    const Joints q_start{-1, -1, -1, -1, -1, -1, -1};
    const Joints q_goal{1, 0.5, 0, 1, 1, 1, 2};
    JointMotionGenerator generator(0.5, q_goal, XMATE7_PRO);
    generator.calculateSynchronizedValues_joint(q_start);
    Joints dq{}, ddq{};
    generator.calculateDerivatives_joint(generator.GetTime() / 2, dq, ddq);
    double largest_ratio = 0;
    for (int i = 0; i < 7; ++i)
      largest_ratio = std::max(largest_ratio, std::abs(dq[i]) / (spec.dq_max[i] * 0.5));
    QVERIFY(std::abs(largest_ratio - 1) < 1e-12);
    // Joint 7 moves farthest (3 rad at 2.61 * 0.5 rad/s): it sets the pace.
    QVERIFY(std::abs(std::abs(dq[6]) - spec.dq_max[6] * 0.5) < 1e-12);
  }

  void callingSynchronizeEveryCycleChangesNothing() {
    const Joints q_start{0.1, 0.2, -0.3, 0.4, 0.5, -0.6, 0.7};
    const Joints q_goal{0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9};
    JointMotionGenerator once(0.2, q_goal);
    once.calculateSynchronizedValues_joint(q_start);
    JointMotionGenerator every_cycle(0.2, q_goal);
    const long cycles = static_cast<long>(once.GetTime() / kCycle) + 2;
    for (long k = 0; k <= cycles; ++k) {
      every_cycle.calculateSynchronizedValues_joint(q_start);
      Joints a{}, b{};
      const bool finished_once = once.calculateDesiredValues_joint(k * kCycle, a);
      const bool finished_every = every_cycle.calculateDesiredValues_joint(k * kCycle, b);
      QCOMPARE(finished_every, finished_once);
      QCOMPARE(b, a);
    }
    QCOMPARE(every_cycle.GetTime(), once.GetTime());
  }

  void replansWhenTheStartChanges() {
    const Joints q_goal{0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9};
    const Joints other_start{-0.5, 0, 0, 0, 0, 0, 0};
    JointMotionGenerator generator(1, q_goal);
    generator.calculateSynchronizedValues_joint({});
    generator.calculateSynchronizedValues_joint(other_start);
    JointMotionGenerator fresh(1, q_goal);
    fresh.calculateSynchronizedValues_joint(other_start);
    QCOMPARE(generator.GetTime(), fresh.GetTime());
    Joints end{};
    QVERIFY(generator.calculateDesiredValues_joint(generator.GetTime(), end));
    QCOMPARE(end[0], 0.8);
  }

  void zeroMoveIsFinishedAtOnce() {
    const Joints q{0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7};
    JointMotionGenerator generator(0.5, q);
    generator.calculateSynchronizedValues_joint(q);
    QCOMPARE(generator.GetTime(), 0.0);
    Joints delta{1, 1, 1, 1, 1, 1, 1};
    QVERIFY(generator.calculateDesiredValues_joint(0, delta));
    QCOMPARE(delta, Joints{});
  }

  void sixAxisModelsIgnoreTheSeventhEntry() {
    const Joints q_goal{0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 99};  // 99 is not a joint of an xMate3
    JointMotionGenerator generator(1, q_goal, XMATE3);
    generator.calculateSynchronizedValues_joint({0, 0, 0, 0, 0, 0, -99});
    Joints end{};
    QVERIFY(generator.calculateDesiredValues_joint(generator.GetTime(), end));
    QCOMPARE(end[5], 0.6);
    QCOMPARE(end[6], 0.0);
  }

  void rejectsInvalidArguments() {
    const Joints ok{};
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, JointMotionGenerator(0, ok));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, JointMotionGenerator(-0.1, ok));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, JointMotionGenerator(1.5, ok));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, JointMotionGenerator(std::nan(""), ok));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             JointMotionGenerator(0.5, {0, 0, std::nan(""), 0, 0, 0, 0}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             JointMotionGenerator(0.5, {0, 2.2, 0, 0, 0, 0, 0}));  // J2 +-120 deg
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             JointMotionGenerator(0.5, {0, 0, 0, 0, 0, 0, -6.3}));  // J7 +-360 deg
    try {
      JointMotionGenerator(0.5, {0, 2.2, 0, 0, 0, 0, 0});
    } catch (const std::invalid_argument& e) {
      const QString message = e.what();
      QVERIFY2(message.contains("q_goal[1]") && message.contains("joint 2"), e.what());
    }

    JointMotionGenerator generator(0.5, ok);
    Joints delta{}, dq{}, ddq{};
    QCOMPARE(generator.GetTime(), 0.0);
    QVERIFY_THROWS_EXCEPTION(MotionException, generator.calculateDesiredValues_joint(0, delta));
    QVERIFY_THROWS_EXCEPTION(MotionException, generator.calculateDerivatives_joint(0, dq, ddq));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             generator.calculateSynchronizedValues_joint({3.2, 0, 0, 0, 0, 0, 0}));
    // Just past a limit (170 deg), where a stop ramp can leave a joint: the way back is planned.
    generator.calculateSynchronizedValues_joint({3.0, 0, 0, 0, 0, 0, 0});
    QVERIFY(generator.GetTime() > 0);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             generator.calculateSynchronizedValues_joint({0, 0, 0, 0, INFINITY, 0, 0}));
    generator.calculateSynchronizedValues_joint({0.1, 0, 0, 0, 0, 0, 0});
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             generator.calculateDesiredValues_joint(std::nan(""), delta));
  }

  void planningAndSamplingDoNotAllocate() {
    JointMotionGenerator generator(0.7, {0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9});
    const std::size_t before = planning_test::allocationCount();
    Joints q_start{}, delta{}, dq{}, ddq{};
    for (int n = 0; n < 100; ++n) {
      q_start[0] = 0.001 * n;  // a new start each time: a full re-plan
      generator.calculateSynchronizedValues_joint(q_start);
      generator.calculateDesiredValues_joint(0.05 * n, delta);
      generator.calculateDerivatives_joint(0.05 * n, dq, ddq);
    }
    QCOMPARE(planning_test::allocationCount(), before);
  }
};

QTEST_APPLESS_MAIN(TestJointMotion)
#include "test_joint_motion.moc"
