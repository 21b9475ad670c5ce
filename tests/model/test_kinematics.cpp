// SPDX-License-Identifier: Apache-2.0
// Kinematics of all four xMate models through the public XmateModel (loaded from the URDFs): FK
// against the DH table, link frames, TCP, Jacobian against finite differences, the arm angle's
// definition, the IK round trip on 100 000 random configurations per model, every IK return code.
// The two KUKA arms (KR 6 R900 sixx, KR 16-2) through the internal API: KUKA's FK check values,
// FK against the DH table, Jacobian, all 8 IK branches on random configurations, IK return codes.
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>
#include <string>

#include <xmate/model.h>

#include "model/arm_model.h"
#include "model/euler_zyx.h"
#include "model/inverse_kinematics.h"
#include "model/kinematics.h"
#include "model/urdf_loader.h"
#include "model_test_support.h"

using namespace xmate;
using namespace xmate::model;
using namespace xmate::model::test;

namespace {

constexpr double kPi = 3.14159265358979323846;
// 100 000 per model; the sanitizer build, ~20x slower, sets RCI_IK_ROUNDTRIP_SAMPLES lower.
int roundTripSamples() {
  const char* text = std::getenv("RCI_IK_ROUNDTRIP_SAMPLES");
  const int n = text ? std::atoi(text) : 0;
  return n > 0 ? n : 100000;
}
// Configurations closer than this to a singularity (the measures below) are left out of the
// round trip: near a singularity the joint angles are ill-conditioned functions of the pose.
constexpr double kExclusionDistance = 5e-4;

void addModelRows() {
  QTest::addColumn<int>("type");
  for (XmateType t : allRobotTypes()) QTest::newRow(std::string(robotSpec(t).name).c_str()) << static_cast<int>(t);
}

const RobotSpec& fetchSpec() {
  QFETCH(int, type);
  return robotSpec(static_cast<XmateType>(type));
}

Eigen::Vector3d wristCentre(const RobotSpec& spec, const JointVector& q) {
  const Eigen::Isometry3d flange = dhFrames(spec, q)[spec.dof];
  return flange.translation() - spec.dh[spec.dof - 1].d * flange.linear().col(2);
}

// The smallest of the test's singularity measures (docs/kinematics.md, "Singularities"): distance
// (m) of the wrist centre from the joint-1 axis, and |sin| of the angles that align two axes or
// stretch/fold the elbow.
double singularityDistance(const RobotSpec& spec, const JointVector& q) {
  const Eigen::Vector3d w = wristCentre(spec, q);
  const double horizontal = std::hypot(w.x(), w.y());
  if (spec.dof == 7)
    return std::min({horizontal, std::abs(std::sin(q[1])), std::abs(std::sin(q[3])), std::abs(std::sin(q[5]))});
  return std::min({horizontal, std::abs(std::cos(q[2])), std::abs(std::sin(q[4]))});
}

double wrapAngle(double a) { return std::remainder(a, 2 * kPi); }

// Rotation vector of R_plus R_minus^T / (2h): the angular velocity column of a central difference.
Eigen::Vector3d angularDifference(const Eigen::Matrix3d& plus, const Eigen::Matrix3d& minus, double h) {
  const Eigen::AngleAxisd aa(plus * minus.transpose());
  return aa.angle() * aa.axis() / (2 * h);
}

std::array<double, 16> withFlangeAt(const Eigen::Matrix3d& r, const Eigen::Vector3d& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = r;
  t.translation() = p;
  return toRowMajor(t);
}

// A configuration well inside the limits and away from singularities, for the return-code cases.
JointVector regularConfiguration(const RobotSpec& spec) {
  JointVector q = JointVector::Zero();
  const double seven[7] = {1.0, 0.6, 0.4, -1.2, 0.5, 0.8, 0.3};
  const double six[6] = {1.0, 0.6, 0.4, 0.5, 0.8, 0.3};
  for (int i = 0; i < spec.dof; ++i) q[i] = spec.dof == 7 ? seven[i] : six[i];
  return q;
}

int wristPitchJoint(const RobotSpec& spec) { return spec.dof == 7 ? 5 : 4; }

std::array<double, 7> radToDeg(const JointVector& v) {
  std::array<double, 7> a{};
  for (int i = 0; i < 7; ++i) a[i] = v[i] * 180.0 / kPi;
  return a;
}

// ---- KUKA ----

void addKukaRows() {
  QTest::addColumn<QString>("model");
  for (const RobotSpec& spec : allRobotSpecs())
    if (spec.family == RobotFamily::kKuka)
      QTest::newRow(std::string(spec.name).c_str()) << QString::fromStdString(std::string(spec.name));
}

const RobotSpec& fetchKukaSpec() {
  QFETCH(QString, model);
  const RobotSpec* spec = findRobotSpec(model.toStdString());
  if (!spec) qFatal("unknown model in test data");
  return *spec;
}

JointVector fromDegrees(std::initializer_list<double> deg) {
  JointVector q = JointVector::Zero();
  int i = 0;
  for (double d : deg) q[i++] = d * kPi / 180.0;
  return q;
}

// Wrist centre of an offset-wrist arm: where A4, A5 and A6 meet (DH frame 4's origin).
Eigen::Vector3d kukaWristCentre(const RobotSpec& spec, const JointVector& q) {
  return dhFrames(spec, q)[4].translation();
}

// The smallest of the offset-wrist singularity measures (docs/kinematics.md): distance (m) of the
// wrist centre from the A1 axis, |sin| of the elbow's bend away from stretched or folded, |sin q5|.
double kukaSingularityDistance(const RobotSpec& spec, const JointVector& q) {
  const Eigen::Vector3d w = kukaWristCentre(spec, q);
  const double beta = std::atan2(-spec.dh[3].d * (spec.dh[2].alpha < 0 ? -1.0 : 1.0), spec.dh[2].a);
  const double phi3 = spec.dh[2].theta + spec.dh[2].axis_sign * q[2];
  return std::min({std::hypot(w.x(), w.y()), std::abs(std::sin(phi3 + beta)), std::abs(std::sin(q[4]))});
}

double angleDifferenceDeg(double a, double b) { return std::abs(std::remainder(a - b, 360.0)); }

}  // namespace

