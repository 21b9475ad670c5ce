// SPDX-License-Identifier: Apache-2.0
// Tests of the MOVEL/MOVEC path geometry and timing (planning/cartesian_path.h,
// cartesian_trajectory.h): every trajectory sampled at 1 ms.
#include <cmath>
#include <random>

#include <QtTest>

#include <xmate/exception.h>

#include "allocation_counter.h"
#include "model/robot_spec.h"
#include "planning/cartesian_pose.h"
#include "planning/cartesian_trajectory.h"
#include "sampled_limits.h"

using namespace xmate;
using namespace xmate::planning;
using planning_test::angleBetween;
using planning_test::DifferenceMaxima;
using planning_test::kCycle;
using planning_test::makePose;
using planning_test::randomRotation;
using planning_test::randomVector;
using planning_test::withinLimit;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Where the three points of a test arc came from: the reference the path must reproduce.
struct Circle {
  Eigen::Vector3d centre, normal;
  double radius;
};

struct Arc {
  PathPoint start, via, target;
  Circle circle;
  double sweep;  // rad, from start to target
};

// Three points on a random circle at increasing angles (about circle.normal). With `reorient`,
// random orientations and arm angles; without, one orientation and arm angle for all three, so
// that the translation limits alone set the pace.
Arc randomArc(std::mt19937_64& rng, double radius, bool reorient) {
  std::uniform_real_distribution<double> uniform(0, 1);
  Arc arc;
  arc.circle = {randomVector(rng, 0.5), randomRotation(rng).col(2), radius};
  const Eigen::Vector3d x = randomRotation(rng).col(0).cross(arc.circle.normal).normalized();
  const Eigen::Vector3d y = arc.circle.normal.cross(x);
  const double start_angle = 2 * kPi * uniform(rng);
  arc.sweep = 0.2 + (2 * kPi - 0.4) * uniform(rng);
  const double via_angle = (0.1 + 0.8 * uniform(rng)) * arc.sweep;
  const Eigen::Matrix3d fixed_rotation = randomRotation(rng);
  auto point = [&](double angle) {
    const Eigen::Vector3d p = arc.circle.centre + radius * (std::cos(angle) * x + std::sin(angle) * y);
    if (!reorient) return PathPoint{makePose(fixed_rotation, p), 0.25};
    return PathPoint{makePose(randomRotation(rng), p), uniform(rng) - 0.5};
  };
  arc.start = point(start_angle);
  arc.via = point(start_angle + via_angle);
  arc.target = point(start_angle + arc.sweep);
  return arc;
}

struct Sampled {
  DifferenceMaxima<3> position;
  DifferenceMaxima<1> rotation;  // angle from the start orientation (the axis is fixed)
  DifferenceMaxima<1> psi;
};

