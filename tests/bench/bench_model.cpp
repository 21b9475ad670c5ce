// SPDX-License-Identifier: Apache-2.0
// rci-bench-model: our kinematics, dynamics and IK side by side with KDL on the same URDF, plus
// the 7-axis joint S-curve plan; every model, the xMates and the KUKA arms. Prints median time per call and the largest difference from KDL.
// Usage: rci-bench-model [--quick]      (results quoted in docs/performance.md)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include <kdl/chain.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainidsolver_recursive_newton_euler.hpp>
#include <kdl/chainiksolverpos_lma.hpp>
#include <kdl/chainjnttojacsolver.hpp>
#include <kdl/tree.hpp>
#include <kdl_parser/kdl_parser.hpp>

#include <xmate/joint_motion.h>
#include <xmate/model.h>

#include "model/arm_model.h"
#include "model/dynamics.h"
#include "model/inverse_kinematics.h"
#include "model/kinematics.h"
#include "model/resource_locator.h"
#include "model/robot_spec.h"
#include "model/urdf_loader.h"

namespace {

using namespace xmate;
using namespace xmate::model;

volatile double g_sink = 0;  // keeps the timed calls from being optimised away

struct Settings {
  int samples = 20000;     // random inputs for FK, Jacobian, RNEA
  int ik_samples = 2000;   // random inputs for the IK comparison (KDL's LMA is slow)
  int repeats = 5;         // passes over the inputs
};

// Median over batches of the time per call, in ns. `call(i)` runs the operation on input i.
double medianNsPerCall(int inputs, int repeats, int batch, const std::function<void(int)>& call) {
  std::vector<double> per_call;
  for (int r = 0; r < repeats; ++r) {
    for (int start = 0; start + batch <= inputs; start += batch) {
      const auto t0 = std::chrono::steady_clock::now();
      for (int i = start; i < start + batch; ++i) call(i);
      const auto t1 = std::chrono::steady_clock::now();
      per_call.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() / batch);
    }
  }
  std::nth_element(per_call.begin(), per_call.begin() + per_call.size() / 2, per_call.end());
  return per_call[per_call.size() / 2];
}

KDL::JntArray toKdl(const JointVector& q, int dof) {
  KDL::JntArray a(dof);
  for (int i = 0; i < dof; ++i) a(i) = q[i];
  return a;
}

std::array<double, 7> toArray(const JointVector& q) {
  std::array<double, 7> a{};
  for (int i = 0; i < 7; ++i) a[i] = q[i];
  return a;
}

double frameDifference(const Eigen::Isometry3d& ours, const KDL::Frame& kdl) {
  double worst = 0;
  for (int r = 0; r < 3; ++r) {
    worst = std::max(worst, std::abs(ours.translation()[r] - kdl.p(r)));
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(ours.linear()(r, c) - kdl.M(r, c)));
  }
  return worst;
}

Eigen::Isometry3d fromKdl(const KDL::Frame& f) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r) {
    t.translation()[r] = f.p(r);
    for (int c = 0; c < 3; ++c) t.linear()(r, c) = f.M(r, c);
  }
  return t;
}

// Larger of the position error (m) and rotation error (rad) between two poses.
double poseError(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  const Eigen::AngleAxisd d(a.linear().transpose() * b.linear());
  return std::max((a.translation() - b.translation()).norm(), std::abs(d.angle()));
}

struct Row {
  std::string model, operation;
  double ours_ns, kdl_ns;  // kdl_ns < 0: no KDL counterpart
  std::string agreement;
};