class TestKinematics : public QObject {
  Q_OBJECT

 private slots:
  void fkMatchesDhTable_data() { addModelRows(); }
  void fkMatchesDhTable() {
    const RobotSpec& spec = fetchSpec();
    XmateModel model(spec.type);
    QCOMPARE(model.Dof(), spec.dof);
    const ArmModel arm = makeArmModel(loadRobotChain(spec), spec);
    std::mt19937 rng(11);
    double worst = 0;
    for (int k = 0; k < 1000; ++k) {
      const JointVector q = randomConfiguration(spec, rng);
      const Eigen::Isometry3d expected = dhFlangePose(spec, toArray(q));
      const Eigen::Isometry3d ours = fromRowMajor(model.GetCartPose(toArray(q)));
      worst = std::max({worst, positionError(ours, expected), rotationError(ours, expected)});
      // Every link frame: DH frame i-1 turned by q_i (the chain's frame convention).
      LinkFrames frames;
      forwardKinematics(arm, q, frames);
      const auto dh = dhFrames(spec, q);
      for (int i = 0; i < spec.dof; ++i) {
        Eigen::Isometry3d link = dh[i];
        link.rotate(Eigen::AngleAxisd(q[i], Eigen::Vector3d::UnitZ()));
        worst = std::max({worst, positionError(frames.links[i], link), rotationError(frames.links[i], link)});
      }
      worst = std::max(worst, positionError(frames.flange, expected));
    }
    qInfo("worst FK difference from the DH table: %.3g", worst);
    QVERIFY(worst < 1e-9);
  }

