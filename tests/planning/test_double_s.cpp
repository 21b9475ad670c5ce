// SPDX-License-Identifier: Apache-2.0
// Tests of the scalar double-S profile (planning/double_s.h) and of CartMotionGenerator, which
// is that profile within the planner's Cartesian translation limits.
#include <cmath>
#include <limits>
#include <random>

#include <QtTest>

#include <xmate/cart_motion.h>
#include <xmate/exception.h>

#include "allocation_counter.h"
#include "model/robot_spec.h"
#include "planning/double_s.h"
#include "sampled_limits.h"

using namespace xmate;
using planning::DoubleSProfile;
using planning::planDoubleS;
using planning::sampleDoubleS;
using planning_test::DifferenceMaxima;
using planning_test::kCycle;
using planning_test::withinLimit;

namespace {

struct Limits {
  double v, a, j;
};

// Samples the profile every cycle from before the start to after the end and checks: limits by
// finite differences, the reported v and a against central differences of p, continuity, rest at
// both ends, exact end point. Stops at the first failure (the caller sees currentTestFailed()).
void checkSampled(const DoubleSProfile& s, const Limits& limits) {
  DifferenceMaxima<1> differences;
  const long last = static_cast<long>(std::ceil(s.duration / kCycle)) + 3;
  for (long k = -3; k <= last; ++k)
    differences.add(Eigen::Matrix<double, 1, 1>(sampleDoubleS(s, k * kCycle).p));
  QVERIFY2(withinLimit(differences.maxNorm(1), limits.v, differences.roundingBound(1)),
           "velocity limit exceeded");
  QVERIFY2(withinLimit(differences.maxNorm(2), limits.a, differences.roundingBound(2)),
           "acceleration limit exceeded");
  QVERIFY2(withinLimit(differences.maxNorm(3), limits.j, differences.roundingBound(3)),
           "jerk limit exceeded");

  // The reported velocity and acceleration are the derivatives of the reported position: a central
  // difference differs from v by at most j h^2 / 6, a second difference from a by at most j h / 3.
  const double h = kCycle;
  for (long k = 0; k <= last - 3; ++k) {
    const double t = k * h;
    // The sampler works with T - t near the end: t's own rounding, relative 1e-16, shows up there.
    const double time_rounding = 4 * std::numeric_limits<double>::epsilon() * (t + h);
    const auto now = sampleDoubleS(s, t);
    const double p_next = sampleDoubleS(s, t + h).p, p_prev = sampleDoubleS(s, t - h).p;
    const double v_fd = (p_next - p_prev) / (2 * h);
    const double a_fd = (p_next - 2 * now.p + p_prev) / (h * h);
    QVERIFY(std::abs(v_fd - now.v) <= limits.j * h * h / 6 + 1e-9 * limits.v + differences.roundingBound(1));
    QVERIFY(std::abs(a_fd - now.a) <= limits.j * h / 3 + 1e-9 * limits.a + differences.roundingBound(2));
    // Continuity of the sampled v and a between neighbouring cycles.
    const auto next = sampleDoubleS(s, t + h);
    QVERIFY(std::abs(next.v - now.v) <= limits.a * (h * (1 + 1e-9) + time_rounding));
    QVERIFY(std::abs(next.a - now.a) <= limits.j * (h * (1 + 1e-9) + time_rounding));
    QVERIFY(std::abs(now.j) <= limits.j);
  }
  const auto end = sampleDoubleS(s, s.duration);
  QCOMPARE(end.p, s.distance);
  QCOMPARE(end.v, 0.0);
  QCOMPARE(end.a, 0.0);
}

}  // namespace

class TestDoubleS : public QObject {
  Q_OBJECT