// Samples a trajectory every cycle and checks: limits by finite differences (translation,
// rotation, arm angle), reported rates against differences of the poses, continuity, the finished
// flag and exact end points. `visit` sees every sample for shape-specific checks.
template <class Visit>
void checkTrajectory(const CartesianTrajectory& trajectory, double speed_ratio, Visit visit) {
  const model::CartesianLimits& c = model::plannerCartesianLimits();
  const double r = speed_ratio, h = kCycle, T = duration(trajectory);
  const Eigen::Matrix3d r0 = trajectory.path.start.pose.linear();
  Sampled sampled;
  CartesianSample previous = sampleTrajectory(trajectory, -h);
  const long last = static_cast<long>(std::ceil(T / h)) + 3;
  for (long k = -2; k <= last; ++k) {
    const double t = k * h;
    const CartesianSample now = sampleTrajectory(trajectory, t);
    QCOMPARE(now.finished, t >= T);
    sampled.position.add(now.pose.translation());
    sampled.rotation.add(Eigen::Matrix<double, 1, 1>(angleBetween(r0, now.pose.linear())));
    sampled.psi.add(Eigen::Matrix<double, 1, 1>(now.psi));

    // The reported rates are the derivatives of the reported poses (bounds as in test_double_s).
    const CartesianSample next = sampleTrajectory(trajectory, t + h);
    const Eigen::Vector3d v_fd = (next.pose.translation() - previous.pose.translation()) / (2 * h);
    const Eigen::Vector3d a_fd =
        (next.pose.translation() - 2 * now.pose.translation() + previous.pose.translation()) / (h * h);
    QVERIFY((v_fd - now.linear_velocity).norm() <= c.j_trans * r * h * h / 6 + 1e-9);
    QVERIFY((a_fd - now.linear_acceleration).norm() <= c.j_trans * r * h / 3 + 1e-6);
    const Eigen::AngleAxisd turn(
        Eigen::Quaterniond(next.pose.linear() * previous.pose.linear().transpose()).normalized());
    const Eigen::Vector3d w_fd = turn.axis() * turn.angle() / (2 * h);
    QVERIFY((w_fd - now.angular_velocity).norm() <= c.j_rot * r * h * h / 6 + 1e-9);
    QVERIFY(std::abs((next.psi - previous.psi) / (2 * h) - now.psi_velocity) <=
            c.j_elbow * r * h * h / 6 + 1e-9);
    // Continuity of the reported rates between cycles.
    QVERIFY((next.linear_velocity - now.linear_velocity).norm() <= c.a_trans * r * h * (1 + 1e-9));
    QVERIFY((next.linear_acceleration - now.linear_acceleration).norm() <= c.j_trans * r * h * (1 + 1e-9));
    QVERIFY((next.angular_velocity - now.angular_velocity).norm() <= c.a_rot * r * h * (1 + 1e-9));
    QVERIFY((next.angular_acceleration - now.angular_acceleration).norm() <= c.j_rot * r * h * (1 + 1e-9));
    visit(now);
    if (QTest::currentTestFailed()) return;
    previous = now;
  }

  const auto& p = sampled.position;
  QVERIFY2(withinLimit(p.maxNorm(1), c.v_trans * r, p.roundingBound(1)),
           qPrintable(QString::number(p.maxNorm(1))));
  QVERIFY2(withinLimit(p.maxNorm(2), c.a_trans * r, p.roundingBound(2)),
           qPrintable(QString::number(p.maxNorm(2))));
  QVERIFY2(withinLimit(p.maxNorm(3), c.j_trans * r, p.roundingBound(3)),
           qPrintable(QString::number(p.maxNorm(3))));
  // The rotation angle comes out of acos-like functions: allow for their rounding (~1e-15 rad).
  const auto& w = sampled.rotation;
  const double angle_noise = 1e-14;
  QVERIFY(withinLimit(w.maxNorm(1), c.v_rot * r, w.roundingBound(1) + 2 * angle_noise / h));
  QVERIFY(withinLimit(w.maxNorm(2), c.a_rot * r, w.roundingBound(2) + 4 * angle_noise / (h * h)));
  QVERIFY(withinLimit(w.maxNorm(3), c.j_rot * r, w.roundingBound(3) + 8 * angle_noise / (h * h * h)));
  const auto& e = sampled.psi;
  QVERIFY(withinLimit(e.maxNorm(1), c.v_elbow * r, e.roundingBound(1)));
  QVERIFY(withinLimit(e.maxNorm(2), c.a_elbow * r, e.roundingBound(2)));
  QVERIFY(withinLimit(e.maxNorm(3), c.j_elbow * r, e.roundingBound(3)));

  // Exact end points; rest at both ends.
  const CartesianSample begin = sampleTrajectory(trajectory, 0);
  const CartesianSample end = sampleTrajectory(trajectory, T);
  QVERIFY((begin.pose.matrix() - trajectory.path.start.pose.matrix()).cwiseAbs().maxCoeff() <= 1e-12);
  QVERIFY((end.pose.matrix() - trajectory.path.target.pose.matrix()).cwiseAbs().maxCoeff() <= 1e-12);
  QCOMPARE(end.psi, trajectory.path.target.psi);
  QVERIFY(end.finished);
  QCOMPARE(end.linear_velocity.norm() + end.angular_velocity.norm() + std::abs(end.psi_velocity), 0.0);
  QCOMPARE(poseToRowMajor(end.pose), poseToRowMajor(trajectory.path.target.pose));
  if (T > h) QVERIFY(!sampleTrajectory(trajectory, std::nextafter(T, 0.0)).finished);
}

