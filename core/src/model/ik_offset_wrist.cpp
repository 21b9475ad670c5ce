// SPDX-License-Identifier: Apache-2.0
// Offset-wrist inverse kinematics (KUKA). With DH angles phi_i = theta_i + axis_sign_i * q_i:
//   J1 turns the vertical arm plane; the shoulder o1 = Rz(phi1) (a1, 0, d1);
//   in that plane the wrist centre is o1 + R(phi2) [(a2, 0) + R(phi3) (a3, -sgn(alpha3) d4)];
//   the wrist is R03^T R = Rz(phi4) Ry(-sgn(alpha4) phi5) Rz(phi6) (alpha5 = -alpha4, alpha6 = 0).
// The same structure as Brandstoetter, Angerer, Hofbaur (2014), "An analytical solution of the
// inverse kinematics problem of industrial serial manipulators with an ortho-parallel basis and a
// spherical wrist", written here in DH terms.
#include "model/ik_offset_wrist.h"

#include <algorithm>
#include <cmath>

#include "model/euler_zyz.h"

namespace xmate::model {
namespace {

constexpr double kPi = 3.14159265358979323846;

Eigen::Matrix3d rotX(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Eigen::Matrix3d r;
  r << 1, 0, 0, 0, c, -s, 0, s, c;
  return r;
}

double sign(double x) { return x < 0 ? -1.0 : 1.0; }

// Joint value (the controller's) of DH angle phi of row r.
double jointOf(const DhRow& r, double phi) { return r.axis_sign * (phi - r.theta); }

}  // namespace

IkStatus offsetWristCandidates(const ArmModel& arm, const Eigen::Isometry3d& flange, const JointVector& q_init,
                               IkCandidates& out) {
  const ArmGeometry& g = arm.geometry;
  const auto& dh = g.dh;
  const Eigen::Matrix3d& r = flange.linear();
  const Eigen::Vector3d w = flange.translation() - g.wrist_to_flange * r.col(2);  // wrist centre
  const double horizontal = std::hypot(w.x(), w.y());
  if (horizontal < kIkSingularTolerance) return IkStatus::kSingular;  // on the J1 axis

  const double a2 = g.upper_arm;
  const Eigen::Vector2d forearm(g.elbow_offset, -sign(dh[2].alpha) * g.forearm);  // in the elbow frame
  const double len = forearm.norm();
  const double beta = std::atan2(forearm.y(), forearm.x());
  const double azimuth = std::atan2(w.y(), w.x());
  const double wrist_pitch_sign = -sign(dh[3].alpha);

  IkStatus front_failure = IkStatus::kOk;
  for (int shoulder = 0; shoulder < 2; ++shoulder) {  // J2 in front of the J1 axis, or behind it
    const double phi1 = azimuth + shoulder * kPi;
    const Eigen::Matrix3d r01 = rotZ(phi1) * rotX(dh[0].alpha);
    const Eigen::Vector3d o1 = rotZ(phi1) * Eigen::Vector3d(dh[0].a, 0, dh[0].d);
    const Eigen::Vector3d p = r01.transpose() * (w - o1);  // in the arm plane: p.z() = 0
    const double reach = std::hypot(p.x(), p.y());
    if (reach > a2 + len + kIkReachTolerance || reach < std::abs(a2 - len) - kIkReachTolerance) {
      if (shoulder == 0) front_failure = reach > a2 + len ? IkStatus::kBeyondReach : IkStatus::kTooClose;
      continue;
    }
    const double c = std::clamp((reach * reach - a2 * a2 - len * len) / (2 * a2 * len), -1.0, 1.0);
    const double bend = std::acos(c);  // 0: stretched, pi: folded
    const bool elbow_singular = bend < kIkSingularTolerance || kPi - bend < kIkSingularTolerance;
    for (const double elbow : {1.0, -1.0}) {  // elbow up or down
      const double phi3 = elbow * bend - beta;
      const Eigen::Vector2d u = Eigen::Vector2d(a2, 0) + Eigen::Rotation2Dd(phi3) * forearm;
      const double phi2 = std::atan2(p.y(), p.x()) - std::atan2(u.y(), u.x());
      JointVector q = JointVector::Zero();
      q[0] = jointOf(dh[0], phi1);
      q[1] = jointOf(dh[1], phi2);
      q[2] = jointOf(dh[2], phi3);
      const Eigen::Matrix3d r03 = r01 * rotZ(phi2) * rotX(dh[1].alpha) * rotZ(phi3) * rotX(dh[2].alpha);
      bool wrist_singular = false;  // J4/J6 coaxial
      const double phi4_init = dh[3].theta + dh[3].axis_sign * q_init[3];
      const ZyzAngles z = zyzForIk(r03.transpose() * r, phi4_init, wrist_singular);
      for (int flip = 0; flip < 2; ++flip) {  // wrist: (phi4, b, phi6) or (phi4 + pi, -b, phi6 + pi)
        q[3] = jointOf(dh[3], z.a + flip * kPi);
        q[4] = jointOf(dh[4], wrist_pitch_sign * (flip == 0 ? z.b : -z.b));
        q[5] = jointOf(dh[5], z.c + flip * kPi);
        out.items[out.count++] = IkCandidate{q, elbow_singular || wrist_singular};
      }
    }
  }
  return out.count > 0 ? IkStatus::kOk : front_failure;
}

}  // namespace xmate::model
