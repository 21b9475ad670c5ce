// SPDX-License-Identifier: Apache-2.0
// Dynamics of every model (the four xMates and the two KUKA arms): on the DH-table chain with
// random link inertias and on the URDF models (internal API), and of the xMates through the public
// XmateModel. Checks M(q) symmetric positive definite,
// M ddq = RNEA(q,0,ddq) - RNEA(q,0,0), full = inertial + coriolis + gravity, the power balance
// dE/dt = dq^T tau along a trajectory, gravity = grad V, Coriolis from the Christoffel symbols of
// M, and the payload's effect.
#include <QtTest>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <random>

#include <Eigen/Eigenvalues>
#include <string>

#include <xmate/model.h>

#include "model/arm_model.h"
#include "model/dynamics.h"
#include "model/inverse_kinematics.h"
#include "model/kinematics.h"
#include "model/urdf_loader.h"
#include "model_test_support.h"

using namespace xmate;
using namespace xmate::model;
using namespace xmate::model::test;

// Every heap allocation of this test program is counted, to prove the hot paths make none.
namespace {
std::atomic<long> g_allocations{0};
}
void* operator new(std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace {

// Each internal-API test runs on both descriptions of each model of every family. "index" is the
// model's place in allRobotSpecs().
void addRows() {
  QTest::addColumn<int>("index");
  QTest::addColumn<bool>("urdf");
  const auto specs = allRobotSpecs();
  for (int k = 0; k < int(specs.size()); ++k) {
    const std::string name(specs[k].name);
    QTest::newRow((name + " dh").c_str()) << k << false;
    QTest::newRow((name + " urdf").c_str()) << k << true;
  }
}

struct Fixture {
  const RobotSpec* spec;
  Chain chain;
  ArmModel arm;
};

Fixture fetchFixture() {
  QFETCH(int, index);
  QFETCH(bool, urdf);
  const RobotSpec& spec = allRobotSpecs()[index];
  Chain chain = urdf ? loadRobotChain(spec) : dhChainWithInertias(spec, 100 + index);
  ArmModel arm = makeArmModel(chain, spec);
  return {&spec, chain, arm};
}

Payload samplePayload() {
  Payload p;
  p.mass = 1.7;
  p.com = Eigen::Vector3d(0.02, -0.03, 0.08);
  p.inertia << 0.004, 0.0005, -0.0002, 0.0005, 0.006, 0.0003, -0.0002, 0.0003, 0.003;
  return p;
}

JointVector randomVector(int dof, std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> d(-scale, scale);
  JointVector v = JointVector::Zero();
  for (int i = 0; i < dof; ++i) v[i] = d(rng);
  return v;
}

// Potential energy V(q) = -sum m_i g^T c_i from the DH frames and the chain's link data (link i's
// frame is DH frame i-1 turned by q_i), plus the payload at the flange.
double potentialEnergy(const Fixture& f, const JointVector& q, const Payload& payload) {
  const auto frames = dhFrames(*f.spec, q);
  double v = 0;
  for (int i = 0; i < f.spec->dof; ++i) {
    Eigen::Isometry3d link = frames[i];
    const DhRow& row = f.spec->dh[i];
    link.rotate(Eigen::AngleAxisd(row.theta + row.axis_sign * q[i], Eigen::Vector3d::UnitZ()));
    v += f.chain.links[i].mass * kStandardGravity * (link * f.chain.links[i].com).z();
  }
  v += payload.mass * kStandardGravity * (frames[f.spec->dof] * payload.com).z();
  return v;
}

// A smooth trajectory: q_i(t) = q0_i + a_i sin(w_i t + p_i).
struct Trajectory {
  JointVector q0, amplitude, frequency, phase;
  JointVector q(double t) const {
    return q0 + amplitude.cwiseProduct((frequency * t + phase).array().sin().matrix());
  }
  JointVector dq(double t) const {
    return amplitude.cwiseProduct(frequency).cwiseProduct((frequency * t + phase).array().cos().matrix());
  }
  JointVector ddq(double t) const {
    return -amplitude.cwiseProduct(frequency).cwiseProduct(frequency).cwiseProduct(
        (frequency * t + phase).array().sin().matrix());
  }
};

}  // namespace

class TestDynamics : public QObject {
  Q_OBJECT

 private slots:
  void massMatrixIsSymmetricPositiveDefinite_data() { addRows(); }
  void massMatrixIsSymmetricPositiveDefinite() {
    Fixture f = fetchFixture();
    setPayload(f.arm, samplePayload());
    const int n = f.spec->dof;
    std::mt19937 rng(21);
    for (int k = 0; k < 500; ++k) {
      const JointMatrix m = massMatrix(f.arm, randomConfiguration(*f.spec, rng));
      QVERIFY((m - m.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * m.cwiseAbs().maxCoeff());
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(m.topLeftCorner(n, n));
      QVERIFY(eig.eigenvalues().minCoeff() > 1e-6);
      QCOMPARE(m.bottomRows(kMaxDof - n).cwiseAbs().sum() + m.rightCols(kMaxDof - n).cwiseAbs().sum(), 0.0);
    }
  }

  void massMatrixMatchesInverseDynamics_data() { addRows(); }
  void massMatrixMatchesInverseDynamics() {
    Fixture f = fetchFixture();
    setPayload(f.arm, samplePayload());
    std::mt19937 rng(22);
    double worst = 0;
    for (int k = 0; k < 500; ++k) {
      const JointVector q = randomConfiguration(*f.spec, rng);
      const JointVector ddq = randomVector(f.spec->dof, rng, 5.0);
      const JointVector zero = JointVector::Zero();
      const JointVector expected = inverseDynamics(f.arm, q, zero, ddq) - inverseDynamics(f.arm, q, zero, zero);
      const JointVector ours = massMatrix(f.arm, q) * ddq;
      worst = std::max(worst, (ours - expected).cwiseAbs().maxCoeff() / (1 + expected.cwiseAbs().maxCoeff()));
    }
    qInfo("worst relative difference M ddq vs RNEA: %.3g", worst);
    QVERIFY(worst < 1e-12);
  }

  void coriolisMatchesChristoffelSymbols_data() { addRows(); }
  void coriolisMatchesChristoffelSymbols() {
    const Fixture f = fetchFixture();
    const int n = f.spec->dof;
    constexpr double h = 1e-6;
    std::mt19937 rng(23);
    double worst = 0;
    for (int k = 0; k < 50; ++k) {
      const JointVector q = randomConfiguration(*f.spec, rng);
      const JointVector dq = randomVector(n, rng, 2.0);
      std::array<JointMatrix, kMaxDof> dm;  // dM/dq_k by central differences
      for (int c = 0; c < n; ++c) {
        JointVector plus = q, minus = q;
        plus[c] += h;
        minus[c] -= h;
        dm[c] = (massMatrix(f.arm, plus) - massMatrix(f.arm, minus)) / (2 * h);
      }
      JointVector expected = JointVector::Zero();
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
          for (int c = 0; c < n; ++c) expected[i] += (dm[c](i, j) - 0.5 * dm[i](j, c)) * dq[j] * dq[c];
      const JointVector ours = coriolisTorques(f.arm, q, dq);
      worst = std::max(worst, (ours - expected).cwiseAbs().maxCoeff() / (1 + expected.cwiseAbs().maxCoeff()));
    }
    qInfo("worst relative difference Coriolis vs Christoffel: %.3g", worst);
    QVERIFY(worst < 1e-6);
  }

  void gravityIsPotentialGradient_data() { addRows(); }
  void gravityIsPotentialGradient() {
    Fixture f = fetchFixture();
    const Payload payload = samplePayload();
    setPayload(f.arm, payload);
    constexpr double h = 1e-6;
    std::mt19937 rng(24);
    double worst = 0;
    for (int k = 0; k < 300; ++k) {
      const JointVector q = randomConfiguration(*f.spec, rng);
      JointVector expected = JointVector::Zero();
      for (int i = 0; i < f.spec->dof; ++i) {
        JointVector plus = q, minus = q;
        plus[i] += h;
        minus[i] -= h;
        expected[i] = (potentialEnergy(f, plus, payload) - potentialEnergy(f, minus, payload)) / (2 * h);
      }
      const JointVector ours = gravityTorques(f.arm, q);
      worst = std::max(worst, (ours - expected).cwiseAbs().maxCoeff() / (1 + expected.cwiseAbs().maxCoeff()));
    }
    qInfo("worst relative difference gravity vs dV/dq: %.3g", worst);
    QVERIFY(worst < 1e-7);
  }

  // d/dt [1/2 dq^T M dq + V(q)] = dq^T tau along a smooth trajectory (tau = RNEA with gravity).
  void powerBalance_data() { addRows(); }
  void powerBalance() {
    Fixture f = fetchFixture();
    const Payload payload = samplePayload();
    setPayload(f.arm, payload);
    const int n = f.spec->dof;
    std::mt19937 rng(25);
    Trajectory traj;
    traj.q0 = randomConfiguration(*f.spec, rng, 0.6);
    traj.amplitude = randomVector(n, rng, 0.5);
    traj.frequency = randomVector(n, rng, 3.0);
    traj.phase = randomVector(n, rng, 3.0);
    auto energy = [&](double t) {
      const JointVector q = traj.q(t), dq = traj.dq(t);
      return 0.5 * dq.dot(massMatrix(f.arm, q) * dq) + potentialEnergy(f, q, payload);
    };
    constexpr double h = 1e-5;
    double worst = 0;
    for (int k = 0; k < 200; ++k) {
      const double t = 0.01 * k;
      const double de_dt = (energy(t + h) - energy(t - h)) / (2 * h);
      const JointVector dq = traj.dq(t);
      const JointVector tau = inverseDynamics(f.arm, traj.q(t), dq, traj.ddq(t));
      const double power = dq.dot(tau);
      const double scale = dq.cwiseProduct(tau).cwiseAbs().sum() + 1e-3;
      worst = std::max(worst, std::abs(de_dt - power) / scale);
    }
    qInfo("worst relative power imbalance: %.3g", worst);
    QVERIFY(worst < 1e-7);
  }

  // A point mass at a point c of the flange adds J_c^T (m * 9.81 z) to the gravity torques, with
  // J_c the translational Jacobian of c; and a payload equals the same mass properties merged by hand.
  void payloadChangesTorquesAsExpected_data() { addRows(); }
  void payloadChangesTorquesAsExpected() {
    Fixture f = fetchFixture();
    const ArmModel bare = f.arm;
    Payload point;
    point.mass = 2.5;
    point.com = Eigen::Vector3d(0.03, 0.01, 0.1);
    setPayload(f.arm, point);
    ArmModel at_com = bare;
    Eigen::Isometry3d tool = Eigen::Isometry3d::Identity();
    tool.translation() = point.com;
    setTool(at_com, tool);
    std::mt19937 rng(26);
    double worst = 0;
    for (int k = 0; k < 300; ++k) {
      const JointVector q = randomConfiguration(*f.spec, rng);
      const Eigen::Matrix<double, 3, kMaxDof> jv = tcpJacobian(at_com, q).topRows<3>();
      const JointVector expected = jv.transpose() * Eigen::Vector3d(0, 0, point.mass * kStandardGravity);
      const JointVector ours = gravityTorques(f.arm, q) - gravityTorques(bare, q);
      worst = std::max(worst, (ours - expected).cwiseAbs().maxCoeff());
    }
    QVERIFY(worst < 1e-9);

    // Inertia: merge the payload into the last link of the chain by hand (parallel-axis theorem).
    const Payload p = samplePayload();
    setPayload(f.arm, p);
    Chain merged = f.chain;
    ChainLink& last = merged.links[f.spec->dof - 1];
    const Eigen::Vector3d pc = f.chain.flange * p.com;  // payload centre of mass in the last link frame
    const Eigen::Matrix3d pi = f.chain.flange.linear() * p.inertia * f.chain.flange.linear().transpose();
    const double m = last.mass + p.mass;
    const Eigen::Vector3d c = (last.mass * last.com + p.mass * pc) / m;
    auto shift = [](double mass, const Eigen::Vector3d& d) {
      return mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
    };
    last.inertia = last.inertia + shift(last.mass, last.com - c) + pi + shift(p.mass, pc - c);
    last.mass = m;
    last.com = c;
    const ArmModel reference = makeArmModel(merged, *f.spec);
    worst = 0;
    for (int k = 0; k < 300; ++k) {
      const JointVector q = randomConfiguration(*f.spec, rng);
      const JointVector dq = randomVector(f.spec->dof, rng, 2.0), ddq = randomVector(f.spec->dof, rng, 5.0);
      const JointVector expected = inverseDynamics(reference, q, dq, ddq);
      worst = std::max(worst, (inverseDynamics(f.arm, q, dq, ddq) - expected).cwiseAbs().maxCoeff());
    }
    QVERIFY(worst < 1e-9);
  }

  // FK, Jacobian, IK, RNEA, mass matrix and the torque terms run without touching the heap.
  void hotPathsDoNotAllocate_data() { addRows(); }
  void hotPathsDoNotAllocate() {
    Fixture f = fetchFixture();
    setPayload(f.arm, samplePayload());
    std::mt19937 rng(28);
    const JointVector q = randomConfiguration(*f.spec, rng), dq = randomVector(f.spec->dof, rng, 1.0);
    const Eigen::Matrix4d pose = tcpPose(f.arm, q).matrix();
    const double psi = armAngle(f.arm, q);
    LinkFrames frames;
    JointVector out;
    IkBranchSolutions branches;
    double sink = 0;
    const long before = g_allocations.load();
    for (int k = 0; k < 10; ++k) {
      forwardKinematics(f.arm, q, frames);
      sink += frames.tcp(0, 3) + tcpJacobian(f.arm, q)(0, 0);
      sink += static_cast<int>(inverseKinematics(f.arm, pose, psi, q, out)) + armAngle(f.arm, q);
      sink += static_cast<int>(inverseKinematicsBranches(f.arm, pose, psi, q, branches)) + branches.count;
      sink += inverseDynamics(f.arm, q, dq, dq)[0] + massMatrix(f.arm, q)(0, 0);
      sink += torqueTerms(f.arm, q, dq, dq).full[0] + wrenchToJointTorques(f.arm, q, Vector6d::Ones())[0];
    }
    const long allocations = g_allocations.load() - before;
    QVERIFY(std::isfinite(sink));
    QCOMPARE(allocations, 0L);
  }

  // The public API: GetTauNoFriction's terms add up and match M(q) ddq; SetLoad works through it.
  void publicTorqueTerms_data() {
    QTest::addColumn<int>("type");
    for (XmateType t : allRobotTypes())
      QTest::newRow(std::string(robotSpec(t).name).c_str()) << static_cast<int>(t);
  }
  void publicTorqueTerms() {
    QFETCH(int, type);
    XmateModel model(static_cast<XmateType>(type));
    const RobotSpec& spec = robotSpec(static_cast<XmateType>(type));
    model.SetLoad(1.2, {0.01, 0.0, 0.05}, {0.002, 0, 0, 0, 0.002, 0, 0, 0, 0.001});
    std::mt19937 rng(27);
    double worst_sum = 0, worst_inertial = 0;
    for (int k = 0; k < 500; ++k) {
      const JointVector q = randomConfiguration(spec, rng);
      const JointVector dq = randomVector(spec.dof, rng, 2.0), ddq = randomVector(spec.dof, rng, 5.0);
      std::array<double, 7> full{}, inertial{}, coriolis{}, gravity{};
      model.GetTauNoFriction(toArray(q), toArray(dq), toArray(ddq), full, inertial, coriolis, gravity);
      const std::array<double, 49> m = model.MassMatrix(toArray(q));
      for (int i = 0; i < 7; ++i) {
        worst_sum = std::max(worst_sum, std::abs(full[i] - (inertial[i] + coriolis[i] + gravity[i])));
        double m_ddq = 0;
        for (int j = 0; j < 7; ++j) m_ddq += m[i * 7 + j] * ddq[j];
        worst_inertial = std::max(worst_inertial, std::abs(inertial[i] - m_ddq));
      }
      for (int i = spec.dof; i < 7; ++i) QCOMPARE(full[i], 0.0);
    }
    qInfo("worst |full - sum| %.3g Nm, worst |inertial - M ddq| %.3g Nm", worst_sum, worst_inertial);
    QVERIFY(worst_sum < 1e-9);
    QVERIFY(worst_inertial < 1e-9);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, model.SetLoad(-1.0, {0, 0, 0}, {0, 0, 0, 0, 0, 0, 0, 0, 0}));
  }
};

QTEST_APPLESS_MAIN(TestDynamics)
#include "test_dynamics.moc"