std::string formatDouble(const char* fmt, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

void printRow(const Row& r) {
  const std::string kdl = r.kdl_ns < 0 ? "-" : formatDouble("%.0f", r.kdl_ns);
  const std::string ratio = r.kdl_ns < 0 ? "-" : formatDouble("%.3f", r.ours_ns / r.kdl_ns);
  std::printf("| %-13s | %-28s | %9.0f | %9s | %8s | %-34s |\n", r.model.c_str(), r.operation.c_str(), r.ours_ns,
              kdl.c_str(), ratio.c_str(), r.agreement.c_str());
}

// Everything for one robot model: our internal API, the public XmateModel (xMates; the KUKA arms,
// which it does not cover, through the same internal calls it wraps), and KDL. `index` is the
// model's place in allRobotSpecs() (seeds the inputs).
void benchModel(const RobotSpec& spec, int index, const Settings& s, std::vector<Row>& rows) {
  const std::string urdf = robotDescriptionPath(spec).string();
  KDL::Tree tree;
  KDL::Chain chain;
  if (!kdl_parser::treeFromFile(urdf, tree) || !tree.getChain("base_link", "flange", chain)) {
    std::fprintf(stderr, "KDL could not load %s (chain base_link -> flange)\n", urdf.c_str());
    std::exit(1);
  }
  const int dof = spec.dof;
  const ArmModel arm = makeArmModel(loadRobotChain(spec), spec);
  const bool xmate = spec.family == RobotFamily::kXmate;
  XmateModel model(xmate ? spec.type : XMATE7_PRO);  // used for the xMates only
  model.SetSpeedCheckInterval(0);
  ArmModel ik_arm = arm;  // the KUKA arms' IK: internal API, rated-speed check off as for the xMates
  setSpeedCheckInterval(ik_arm, 0);
  const std::string name(spec.name);

  std::mt19937 rng(7 + index);
  std::vector<JointVector> q(s.samples), dq(s.samples), ddq(s.samples);
  std::vector<KDL::JntArray> kq, kdq, kddq;
  for (int i = 0; i < s.samples; ++i) {
    q[i] = dq[i] = ddq[i] = JointVector::Zero();
    for (int j = 0; j < dof; ++j) {
      q[i][j] = std::uniform_real_distribution<double>(spec.q_min[j], spec.q_max[j])(rng);
      dq[i][j] = std::uniform_real_distribution<double>(-spec.dq_max[j], spec.dq_max[j])(rng);
      ddq[i][j] = std::uniform_real_distribution<double>(-spec.ddq_max[j], spec.ddq_max[j])(rng);
    }
    kq.push_back(toKdl(q[i], dof));
    kdq.push_back(toKdl(dq[i], dof));
    kddq.push_back(toKdl(ddq[i], dof));
  }

  // Forward kinematics of the flange.
  KDL::ChainFkSolverPos_recursive kdl_fk(chain);
  KDL::Frame frame;
  double fk_diff = 0;
  for (int i = 0; i < s.samples; ++i) {
    kdl_fk.JntToCart(kq[i], frame);
    fk_diff = std::max(fk_diff, frameDifference(flangePose(arm, q[i]), frame));
  }
  const double fk_ours = medianNsPerCall(s.samples, s.repeats, 100, [&](int i) {
    g_sink = g_sink + flangePose(arm, q[i]).translation().x();
  });
  const double fk_kdl = medianNsPerCall(s.samples, s.repeats, 100, [&](int i) {
    kdl_fk.JntToCart(kq[i], frame);
    g_sink = g_sink + frame.p.x();
  });
  rows.push_back({name, "FK (flange pose)", fk_ours, fk_kdl, formatDouble("%.1e", fk_diff)});

  // Geometric Jacobian: KDL's is [v; omega] of the chain's end point in the base frame, like ours.
  KDL::ChainJntToJacSolver kdl_jac(chain);
  KDL::Jacobian jac(dof);
  double jac_diff = 0;
  for (int i = 0; i < s.samples; ++i) {
    kdl_jac.JntToJac(kq[i], jac);
    const Jacobian ours = tcpJacobian(arm, q[i]);
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < dof; ++c) jac_diff = std::max(jac_diff, std::abs(ours(r, c) - jac(r, c)));
  }
  const double jac_ours = medianNsPerCall(s.samples, s.repeats, 100, [&](int i) {
    g_sink = g_sink + tcpJacobian(arm, q[i])(0, 0);
  });
  const double jac_kdl = medianNsPerCall(s.samples, s.repeats, 100, [&](int i) {
    kdl_jac.JntToJac(kq[i], jac);
    g_sink = g_sink + jac(0, 0);
  });
  rows.push_back({name, "Jacobian", jac_ours, jac_kdl, formatDouble("%.1e", jac_diff)});

  // Inverse dynamics with gravity.
  KDL::ChainIdSolver_RNE kdl_id(chain, KDL::Vector(0, 0, -kStandardGravity));
  KDL::JntArray torques(dof);
  const KDL::Wrenches no_wrench(chain.getNrOfSegments(), KDL::Wrench::Zero());
  double id_diff = 0;
  for (int i = 0; i < s.samples; ++i) {
    kdl_id.CartToJnt(kq[i], kdq[i], kddq[i], no_wrench, torques);
    const JointVector ours = inverseDynamics(arm, q[i], dq[i], ddq[i]);
    for (int j = 0; j < dof; ++j) id_diff = std::max(id_diff, std::abs(ours[j] - torques(j)));
  }
  const double id_ours = medianNsPerCall(s.samples, s.repeats, 100, [&](int i) {
    g_sink = g_sink + inverseDynamics(arm, q[i], dq[i], ddq[i])[0];
  });
  const double id_kdl = medianNsPerCall(s.samples, s.repeats, 100, [&](int i) {
    kdl_id.CartToJnt(kq[i], kdq[i], kddq[i], no_wrench, torques);
    g_sink = g_sink + torques(0);
  });
  rows.push_back({name, "RNEA (with gravity)", id_ours, id_kdl, formatDouble("%.1e Nm", id_diff)});

  // IK from a seed 0.05 rad per joint away from the answer: KDL's LMA vs our closed form
  // (public GetJointPos, rated-speed check off). Both must reach the target pose.
  const int n_ik = std::min(s.ik_samples, s.samples);
  std::vector<std::array<double, 16>> target(n_ik);
  std::vector<KDL::Frame> kdl_target(n_ik);
  std::vector<double> psi(n_ik);
  std::vector<JointVector> seed(n_ik);
  std::vector<KDL::JntArray> kseed;
  // Our IK: the public GetJointPos on the xMates, inverseKinematics (what it wraps) on the KUKA arms.
  std::vector<Eigen::Matrix4d> target_matrix(n_ik);
  auto ourIk = [&](int i, std::array<double, 7>& result) {
    if (xmate) return model.GetJointPos(target[i], psi[i], toArray(seed[i]), result);
    JointVector qo = JointVector::Zero();
    const int code = static_cast<int>(inverseKinematics(ik_arm, target_matrix[i], psi[i], seed[i], qo));
    result = toArray(qo);
    return code;
  };
  for (int i = 0; i < n_ik; ++i) {
    target[i] = xmate ? model.GetCartPose(toArray(q[i])) : std::array<double, 16>{};
    target_matrix[i] = flangePose(arm, q[i]).matrix();
    kdl_fk.JntToCart(kq[i], kdl_target[i]);
    psi[i] = xmate ? model.GetPsi(toArray(q[i])) : armAngle(arm, q[i]);
    seed[i] = q[i];
    for (int j = 0; j < dof; ++j) seed[i][j] += std::uniform_real_distribution<double>(-0.05, 0.05)(rng);
    kseed.push_back(toKdl(seed[i], dof));
  }
  // LMA with equal weights on position and rotation and a tight tolerance, so that both solvers
  // deliver comparable precision (KDL's defaults weight rotation by 0.01 and stop at 1e-5).
  const Eigen::Matrix<double, 6, 1> lma_weights = Eigen::Matrix<double, 6, 1>::Ones();
  KDL::ChainIkSolverPos_LMA kdl_ik(chain, lma_weights, 1e-10);
  KDL::JntArray k_out(dof);
  std::array<double, 7> out{};
  double ours_err = 0, kdl_err = 0;
  int ours_fail = 0, kdl_fail = 0;
  for (int i = 0; i < n_ik; ++i) {
    if (ourIk(i, out) == 0) {
      JointVector qo = JointVector::Zero();
      for (int j = 0; j < dof; ++j) qo[j] = out[j];
      ours_err = std::max(ours_err, poseError(flangePose(arm, qo), fromKdl(kdl_target[i])));
    } else {
      ++ours_fail;
    }
    if (kdl_ik.CartToJnt(kseed[i], kdl_target[i], k_out) >= 0) {
      kdl_fk.JntToCart(k_out, frame);
      kdl_err = std::max(kdl_err, poseError(fromKdl(frame), fromKdl(kdl_target[i])));
    } else {
      ++kdl_fail;
    }
  }
  const double ik_ours = medianNsPerCall(n_ik, s.repeats, 20, [&](int i) { g_sink = g_sink + ourIk(i, out) + out[0]; });
  const double ik_kdl = medianNsPerCall(n_ik, 1, 10, [&](int i) {
    g_sink = g_sink + kdl_ik.CartToJnt(kseed[i], kdl_target[i], k_out) + k_out(0);
  });
  std::string ik_note = "pose err ours " + formatDouble("%.0e", ours_err) + ", KDL " + formatDouble("%.0e", kdl_err);
  if (ours_fail || kdl_fail)
    ik_note += " (failed: ours " + std::to_string(ours_fail) + ", KDL " + std::to_string(kdl_fail) + ")";
  rows.push_back({name, "IK (closed form vs LMA)", ik_ours, ik_kdl, ik_note});

  // The public call the vendor API offers for dynamics (four RNEA passes: full and each term); on
  // the KUKA arms the internal torqueTerms it wraps.
  std::array<double, 7> full{}, inertial{}, coriolis{}, gravity{};
  const double terms_ours = medianNsPerCall(s.samples, s.repeats, 100, [&](int i) {
    if (xmate) {
      model.GetTauNoFriction(toArray(q[i]), toArray(dq[i]), toArray(ddq[i]), full, inertial, coriolis, gravity);
      g_sink = g_sink + full[0];
    } else {
      g_sink = g_sink + torqueTerms(arm, q[i], dq[i], ddq[i]).full[0];
    }
  });
  rows.push_back({name, xmate ? "GetTauNoFriction (4 terms)" : "torqueTerms (4 terms)", terms_ours, -1, "-"});

  const double mass_ours = medianNsPerCall(s.samples, s.repeats, 100, [&](int i) {
    g_sink = g_sink + massMatrix(arm, q[i])(0, 0);
  });
  rows.push_back({name, "Mass matrix (CRBA)", mass_ours, -1, "-"});

  if (spec.dof == 7) {
    // The 7-axis joint S-curve: construct the generator and plan (random start and goal).
    const int n_plan = std::min(s.samples, 5000);
    const double plan_ns = medianNsPerCall(n_plan, s.repeats, 10, [&](int i) {
      JointMotionGenerator generator(0.5, toArray(q[(i + 1) % n_plan]), spec.type);
      generator.calculateSynchronizedValues_joint(toArray(q[i]));
      g_sink = g_sink + generator.GetTime();
    });
    rows.push_back({name, "Joint S-curve plan", plan_ns, -1, "-"});
  }
}

}  // namespace