 private slots:
  // Durations derived by hand from the three cases of Biagiotti & Melchiorri sec. 3.4.
  void durationsOfTheThreeCases_data() {
    QTest::addColumn<double>("distance");
    QTest::addColumn<double>("v");
    QTest::addColumn<double>("a");
    QTest::addColumn<double>("j");
    QTest::addColumn<double>("duration");
    QTest::addColumn<double>("v_peak");
    QTest::addColumn<double>("a_peak");
    // Tj = a/j = 0.2, Ta = Tj + v/a = 0.7, cruise h/v - Ta = 1.3: T = 2 Ta + Tv = 2.7.
    QTest::newRow("cruises, a reached") << 2.0 << 1.0 << 2.0 << 10.0 << 2.7 << 1.0 << 2.0;
    // v j < a^2: Tj = sqrt(v/j), Ta = 2 Tj, T = h/v + Ta = 2 + 2 sqrt(0.1).
    QTest::newRow("cruises, a not reached")
        << 2.0 << 1.0 << 5.0 << 10.0 << 2 + 2 * std::sqrt(0.1) << 1.0 << 10 * std::sqrt(0.1);
    // vp^2/a + vp a/j = h: vp = sqrt(1.04) - 0.2, T = 2 (Tj + vp/a) = 0.2 + sqrt(1.04).
    QTest::newRow("no cruise, a reached")
        << 0.5 << 1.0 << 2.0 << 10.0 << 0.2 + std::sqrt(1.04) << std::sqrt(1.04) - 0.2 << 2.0;
    // h = 2 j Tj^3: Tj = cbrt(0.005), T = 4 Tj, vp = j Tj^2, ap = j Tj.
    QTest::newRow("no cruise, a not reached")
        << 0.1 << 1.0 << 2.0 << 10.0 << 4 * std::cbrt(0.005) << 10 * std::cbrt(0.005) * std::cbrt(0.005)
        << 10 * std::cbrt(0.005);
    QTest::newRow("negative distance") << -2.0 << 1.0 << 2.0 << 10.0 << 2.7 << 1.0 << 2.0;
  }
  void durationsOfTheThreeCases() {
    QFETCH(double, distance);
    QFETCH(double, v);
    QFETCH(double, a);
    QFETCH(double, j);
    QFETCH(double, duration);
    QFETCH(double, v_peak);
    QFETCH(double, a_peak);
    const DoubleSProfile s = planDoubleS(distance, v, a, j);
    QVERIFY(std::abs(s.duration - duration) < 1e-12);
    QVERIFY(std::abs(s.v_peak - v_peak) < 1e-12);
    QVERIFY(std::abs(s.a_peak - a_peak) < 1e-12);
    // The middle of a symmetric profile is halfway, at the peak velocity.
    const auto middle = sampleDoubleS(s, s.duration / 2);
    QVERIFY(std::abs(middle.p - distance / 2) < 1e-12);
    QVERIFY(std::abs(std::abs(middle.v) - v_peak) < 1e-12);
    checkSampled(s, {v, a, j});
  }

  void randomProfilesStayWithinLimits() {
    std::mt19937_64 rng(7);
    // Distances 10 um .. 10 m (or rad), limits spanning two to four decades: every case of the
    // planner, durations up to ~100 s.
    auto decades = [&](double from, double to) {
      return std::pow(10.0, std::uniform_real_distribution<double>(from, to)(rng));
    };
    for (int n = 0; n < 300; ++n) {
      const double distance = (n % 2 ? 1 : -1) * decades(-5, 1);
      const Limits limits{decades(-1, 1), decades(-1, 2), decades(0, 4)};
      checkSampled(planDoubleS(distance, limits.v, limits.a, limits.j), limits);
      if (QTest::currentTestFailed()) qWarning() << "failed at profile" << n << distance;
      if (QTest::currentTestFailed()) return;
    }
  }

  void clampsTimeOutsideTheMotion() {
    const DoubleSProfile s = planDoubleS(0.3, 1, 2, 10);
    QCOMPARE(sampleDoubleS(s, -1).p, 0.0);
    QCOMPARE(sampleDoubleS(s, 0).p, 0.0);
    QCOMPARE(sampleDoubleS(s, 0).v, 0.0);
    QCOMPARE(sampleDoubleS(s, s.duration).p, 0.3);
    QCOMPARE(sampleDoubleS(s, 1e9).p, 0.3);
    QCOMPARE(sampleDoubleS(s, 1e9).a, 0.0);
    QVERIFY(sampleDoubleS(s, s.duration - 1e-3).p < 0.3);
    QVERIFY(sampleDoubleS(s, std::nextafter(s.duration, 0.0)).v > 0);
  }

  void zeroDistanceTakesNoTime() {
    const DoubleSProfile s = planDoubleS(0, 1, 2, 10);
    QCOMPARE(s.duration, 0.0);
    QCOMPARE(sampleDoubleS(s, 0).p, 0.0);
    QCOMPARE(sampleDoubleS(s, 1).p, 0.0);
  }