  void tcpFollowsTool_data() { addModelRows(); }
  void tcpFollowsTool() {
    const RobotSpec& spec = fetchSpec();
    XmateModel model(spec.type);
    Eigen::Isometry3d tool = Eigen::Isometry3d::Identity();
    tool.rotate(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, -2, 0.5).normalized()));
    tool.translation() = Eigen::Vector3d(0.03, -0.02, 0.15);
    model.SetCoor(toRowMajor(tool));
    std::mt19937 rng(12);
    for (int k = 0; k < 200; ++k) {
      const JointVector q = randomConfiguration(spec, rng);
      const Eigen::Isometry3d expected = dhFlangePose(spec, toArray(q)) * tool;
      const Eigen::Isometry3d ours = fromRowMajor(model.GetCartPose(toArray(q)));
      QVERIFY(positionError(ours, expected) < 1e-9);
      QVERIFY(rotationError(ours, expected) < 1e-9);
    }
    std::array<double, 16> bad = toRowMajor(tool);
    bad[0] = 1.5;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, model.SetCoor(bad));
  }

  void jacobianMatchesFiniteDifferences_data() { addModelRows(); }
  void jacobianMatchesFiniteDifferences() {
    const RobotSpec& spec = fetchSpec();
    XmateModel model(spec.type);
    Eigen::Isometry3d tool = Eigen::Isometry3d::Identity();
    tool.rotate(Eigen::AngleAxisd(-0.4, Eigen::Vector3d::UnitY()));
    tool.translation() = Eigen::Vector3d(0.05, 0.01, 0.12);
    constexpr double h = 1e-6;
    std::mt19937 rng(13);
    double worst = 0;
    for (int pass = 0; pass < 2; ++pass) {  // flange, then with a tool
      if (pass == 1) model.SetCoor(toRowMajor(tool));
      for (int k = 0; k < 200; ++k) {
        const JointVector q = randomConfiguration(spec, rng);
        const std::array<double, 42> jac = model.Jacobian(toArray(q));
        for (int i = 0; i < 7; ++i) {
          Eigen::Matrix<double, 6, 1> expected = Eigen::Matrix<double, 6, 1>::Zero();
          if (i < spec.dof) {
            JointVector plus = q, minus = q;
            plus[i] += h;
            minus[i] -= h;
            const Eigen::Isometry3d tp = fromRowMajor(model.GetCartPose(toArray(plus)));
            const Eigen::Isometry3d tm = fromRowMajor(model.GetCartPose(toArray(minus)));
            expected.head<3>() = (tp.translation() - tm.translation()) / (2 * h);
            expected.tail<3>() = angularDifference(tp.linear(), tm.linear(), h);
          }
          for (int row = 0; row < 6; ++row) worst = std::max(worst, std::abs(jac[row * 7 + i] - expected[row]));
        }
      }
    }
    qInfo("worst Jacobian difference from central differences: %.3g", worst);
    QVERIFY(worst < 1e-6);
  }

  // psi is the angle, about the shoulder->wrist line, from the elbow of the reference configuration
  // (q3 = 0, same q4, joint 1 facing the wrist) to the actual elbow. Built here from DH frames only.
  void armAngleFollowsDefinition_data() { addModelRows(); }
  void armAngleFollowsDefinition() {
    const RobotSpec& spec = fetchSpec();
    XmateModel model(spec.type);
    std::mt19937 rng(14);
    if (spec.dof == 6) {
      QCOMPARE(model.GetPsi(toArray(randomConfiguration(spec, rng))), 0.0);
      return;
    }
    double worst = 0;
    for (int k = 0; k < 2000; ++k) {
      const JointVector q = randomConfiguration(spec, rng);
      if (singularityDistance(spec, q) < kExclusionDistance) continue;
      const auto frames = dhFrames(spec, q);
      const Eigen::Vector3d s = frames[1].translation(), e = frames[3].translation(), w = frames[5].translation();
      const Eigen::Vector3d u = (w - s).normalized();
      JointVector ref = JointVector::Zero();
      ref[0] = std::atan2(w.y() - s.y(), w.x() - s.x());
      ref[3] = q[3];
      const auto ref0 = dhFrames(spec, ref);  // q2 = 0: turn joint 2 until the wrist is reached
      const Eigen::Vector3d axis2 = ref0[1].linear().col(2);
      const Eigen::Vector3d w0 = ref0[5].translation() - s;
      ref[1] = std::atan2(axis2.dot(w0.cross(w - s)), w0.dot(w - s));
      const auto reference = dhFrames(spec, ref);
      QVERIFY((reference[5].translation() - w).norm() < 1e-9);
      const Eigen::Vector3d e0 = reference[3].translation() - s, e1 = e - s;
      const Eigen::Vector3d p0 = e0 - e0.dot(u) * u, p1 = e1 - e1.dot(u) * u;
      const double expected = std::atan2(u.dot(p0.cross(p1)), p0.dot(p1));
      worst = std::max(worst, std::abs(wrapAngle(model.GetPsi(toArray(q)) - expected)));
      worst = std::max(worst, std::abs(model.GetPsi(toArray(ref))));  // the reference itself: psi = 0
    }
    qInfo("worst arm angle difference from its definition: %.3g rad", worst);
    QVERIFY(worst < 1e-9);
  }

  void ikRoundTrip_data() { addModelRows(); }
  void ikRoundTrip() {
    const RobotSpec& spec = fetchSpec();
    XmateModel model(spec.type);  // rated-speed check on (1 ms)
    XmateModel unchecked(spec.type);
    unchecked.SetSpeedCheckInterval(0);
    std::mt19937 rng(1000 + spec.type);
    std::uniform_real_distribution<double> noise(-1e-4, 1e-4);
    const int samples = roundTripSamples();
    int excluded = 0;
    double worst_pose = 0, worst_q = 0, worst_far_pose = 0, worst_far_psi = 0;
    for (int k = 0; k < samples; ++k) {
      const JointVector q = randomConfiguration(spec, rng);
      if (singularityDistance(spec, q) < kExclusionDistance) {
        ++excluded;
        continue;
      }
      const std::array<double, 16> pose = model.GetCartPose(toArray(q));
      const Eigen::Isometry3d target = fromRowMajor(pose);
      const double psi = model.GetPsi(toArray(q));
      std::array<double, 7> out{};

      // The configuration itself, then a nearby one, as q_init: q comes back.
      for (int variant = 0; variant < 2; ++variant) {
        JointVector q_init = q;
        if (variant == 1)
          for (int i = 0; i < spec.dof; ++i) q_init[i] += noise(rng);
        const int code = model.GetJointPos(pose, psi, toArray(q_init), out);
        if (code != 0) QFAIL(qPrintable(QString("sample %1 variant %2: code %3").arg(k).arg(variant).arg(code)));
        worst_q = std::max(worst_q, (fromArray(out) - q).cwiseAbs().maxCoeff());
        const Eigen::Isometry3d reached = fromRowMajor(model.GetCartPose(out));
        worst_pose = std::max({worst_pose, positionError(reached, target), rotationError(reached, target)});
      }

      // A far q_init, speed check off: some valid solution with the same pose and arm angle.
      const JointVector far = randomConfiguration(spec, rng);
      const int code = unchecked.GetJointPos(pose, psi, toArray(far), out);
      if (code != 0) QFAIL(qPrintable(QString("sample %1 far q_init: code %2").arg(k).arg(code)));
      const Eigen::Isometry3d reached = fromRowMajor(model.GetCartPose(out));
      worst_far_pose = std::max({worst_far_pose, positionError(reached, target), rotationError(reached, target)});
      for (int i = 0; i < spec.dof; ++i) {
        QVERIFY(out[i] >= spec.q_min[i] && out[i] <= spec.q_max[i]);
      }
      worst_far_psi = std::max(worst_far_psi, std::abs(wrapAngle(model.GetPsi(out) - psi)));
    }
    const double excluded_share = double(excluded) / samples;
    qInfo("%d samples, %d (%.3f %%) near a singularity excluded; worst pose error %.3g, worst joint error %.3g, "
          "far q_init: worst pose error %.3g, arm angle error %.3g",
          samples, excluded, 100 * excluded_share, worst_pose, worst_q, worst_far_pose, worst_far_psi);
    QVERIFY(excluded_share < 0.005);
    QVERIFY(worst_pose < 1e-9);
    QVERIFY(worst_q < 1e-9);
    QVERIFY(worst_far_pose < 1e-9);
    QVERIFY(worst_far_psi < 1e-7);
  }

  // The internal API on the DH-table chain (no URDF involved): the same round trip, fewer samples.
  void internalIkRoundTripOnDhChain_data() { addModelRows(); }
  void internalIkRoundTripOnDhChain() {
    const RobotSpec& spec = fetchSpec();
    const ArmModel arm = makeArmModel(chainFromDh(spec), spec);
    std::mt19937 rng(2000 + spec.type);
    double worst_pose = 0, worst_q = 0;
    for (int k = 0; k < 10000; ++k) {
      const JointVector q = randomConfiguration(spec, rng);
      if (singularityDistance(spec, q) < kExclusionDistance) continue;
      const Eigen::Isometry3d target = tcpPose(arm, q);
      JointVector out;
      const IkStatus code = inverseKinematics(arm, target.matrix(), armAngle(arm, q), q, out);
      if (code != IkStatus::kOk) QFAIL(qPrintable(QString("sample %1: %2").arg(k).arg(ikStatusText(code))));
      const Eigen::Isometry3d reached = tcpPose(arm, out);
      worst_pose = std::max({worst_pose, positionError(reached, target), rotationError(reached, target)});
      worst_q = std::max(worst_q, (out - q).cwiseAbs().maxCoeff());
    }
    qInfo("worst pose error %.3g, worst joint error %.3g", worst_pose, worst_q);
    QVERIFY(worst_pose < 1e-9);
    QVERIFY(worst_q < 1e-9);
  }

  void ikPicksNearestTwoPiEquivalent_data() { addModelRows(); }
  void ikPicksNearestTwoPiEquivalent() {
    const RobotSpec& spec = fetchSpec();
    XmateModel model(spec.type);
    model.SetSpeedCheckInterval(0);
    const int last = spec.dof - 1;  // the +-360 deg flange joint
    JointVector q = regularConfiguration(spec);
    q[last] = 5.0;
    const std::array<double, 16> pose = model.GetCartPose(toArray(q));
    const double psi = model.GetPsi(toArray(q));
    std::array<double, 7> out{};
    QCOMPARE(model.GetJointPos(pose, psi, toArray(q), out), 0);
    QVERIFY(std::abs(out[last] - 5.0) < 1e-9);
    JointVector q_init = q;
    q_init[last] = 5.0 - 2 * kPi;
    QCOMPARE(model.GetJointPos(pose, psi, toArray(q_init), out), 0);
    QVERIFY(std::abs(out[last] - (5.0 - 2 * kPi)) < 1e-9);
  }

  void ikReportsReach_data() { addModelRows(); }
  void ikReportsReach() {
    const RobotSpec& spec = fetchSpec();
    XmateModel model(spec.type);
    const std::array<double, 7> q_init = toArray(regularConfiguration(spec));
    std::array<double, 7> out{};
    out.fill(42);
    const Eigen::Matrix3d down = Eigen::AngleAxisd(kPi, Eigen::Vector3d::UnitX()).toRotationMatrix();
    QCOMPARE(model.GetJointPos(withFlangeAt(down, {2.0, 0.0, 0.5}), 0, q_init, out), int(XmateModel::kIkTooFar));
    // Wrist centre 15 mm (6-axis) or 60 mm (7-axis) from the shoulder: the elbow cannot fold that far.
    const double d1 = spec.dh[0].d, d_wf = spec.dh[spec.dof - 1].d;
    const Eigen::Vector3d wrist = spec.dof == 7 ? Eigen::Vector3d(0.05, 0.02, d1 + 0.03)
                                                : Eigen::Vector3d(0.01, 0.005, d1 + 0.01);
    const Eigen::Vector3d flange = wrist + Eigen::Vector3d(0, 0, d_wf);
    QCOMPARE(model.GetJointPos(withFlangeAt(Eigen::Matrix3d::Identity(), flange), 0, q_init, out),
             int(XmateModel::kIkTooClose));
    for (double v : out) QCOMPARE(v, 42.0);  // q_out untouched on failure
  }

  void ikRejectsInvalidPoses_data() { addModelRows(); }
  void ikRejectsInvalidPoses() {
    const RobotSpec& spec = fetchSpec();
    XmateModel model(spec.type);
    const JointVector q = regularConfiguration(spec);
    const std::array<double, 16> good = model.GetCartPose(toArray(q));
    const double psi = model.GetPsi(toArray(q));
    std::array<double, 7> out{};
    QCOMPARE(model.GetJointPos(good, psi, toArray(q), out), 0);
    std::array<double, 16> nan_pose = good, scaled = good, bad_row = good, mirrored = good;
    nan_pose[5] = std::nan("");
    for (int r = 0; r < 3; ++r) scaled[r * 4] *= 1.001;  // first column no longer unit length
    bad_row[14] = 0.5;
    for (int r = 0; r < 3; ++r) mirrored[r * 4 + 2] *= -1;  // det = -1
    for (const auto& pose : {nan_pose, scaled, bad_row, mirrored})
      QCOMPARE(model.GetJointPos(pose, psi, toArray(q), out), int(XmateModel::kIkInvalidPose));
    std::array<double, 7> nan_init = toArray(q);
    nan_init[0] = std::numeric_limits<double>::infinity();
    QCOMPARE(model.GetJointPos(good, psi, nan_init, out), int(XmateModel::kIkInvalidPose));
  }

  void ikChecksRatedSpeed_data() { addModelRows(); }
  void ikChecksRatedSpeed() {
    const RobotSpec& spec = fetchSpec();
    XmateModel model(spec.type);
    const JointVector q = regularConfiguration(spec);
    const std::array<double, 16> pose = model.GetCartPose(toArray(q));
    const double psi = model.GetPsi(toArray(q));
    std::array<double, 7> out{};
    // In 1 ms joint 1 may move 2.175 mrad, joint 6 (7-axis) or 5 (6-axis) 2.61 mrad.
    JointVector arm_jump = q, wrist_jump = q, small_step = q;
    arm_jump[0] -= 0.003;
    wrist_jump[wristPitchJoint(spec)] -= 0.003;
    small_step[0] -= 0.002;
    small_step[wristPitchJoint(spec)] -= 0.0025;
    QCOMPARE(model.GetJointPos(pose, psi, toArray(arm_jump), out), int(XmateModel::kIkArmJointTooFast));
    QCOMPARE(model.GetJointPos(pose, psi, toArray(wrist_jump), out), int(XmateModel::kIkWristJointTooFast));
    QCOMPARE(model.GetJointPos(pose, psi, toArray(small_step), out), 0);
    model.SetSpeedCheckInterval(0.01);  // ten times the time: ten times the allowed step
    QCOMPARE(model.GetJointPos(pose, psi, toArray(arm_jump), out), 0);
    model.SetSpeedCheckInterval(0);
    JointVector far = q;
    far[0] -= 1.0;
    QCOMPARE(model.GetJointPos(pose, psi, toArray(far), out), 0);
    QVERIFY((fromArray(out) - q).cwiseAbs().maxCoeff() < 1e-9);
  }

  void ikChecksSoftLimits_data() { addModelRows(); }
  void ikChecksSoftLimits() {
    const RobotSpec& spec = fetchSpec();
    XmateModel model(spec.type);
    const JointVector q = regularConfiguration(spec);
    const std::array<double, 16> pose = model.GetCartPose(toArray(q));
    const double psi = model.GetPsi(toArray(q));
    std::array<double, 7> out{};
    // Narrow bands around q for every joint; joint 1's band just below (then above) q1.
    JointVector lower = q.array() - 0.05, upper = q.array() + 0.05;
    lower[0] = q[0] - 0.5;
    upper[0] = q[0] - 0.1;
    model.SetJointLimit(radToDeg(upper), radToDeg(lower));
    QCOMPARE(model.GetJointPos(pose, psi, toArray(q), out), int(XmateModel::kIkAboveSoftLimit));
    lower[0] = q[0] + 0.1;
    upper[0] = q[0] + 0.5;
    model.SetJointLimit(radToDeg(upper), radToDeg(lower));
    QCOMPARE(model.GetJointPos(pose, psi, toArray(q), out), int(XmateModel::kIkBelowSoftLimit));
    lower[0] = q[0] - 0.05;
    upper[0] = q[0] + 0.05;
    model.SetJointLimit(radToDeg(upper), radToDeg(lower));
    QCOMPARE(model.GetJointPos(pose, psi, toArray(q), out), 0);
    // Soft limits beyond the hardware range are refused.
    JointVector too_wide = upper;
    too_wide[1] = spec.q_max[1] + 0.1;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, model.SetJointLimit(radToDeg(too_wide), radToDeg(lower)));
  }

  void ikReportsSingularities_data() { addModelRows(); }
  void ikReportsSingularities() {
    const RobotSpec& spec = fetchSpec();
    XmateModel model(spec.type);
    model.SetSpeedCheckInterval(0);
    std::array<double, 7> out{};
    auto codeAt = [&](const JointVector& q) {
      return model.GetJointPos(model.GetCartPose(toArray(q)), model.GetPsi(toArray(q)), toArray(q), out);
    };
    const int singular = XmateModel::kIkSingular;
    // Wrist: the two wrist roll axes aligned. Just outside the 1e-6 band it solves.
    JointVector wrist = regularConfiguration(spec);
    wrist[wristPitchJoint(spec)] = 0;
    QCOMPARE(codeAt(wrist), singular);
    wrist[wristPitchJoint(spec)] = 1e-4;
    QCOMPARE(codeAt(wrist), 0);
    // Shoulder: wrist centre on the joint-1 axis.
    JointVector shoulder = regularConfiguration(spec);
    const double d3 = spec.dof == 7 ? spec.dh[2].d : spec.dh[1].a, d5 = spec.dof == 7 ? spec.dh[4].d : spec.dh[3].d;
    if (spec.dof == 7) {
      shoulder[2] = 0;
      shoulder[1] = -std::atan2(d5 * std::sin(shoulder[3]), d3 + d5 * std::cos(shoulder[3]));
    } else {
      shoulder[2] = -1.0;
      shoulder[1] = std::atan2(-(d3 + d5 * std::sin(shoulder[2])), d5 * std::cos(shoulder[2]));
    }
    const Eigen::Vector3d w = wristCentre(spec, shoulder);
    QVERIFY(std::hypot(w.x(), w.y()) < 1e-12);
    QCOMPARE(codeAt(shoulder), singular);
    // Elbow: fully stretched.
    JointVector stretched = regularConfiguration(spec);
    stretched[spec.dof == 7 ? 3 : 2] = spec.dof == 7 ? 0.0 : kPi / 2;
    QCOMPARE(codeAt(stretched), singular);
    if (spec.dof == 7) {
      QCOMPARE(codeAt(JointVector::Zero()), singular);  // straight up
      JointVector coaxial = regularConfiguration(spec);  // upper arm vertical: J1 and J3 coaxial
      coaxial[1] = 0;
      QCOMPARE(codeAt(coaxial), singular);
    }
  }

  // ---- KUKA (internal API) ----

  void kukaSpecsAreFound() {
    int kuka = 0;
    for (const RobotSpec& spec : allRobotSpecs()) {
      QCOMPARE(findRobotSpec(spec.name), &spec);
      if (spec.family == RobotFamily::kXmate) {
        QCOMPARE(xmateType(spec).value(), spec.type);
        QCOMPARE(&robotSpec(spec.type), &spec);
        QCOMPARE(findXmateSpec(spec.name), &spec);
      } else {
        ++kuka;
        QVERIFY(!xmateType(spec).has_value());
        QVERIFY(findXmateSpec(spec.name) == nullptr);
      }
    }
    QCOMPARE(kuka, 2);
    QCOMPARE(int(allRobotSpecs().size()), 6);
    QCOMPARE(findRobotSpec("kr6_r900_sixx")->display_name, std::string_view("KR 6 R900 sixx"));
    QCOMPARE(findRobotSpec("kr16_2")->display_name, std::string_view("KR 16-2"));
    for (XmateType t : allRobotTypes()) QCOMPARE(robotSpec(t).family, RobotFamily::kXmate);
  }

  // KUKA's own check values: flange position (mm) and A B C (deg) at given A1..A6 (deg).
  void kukaFkCheckValues() {
    const RobotSpec& kr6 = *findRobotSpec("kr6_r900_sixx");
    const RobotSpec& kr16 = *findRobotSpec("kr16_2");
    const ArmModel arm6 = makeArmModel(loadRobotChain(kr6), kr6);
    const ArmModel arm16 = makeArmModel(loadRobotChain(kr16), kr16);
    struct Check {
      const ArmModel* arm;
      JointVector q;
      Eigen::Vector3d mm;
    };
    const Check checks[] = {
        {&arm6, fromDegrees({0, -90, 90, 0, 90, 0}), {445, 0, 810}},
        {&arm16, fromDegrees({0, -90, 90, 0, 90, 0}), {930, 0, 1162}},
        {&arm6, fromDegrees({30, -60, 100, 20, 40, 10}), {521.75, -321.54, 474.47}},
    };
    for (const Check& c : checks) {
      const Eigen::Vector3d got = 1000.0 * flangePose(*c.arm, c.q).translation();
      QVERIFY2((got - c.mm).cwiseAbs().maxCoeff() < 0.01,
               qPrintable(QString("flange at %1 %2 %3 mm, expected %4 %5 %6")
                              .arg(got.x(), 0, 'f', 4).arg(got.y(), 0, 'f', 4).arg(got.z(), 0, 'f', 4)
                              .arg(c.mm.x()).arg(c.mm.y()).arg(c.mm.z())));
    }
    // Orientation of the first check: A B C = (180, 0, 180) deg, R = Rz(A) Ry(B) Rx(C).
    const AbcAngles abc = abcFromRotation(flangePose(arm6, checks[0].q).linear());
    QVERIFY(angleDifferenceDeg(abc.a * 180 / kPi, 180) < 1e-9);
    QVERIFY(angleDifferenceDeg(abc.b * 180 / kPi, 0) < 1e-9);
    QVERIFY(angleDifferenceDeg(abc.c * 180 / kPi, 180) < 1e-9);
    const Eigen::Matrix3d expected = rotationFromAbc({kPi, 0, kPi});
    QVERIFY((flangePose(arm6, checks[0].q).linear() - expected).cwiseAbs().maxCoeff() < 1e-12);
    QVERIFY((flangePose(arm16, checks[1].q).linear() - expected).cwiseAbs().maxCoeff() < 1e-12);
    // The last check also through the DH table alone.
    QVERIFY((1000.0 * dhFlangePose(kr6, toArray(checks[2].q)).translation() - checks[2].mm).cwiseAbs().maxCoeff() < 0.01);
  }

  void kukaFkMatchesDhTable_data() { addKukaRows(); }
  void kukaFkMatchesDhTable() {
    const RobotSpec& spec = fetchKukaSpec();
    const ArmModel arm = makeArmModel(loadRobotChain(spec), spec);
    QVERIFY(arm.geometry.kind == IkGeometry::kOffsetWrist);
    QCOMPARE(arm.family, RobotFamily::kKuka);
    std::mt19937 rng(31);
    double worst = 0;
    for (int k = 0; k < 1000; ++k) {
      const JointVector q = randomConfiguration(spec, rng);
      const Eigen::Isometry3d expected = dhFlangePose(spec, toArray(q));
      LinkFrames frames;
      forwardKinematics(arm, q, frames);
      const auto dh = dhFrames(spec, q);
      for (int i = 0; i < spec.dof; ++i) {  // link i: DH frame i-1 turned by theta_i + sign_i q_i
        Eigen::Isometry3d link = dh[i];
        link.rotate(Eigen::AngleAxisd(spec.dh[i].theta + spec.dh[i].axis_sign * q[i], Eigen::Vector3d::UnitZ()));
        worst = std::max({worst, positionError(frames.links[i], link), rotationError(frames.links[i], link)});
      }
      worst = std::max({worst, positionError(frames.flange, expected), rotationError(frames.flange, expected)});
      worst = std::max(worst, positionError(frames.flange, dh[spec.dof]));
    }
    qInfo("worst FK difference from the DH table: %.3g", worst);
    QVERIFY(worst < 1e-9);
    // A positive A1 turns the arm clockwise seen from above (about -z).
    JointVector q = fromDegrees({10, -90, 90, 0, 90, 0});
    QVERIFY(flangePose(arm, q).translation().y() < 0);
  }

  void kukaJacobianMatchesFiniteDifferences_data() { addKukaRows(); }
  void kukaJacobianMatchesFiniteDifferences() {
    const RobotSpec& spec = fetchKukaSpec();
    ArmModel arm = makeArmModel(loadRobotChain(spec), spec);
    Eigen::Isometry3d tool = Eigen::Isometry3d::Identity();
    tool.rotate(Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 1, 0).normalized()));
    tool.translation() = Eigen::Vector3d(0.02, 0.01, 0.15);
    setTool(arm, tool);
    constexpr double h = 1e-6;
    std::mt19937 rng(32);
    double worst = 0;
    for (int k = 0; k < 200; ++k) {
      const JointVector q = randomConfiguration(spec, rng);
      const Jacobian jac = tcpJacobian(arm, q);
      for (int i = 0; i < spec.dof; ++i) {
        JointVector plus = q, minus = q;
        plus[i] += h;
        minus[i] -= h;
        const Eigen::Isometry3d tp = tcpPose(arm, plus), tm = tcpPose(arm, minus);
        Eigen::Matrix<double, 6, 1> expected;
        expected.head<3>() = (tp.translation() - tm.translation()) / (2 * h);
        expected.tail<3>() = angularDifference(tp.linear(), tm.linear(), h);
        worst = std::max(worst, (jac.col(i) - expected).cwiseAbs().maxCoeff());
      }
    }
    qInfo("worst Jacobian difference from central differences: %.3g", worst);
    QVERIFY(worst < 1e-6);
  }

  // Every branch the IK returns reaches the pose; the branch holding the original q gives it back;
  // inverseKinematics from q itself (and from far away) solves within the limits.
  void kukaIkAllBranches_data() { addKukaRows(); }
  void kukaIkAllBranches() {
    const RobotSpec& spec = fetchKukaSpec();
    ArmModel arm = makeArmModel(loadRobotChain(spec), spec);
    setSpeedCheckInterval(arm, 0);
    Eigen::Isometry3d tool = Eigen::Isometry3d::Identity();
    tool.translation() = Eigen::Vector3d(0.01, -0.02, 0.12);
    tool.rotate(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitY()));
    std::mt19937 rng(33);
    const int samples = std::min(roundTripSamples(), 50000);
    int excluded = 0, eight = 0;
    double worst_branch = 0, worst_q = 0, worst_far = 0;
    for (int k = 0; k < samples; ++k) {
      if (k == samples / 2) setTool(arm, tool);  // the second half through a tool
      const JointVector q = randomConfiguration(spec, rng);
      if (kukaSingularityDistance(spec, q) < kExclusionDistance) {
        ++excluded;
        continue;
      }
      const Eigen::Isometry3d target = tcpPose(arm, q);
      IkBranchSolutions branches;
      const IkStatus status = inverseKinematicsBranches(arm, target.matrix(), 0, q, branches);
      if (status != IkStatus::kOk) QFAIL(qPrintable(QString("sample %1: %2").arg(k).arg(ikStatusText(status))));
      if (branches.count == 8) ++eight;
      double nearest = 1e9;
      for (int b = 0; b < branches.count; ++b) {
        const IkBranchSolution& s = branches.items[b];
        const Eigen::Isometry3d reached = tcpPose(arm, s.q);
        worst_branch = std::max({worst_branch, positionError(reached, target), rotationError(reached, target)});
        bool inside = true;
        for (int i = 0; i < spec.dof; ++i) inside = inside && s.q[i] >= arm.lower[i] - 1e-12 && s.q[i] <= arm.upper[i] + 1e-12;
        QCOMPARE(s.within_limits, inside);
        nearest = std::min(nearest, (s.q - q).cwiseAbs().maxCoeff());
      }
      worst_q = std::max(worst_q, nearest);
      JointVector out;
      QCOMPARE(inverseKinematics(arm, target.matrix(), 0, q, out), IkStatus::kOk);
      worst_q = std::max(worst_q, (out - q).cwiseAbs().maxCoeff());
      const JointVector far = randomConfiguration(spec, rng);
      QCOMPARE(inverseKinematics(arm, target.matrix(), 0, far, out), IkStatus::kOk);
      const Eigen::Isometry3d reached = tcpPose(arm, out);
      worst_far = std::max({worst_far, positionError(reached, target), rotationError(reached, target)});
      for (int i = 0; i < spec.dof; ++i) QVERIFY(out[i] >= spec.q_min[i] && out[i] <= spec.q_max[i]);
    }
    qInfo("%d samples, %d near a singularity excluded, %d with all 8 branches; worst branch pose error %.3g, "
          "worst joint error %.3g, far q_init pose error %.3g",
          samples, excluded, eight, worst_branch, worst_q, worst_far);
    QVERIFY(double(excluded) / samples < 0.005);
    QVERIFY(eight > samples / 2);
    QVERIFY(worst_branch < 1e-9);
    QVERIFY(worst_q < 1e-9);
    QVERIFY(worst_far < 1e-9);
  }

  // The 8 branches are distinct: shoulder front/back (A1 differs by pi), elbow up/down, wrist flip
  // (A5 changes sign).
  void kukaIkBranchesAreDistinct_data() { addKukaRows(); }
  void kukaIkBranchesAreDistinct() {
    const RobotSpec& spec = fetchKukaSpec();
    const ArmModel arm = makeArmModel(loadRobotChain(spec), spec);
    const JointVector q = fromDegrees({20, -90, 120, 30, 50, 40});  // wrist centre near enough for the back branches
    IkBranchSolutions branches;
    QCOMPARE(inverseKinematicsBranches(arm, flangePose(arm, q).matrix(), 0, q, branches), IkStatus::kOk);
    QCOMPARE(branches.count, 8);
    int positive_q5 = 0;
    for (int a = 0; a < 8; ++a) {
      positive_q5 += std::remainder(branches.items[a].q[4], 2 * kPi) > 0;  // unwrapped: out-of-range branches may be shifted by 2 pi
      for (int b = a + 1; b < 8; ++b) {
        JointVector d = branches.items[a].q - branches.items[b].q;
        for (int i = 0; i < 6; ++i) d[i] = std::remainder(d[i], 2 * kPi);
        QVERIFY(d.cwiseAbs().maxCoeff() > 1e-3);
      }
    }
    QCOMPARE(positive_q5, 4);
  }

  // The offset-wrist solver is general: on the xMate 6-axis tables (offsets 0) it must give the
  // same branches as the xMates' own solver.
  void offsetWristSolverAgreesOnXmateSixAxis() {
    for (XmateType t : {XMATE3, XMATE7}) {
      const RobotSpec& spec = robotSpec(t);
      const ArmModel six = makeArmModel(chainFromDh(spec), spec);
      ArmModel offset = six;
      offset.geometry.kind = IkGeometry::kOffsetWrist;
      for (int i = 0; i < 6; ++i) offset.geometry.dh[i] = spec.dh[i];
      std::mt19937 rng(34 + t);
      int compared = 0;
      for (int k = 0; k < 2000; ++k) {
        const JointVector q = randomConfiguration(spec, rng);
        if (singularityDistance(spec, q) < kExclusionDistance) continue;
        const Eigen::Matrix4d pose = flangePose(six, q).matrix();
        IkBranchSolutions a, b;
        QCOMPARE(inverseKinematicsBranches(six, pose, 0, q, a), IkStatus::kOk);
        QCOMPARE(inverseKinematicsBranches(offset, pose, 0, q, b), IkStatus::kOk);
        QCOMPARE(a.count, b.count);
        for (int i = 0; i < a.count; ++i) {  // the same set of solutions (mod 2 pi), in any order
          double nearest = 1e9;
          for (int j = 0; j < b.count; ++j) {
            double d = 0;
            for (int n = 0; n < 6; ++n) d = std::max(d, std::abs(wrapAngle(a.items[i].q[n] - b.items[j].q[n])));
            nearest = std::min(nearest, d);
          }
          QVERIFY2(nearest < 1e-9, qPrintable(QString("sample %1 branch %2: %3 rad").arg(k).arg(i).arg(nearest)));
        }
        ++compared;
      }
      QVERIFY(compared > 1900);
    }
  }

  // A6 spans +-350 deg: q and q - 2 pi are both in range; the IK keeps the one nearest q_init.
  void kukaIkPicksNearestTwoPiEquivalent_data() { addKukaRows(); }
  void kukaIkPicksNearestTwoPiEquivalent() {
    const RobotSpec& spec = fetchKukaSpec();
    ArmModel arm = makeArmModel(loadRobotChain(spec), spec);
    setSpeedCheckInterval(arm, 0);
    JointVector q = fromDegrees({20, -70, 80, 30, 50, 0});
    q[5] = 5.0;
    const Eigen::Matrix4d pose = flangePose(arm, q).matrix();
    JointVector out;
    QCOMPARE(inverseKinematics(arm, pose, 0, q, out), IkStatus::kOk);
    QVERIFY(std::abs(out[5] - 5.0) < 1e-9);
    JointVector q_init = q;
    q_init[5] = 5.0 - 2 * kPi;
    QCOMPARE(inverseKinematics(arm, pose, 0, q_init, out), IkStatus::kOk);
    QVERIFY(std::abs(out[5] - (5.0 - 2 * kPi)) < 1e-9);
  }

  void kukaIkReturnCodes_data() { addKukaRows(); }
  void kukaIkReturnCodes() {
    const RobotSpec& spec = fetchKukaSpec();
    ArmModel arm = makeArmModel(loadRobotChain(spec), spec);
    setSpeedCheckInterval(arm, 0);
    const JointVector regular = fromDegrees({20, -70, 80, 30, 50, 40});
    JointVector out = JointVector::Constant(42);
    auto codeAt = [&](const JointVector& q) { return inverseKinematics(arm, flangePose(arm, q).matrix(), 0, q, out); };
    QCOMPARE(codeAt(regular), IkStatus::kOk);
    // Beyond reach: 3 m away.
    Eigen::Matrix4d far = Eigen::Matrix4d::Identity();
    far.topRightCorner<3, 1>() = Eigen::Vector3d(3.0, 0, 0.5);
    JointVector untouched = JointVector::Constant(42);
    out = untouched;
    QCOMPARE(inverseKinematics(arm, far, 0, regular, out), IkStatus::kBeyondReach);
    QVERIFY(out == untouched);
    // Invalid pose.
    Eigen::Matrix4d bad = flangePose(arm, regular).matrix();
    bad(0, 0) *= 1.01;
    QCOMPARE(inverseKinematics(arm, bad, 0, regular, out), IkStatus::kInvalidPose);
    // Wrist singular: A5 = 0 (A4 and A6 coaxial); just outside the band it solves.
    JointVector wrist = regular;
    wrist[4] = 0;
    QCOMPARE(codeAt(wrist), IkStatus::kSingular);
    wrist[4] = 1e-4;
    QCOMPARE(codeAt(wrist), IkStatus::kOk);
    // Shoulder singular: wrist centre on the A1 axis. Solve A2 for the wrist centre's x = 0.
    JointVector shoulder = regular;
    auto wristX = [&](double a2) {  // the wrist centre's horizontal distance in the arm's plane
      JointVector t = shoulder;
      t[1] = a2;
      const Eigen::Vector3d w = kukaWristCentre(spec, t);
      return w.x() * std::cos(shoulder[0]) - w.y() * std::sin(shoulder[0]);
    };
    double lo = spec.q_min[1], hi = lo;  // bracket a sign change of wristX over A2's range
    for (double a2 = spec.q_min[1] + 0.01; a2 <= spec.q_max[1]; a2 += 0.01) {
      if (wristX(lo) * wristX(a2) <= 0) {
        hi = a2;
        break;
      }
      lo = a2;
    }
    QVERIFY(hi > lo);
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (lo + hi);
      (wristX(lo) * wristX(mid) <= 0 ? hi : lo) = mid;
    }
    shoulder[1] = 0.5 * (lo + hi);
    const Eigen::Vector3d w = kukaWristCentre(spec, shoulder);
    QVERIFY(std::hypot(w.x(), w.y()) < 1e-9);
    QCOMPARE(codeAt(shoulder), IkStatus::kSingular);
    // Soft limits: a band for A1 above q1 reports kBelowSoftLimit.
    JointVector lower = arm.hardware_lower, upper = arm.hardware_upper;
    lower[0] = regular[0] + 0.1;
    upper[0] = regular[0] + 0.3;
    setSoftLimits(arm, lower, upper);
    QCOMPARE(codeAt(regular), IkStatus::kBelowSoftLimit);
  }
};

QTEST_APPLESS_MAIN(TestKinematics)
#include "test_kinematics.moc"