void expectMotionException(const PathPoint& a, const PathPoint& b, const PathPoint& c, const char* needle) {
  try {
    makeArcPath(a, b, c);
    QFAIL("no MotionException");
  } catch (const MotionException& e) {
    QVERIFY2(QString(e.what()).contains(needle), e.what());
  }
}

}  // namespace

class TestCartesianPath : public QObject {
  Q_OBJECT

 private slots:
  void linesStayWithinLimits_data() {
    QTest::addColumn<double>("speed_ratio");
    for (double r : {0.05, 0.3, 1.0}) QTest::addRow("r=%g", r) << r;
  }
  void linesStayWithinLimits() {
    QFETCH(double, speed_ratio);
    std::mt19937_64 rng(11 + static_cast<int>(speed_ratio * 100));
    for (int n = 0; n < 30; ++n) {
      // Mix long moves, short ones and rotation- or elbow-dominated ones.
      const double reach = n % 3 == 0 ? 0.5 : (n % 3 == 1 ? 0.002 : 0.05);
      const PathPoint start{makePose(randomRotation(rng), randomVector(rng, 0.5)), 0.3};
      const PathPoint target{
          makePose(randomRotation(rng), start.pose.translation() + randomVector(rng, reach)),
          n % 4 == 0 ? 1.5 : 0.3};
      const CartesianTrajectory line = planLine(speed_ratio, start, target);
      const Eigen::Vector3d p0 = start.pose.translation(), chord = target.pose.translation() - p0;
      const Eigen::Quaterniond q0(start.pose.linear()), q1(target.pose.linear());
      checkTrajectory(line, speed_ratio, [&](const CartesianSample& s) {
        // On the segment, and turned by Eigen's own slerp at the same fraction of the way.
        const double u = (s.pose.translation() - p0).dot(chord) / chord.squaredNorm();
        QVERIFY((s.pose.translation() - (p0 + u * chord)).norm() <= 1e-12);
        const Eigen::Matrix3d slerp = q0.slerp(u, q1).toRotationMatrix();
        QVERIFY(angleBetween(slerp, s.pose.linear()) <= 1e-9);
        QVERIFY(std::abs(s.psi - (start.psi + u * (target.psi - start.psi))) <= 1e-9);
      });
      if (QTest::currentTestFailed()) {
        qWarning() << "failed on line" << n;
        return;
      }
    }
  }