  void rejectsBadLimits() {
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, planDoubleS(1, 0, 1, 1));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, planDoubleS(1, 1, -1, 1));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, planDoubleS(1, 1, 1, std::nan("")));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, planDoubleS(std::nan(""), 1, 1, 1));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, planDoubleS(1, INFINITY, 1, 1));
  }

  void planningAndSamplingDoNotAllocate() {
    const std::size_t before = planning_test::allocationCount();
    double sum = 0;
    for (int n = 1; n < 100; ++n) {
      const DoubleSProfile s = planDoubleS(0.01 * n, 1, 2, 10);
      sum += sampleDoubleS(s, 0.1).p;
    }
    QCOMPARE(planning_test::allocationCount(), before);
    QVERIFY(sum > 0);
  }

  // CartMotionGenerator: the planner's translation limits times speed_ratio.
  void cartGeneratorObeysTranslationLimits_data() {
    QTest::addColumn<double>("speed_ratio");
    QTest::addColumn<double>("s_start");
    QTest::addColumn<double>("s_goal");
    for (double r : {0.05, 0.3, 1.0}) {
      QTest::addRow("r=%g long", r) << r << 0.1 << 0.9;
      QTest::addRow("r=%g backwards", r) << r << 0.5 << -0.25;
      QTest::addRow("r=%g short", r) << r << 0.0 << 0.002;
    }
  }
  void cartGeneratorObeysTranslationLimits() {
    QFETCH(double, speed_ratio);
    QFETCH(double, s_start);
    QFETCH(double, s_goal);
    const model::CartesianLimits& c = model::plannerCartesianLimits();
    const Limits limits{c.v_trans * speed_ratio, c.a_trans * speed_ratio, c.j_trans * speed_ratio};

    CartMotionGenerator generator(speed_ratio, s_goal);
    generator.calculateSynchronizedValues_cart(s_start);
    const double T = generator.GetTime();
    QVERIFY(T > 0);
    DifferenceMaxima<1> differences;
    const long last = static_cast<long>(std::ceil(T / kCycle)) + 3;
    for (long k = 0; k <= last; ++k) {
      const double t = k * kCycle;
      double s = -1;
      generator.calculateSynchronizedValues_cart(s_start);  // as vendor programs do, every cycle
      const bool finished = generator.calculateDesiredValues_cart(t, &s);
      QCOMPARE(finished, t >= T);
      differences.add(Eigen::Matrix<double, 1, 1>(s));
    }
    QVERIFY(withinLimit(differences.maxNorm(1), limits.v, differences.roundingBound(1)));
    QVERIFY(withinLimit(differences.maxNorm(2), limits.a, differences.roundingBound(2)));
    QVERIFY(withinLimit(differences.maxNorm(3), limits.j, differences.roundingBound(3)));
    double s_end = 0;
    QVERIFY(generator.calculateDesiredValues_cart(T, &s_end));
    QCOMPARE(s_end, s_goal - s_start);
    QVERIFY(!generator.calculateDesiredValues_cart(std::nextafter(T, 0.0), &s_end));
  }

  void cartGeneratorRejectsMisuse() {
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, CartMotionGenerator(0, 1));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, CartMotionGenerator(1.01, 1));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, CartMotionGenerator(0.5, std::nan("")));
    CartMotionGenerator generator(0.5, 1);
    double s = 0;
    QVERIFY_THROWS_EXCEPTION(MotionException, generator.calculateDesiredValues_cart(0, &s));
    QCOMPARE(generator.GetTime(), 0.0);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, generator.calculateSynchronizedValues_cart(INFINITY));
    generator.calculateSynchronizedValues_cart(0);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, generator.calculateDesiredValues_cart(0, nullptr));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, generator.calculateDesiredValues_cart(std::nan(""), &s));
  }

  void cartGeneratorReplansWhenTheStartChanges() {
    CartMotionGenerator generator(1, 0.5);
    generator.calculateSynchronizedValues_cart(0);
    const double first = generator.GetTime();
    generator.calculateSynchronizedValues_cart(0.4);
    CartMotionGenerator fresh(1, 0.5);
    fresh.calculateSynchronizedValues_cart(0.4);
    QVERIFY(generator.GetTime() < first);
    QCOMPARE(generator.GetTime(), fresh.GetTime());
  }
};

QTEST_APPLESS_MAIN(TestDoubleS)
#include "test_double_s.moc"