int main(int argc, char** argv) {
  Settings s;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) {
      s = Settings{2000, 200, 2};
    } else {
      std::fprintf(stderr, "usage: %s [--quick]\n", argv[0]);
      return 2;
    }
  }
  std::printf("rci-bench-model: median ns per call (batches over %d random configurations, %d passes; IK over %d)\n",
              s.samples, s.repeats, s.ik_samples);
  std::printf("build type: %s; agreement = largest |ours - KDL| over all inputs\n\n", RCI_BENCH_BUILD_TYPE);
  std::printf("| %-13s | %-28s | %9s | %9s | %8s | %-34s |\n", "model", "operation", "ours ns", "KDL ns", "ours/KDL",
              "agreement with KDL");
  std::printf("|%s|%s|%s|%s|%s|%s|\n", std::string(15, '-').c_str(), std::string(30, '-').c_str(),
              std::string(11, '-').c_str(), std::string(11, '-').c_str(), std::string(10, '-').c_str(),
              std::string(36, '-').c_str());
  const auto specs = allRobotSpecs();
  for (int index = 0; index < int(specs.size()); ++index) {
    std::vector<Row> rows;
    benchModel(specs[index], index, s, rows);
    for (const Row& r : rows) printRow(r);
    std::fflush(stdout);
  }
  return 0;
}