  void arcsStayOnTheCircleAndWithinLimits_data() {
    QTest::addColumn<double>("speed_ratio");
    QTest::addColumn<double>("radius");
    for (double r : {0.05, 0.3, 1.0})
      for (double radius : {0.005, 0.05, 0.4}) QTest::addRow("r=%g radius=%g", r, radius) << r << radius;
  }
  void arcsStayOnTheCircleAndWithinLimits() {
    QFETCH(double, speed_ratio);
    QFETCH(double, radius);
    std::mt19937_64 rng(23 + static_cast<int>(speed_ratio * 100) + static_cast<int>(radius * 1000));
    for (int n = 0; n < 12; ++n) {
      const Arc arc = randomArc(rng, radius, n % 2 == 1);
      const CartesianTrajectory trajectory = planArc(speed_ratio, arc.start, arc.via, arc.target);
      const CartesianPath& path = trajectory.path;
      QVERIFY(std::abs(path.length - radius * arc.sweep) <= 1e-9);
      QVERIFY((evaluatePath(path, path.via_u).position - arc.via.pose.translation()).norm() <= 1e-9);

      const Eigen::Vector3d c = arc.circle.centre, p0 = arc.start.pose.translation();
      const double theta = angleBetween(arc.start.pose.linear(), arc.target.pose.linear());
      double closest_to_via = INFINITY, travelled = 0;
      checkTrajectory(trajectory, speed_ratio, [&](const CartesianSample& s) {
        const Eigen::Vector3d p = s.pose.translation();
        QVERIFY(std::abs((p - c).norm() - radius) <= 1e-9);
        QVERIFY(std::abs((p - c).dot(arc.circle.normal)) <= 1e-9);
        closest_to_via = std::min(closest_to_via, (p - arc.via.pose.translation()).norm());
        // Orientation in step with the arc angle: the same fraction of the rotation as of the sweep.
        double angle = std::atan2(arc.circle.normal.dot((p0 - c).cross(p - c)), (p0 - c).dot(p - c));
        if (angle < -1e-9) angle += 2 * kPi;
        const double u = s.finished ? 1.0 : angle / arc.sweep;
        QVERIFY(u >= travelled - 1e-12);  // never goes backwards
        travelled = u;
        if (theta > 1e-6)
          QVERIFY(std::abs(angleBetween(arc.start.pose.linear(), s.pose.linear()) - u * theta) <= 1e-9);
      });
      if (QTest::currentTestFailed()) {
        qWarning() << "failed on arc" << n;
        return;
      }
      // It passes through the via point: some 1 ms sample lies within half a cycle's travel of it.
      QVERIFY(closest_to_via <= model::plannerCartesianLimits().v_trans * speed_ratio * kCycle / 2 + 1e-12);
    }
  }

  // Without the curvature terms a 1 m/s arc of 5 mm radius would need 200 m/s^2 of centripetal
  // acceleration; the planner slows down instead.
  void tightArcIsSlowedByItsCurvature() {
    std::mt19937_64 rng(5);
    const Arc arc = randomArc(rng, 0.005, false);
    const CartesianTrajectory trajectory = planArc(1.0, arc.start, arc.via, arc.target);
    double fastest = 0;
    for (double t = 0; t < duration(trajectory); t += kCycle)
      fastest = std::max(fastest, sampleTrajectory(trajectory, t).linear_velocity.norm());
    const double a = model::plannerCartesianLimits().a_trans;
    QVERIFY(fastest * fastest / 0.005 <= a / 2 * (1 + 1e-9));
  }

  void pureRotationAndZeroMove() {
    std::mt19937_64 rng(3);
    const Eigen::Vector3d p{0.4, 0.1, 0.5};
    const PathPoint start{makePose(randomRotation(rng), p), 0};
    const PathPoint turned{makePose(randomRotation(rng), p), 0};
    checkTrajectory(planLine(1.0, start, turned), 1.0, [](const CartesianSample&) {});

    const CartesianTrajectory still = planLine(0.5, start, start);
    QCOMPARE(duration(still), 0.0);
    const CartesianSample s = sampleTrajectory(still, 0);
    QVERIFY(s.finished);
    QCOMPARE(poseToRowMajor(s.pose), poseToRowMajor(start.pose));
  }

  // Half a turn minus a little: slerp takes the short way (angle < pi), not the long one.
  void orientationTakesTheShortestArc() {
    const PathPoint start{makePose(Eigen::Matrix3d::Identity(), {0.5, 0, 0.5}), 0};
    const Eigen::Matrix3d almost_half_turn =
        Eigen::AngleAxisd(-0.99 * kPi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const PathPoint target{makePose(almost_half_turn, {0.5, 0, 0.5}), 0};
    const CartesianTrajectory line = planLine(1.0, start, target);
    QVERIFY(std::abs(line.path.rotation_angle - 0.99 * kPi) < 1e-12);
    const Eigen::Matrix3d middle = sampleTrajectory(line, duration(line) / 2).pose.linear();
    const Eigen::Matrix3d expected =
        Eigen::AngleAxisd(-0.495 * kPi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    QVERIFY(angleBetween(middle, expected) < 1e-12);
  }

  void rejectsCoincidentAndCollinearPoints() {
    const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
    auto at = [&](double x, double y, double z) { return PathPoint{makePose(I, {x, y, z}), 0}; };
    expectMotionException(at(0, 0, 0), at(0.00005, 0, 0), at(0.1, 0.1, 0), "start and via");
    expectMotionException(at(0, 0, 0), at(0.1, 0.1, 0), at(0.1, 0.1, 0.00009), "via and target");
    expectMotionException(at(0, 0, 0), at(0.1, 0.1, 0), at(0, 0.00001, 0), "start and target");
    expectMotionException(at(0, 0, 0), at(0.5, 0, 0), at(1, 0, 0), "collinear");
    expectMotionException(at(0, 0, 0), at(2, 0, 0), at(1, 0, 0), "collinear");   // via beyond the target
    expectMotionException(at(0, 0, 0), at(0.5, 1e-7, 0), at(1, 0, 0), "MOVEL");  // 0.0001 mm off the line
    // Points 0.2 mm apart on a real circle are fine, and so is a via 1 mm off a 100 mm chord.
    makeArcPath(at(0, 0, 0), at(0.0002, 0.0002, 0), at(0.0004, 0, 0));
    makeArcPath(at(0, 0, 0), at(0.05, 0.001, 0), at(0.1, 0, 0));
  }

  void rejectsInvalidPosesAndSpeedRatios() {
    const PathPoint good{makePose(Eigen::Matrix3d::Identity(), {0.5, 0, 0.5}), 0};
    PathPoint nan_pose = good;
    nan_pose.pose.translation().x() = std::nan("");
    PathPoint scaled = good;
    scaled.pose.linear() *= 1 + 1e-5;
    PathPoint reflected = good;
    reflected.pose.linear()(2, 2) = -1;
    PathPoint last_row = good;
    last_row.pose.matrix()(3, 0) = 0.1;
    PathPoint nan_psi = good;
    nan_psi.psi = std::nan("");
    for (const PathPoint* bad : {&nan_pose, &scaled, &reflected, &last_row, &nan_psi}) {
      QVERIFY_THROWS_EXCEPTION(std::invalid_argument, makeLinePath(good, *bad));
      QVERIFY_THROWS_EXCEPTION(std::invalid_argument, makeArcPath(*bad, good, good));
    }
    PathPoint slightly_off = good;  // within the 1e-6 tolerance
    slightly_off.pose.linear() *= 1 + 1e-8;
    makeLinePath(good, slightly_off);

    const PathPoint other{makePose(Eigen::Matrix3d::Identity(), {0.5, 0.1, 0.5}), 0};
    for (double bad_ratio : {0.0, -0.5, 1.0001, std::nan("")})
      QVERIFY_THROWS_EXCEPTION(std::invalid_argument, planLine(bad_ratio, good, other));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, sampleTrajectory(planLine(1, good, other), std::nan("")));

    std::array<double, 16> row_major = poseToRowMajor(other.pose);
    QCOMPARE(poseFromRowMajor(row_major, "test").translation().y(), 0.1);
    QCOMPARE(row_major[7], 0.1);  // row-major: (1, 3) is the y translation
    row_major[12] = 1;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, poseFromRowMajor(row_major, "test"));
  }

  void planningAndSamplingDoNotAllocate() {
    std::mt19937_64 rng(9);
    const Arc arc = randomArc(rng, 0.2, true);
    const std::size_t before = planning_test::allocationCount();
    const CartesianTrajectory trajectory = planArc(0.5, arc.start, arc.via, arc.target);
    const CartesianTrajectory line = planLine(0.5, arc.start, arc.target);
    double sum = duration(line);
    for (double t = 0; t < duration(trajectory); t += 0.01) {
      const CartesianSample s = sampleTrajectory(trajectory, t);
      sum += velocityOf(s)[0] + accelerationOf(s)[3] + poseToRowMajor(s.pose)[3];
    }
    const CartesianTrajectory retimed = timePath(trajectory.path, 0.3);
    QCOMPARE(planning_test::allocationCount(), before);
    QVERIFY(std::isfinite(sum) && duration(retimed) > duration(trajectory));
  }
};

QTEST_APPLESS_MAIN(TestCartesianPath)
#include "test_cartesian_path.moc"
