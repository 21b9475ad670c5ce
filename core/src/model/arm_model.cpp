// SPDX-License-Identifier: Apache-2.0
// Building an ArmModel from a Chain, and the setters that keep its derived fields consistent.
#include "model/arm_model.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "model/kinematics.h"

namespace xmate::model {
namespace {

constexpr double kHalfPi = 1.57079632679489661923;
// How closely a chain's flange must follow the DH table for the closed-form IK to hold (m, rad).
constexpr double kDhAgreement = 1e-9;

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

JointPlacement placementOf(const ChainJoint& joint) {
  JointPlacement p;
  p.rotation = joint.origin.linear();
  p.translation = joint.origin.translation();
  p.axis = joint.axis.normalized();
  p.axis_is_z = p.axis == Eigen::Vector3d::UnitZ() || p.axis == -Eigen::Vector3d::UnitZ();
  p.z_sign = p.axis.z() < 0 ? -1.0 : 1.0;
  return p;
}

LinkInertia inertiaOf(const ChainLink& link) { return inertiaAboutOrigin(link.mass, link.com, link.inertia); }

// The closed-form IK (ik_srs.cpp, ik_six_axis.cpp) is derived for exactly these DH structures.
bool hasSrsStructure(const RobotSpec& s) {
  const double alpha[7] = {-kHalfPi, kHalfPi, -kHalfPi, kHalfPi, -kHalfPi, kHalfPi, 0};
  for (int i = 0; i < 7; ++i) {
    const DhRow& r = s.dh[i];
    const bool d_expected_zero = i == 1 || i == 3 || i == 5;
    if (r.a != 0 || r.theta != 0 || r.axis_sign != 1 || std::abs(r.alpha - alpha[i]) > 1e-12) return false;
    if (d_expected_zero != (r.d == 0)) return false;
  }
  return s.dof == 7;
}

bool hasSixAxisStructure(const RobotSpec& s) {
  const double alpha[6] = {-kHalfPi, 0, kHalfPi, -kHalfPi, kHalfPi, 0};
  const double a_nonzero[6] = {0, 1, 0, 0, 0, 0};
  const double d_nonzero[6] = {1, 0, 0, 1, 0, 1};
  for (int i = 0; i < 6; ++i) {
    const DhRow& r = s.dh[i];
    if (r.theta != 0 || r.axis_sign != 1 || std::abs(r.alpha - alpha[i]) > 1e-12) return false;
    if ((r.a != 0) != (a_nonzero[i] != 0) || (r.d != 0) != (d_nonzero[i] != 0)) return false;
  }
  return s.dof == 6;
}

bool isQuarterTurn(double alpha) { return std::abs(std::abs(alpha) - kHalfPi) <= 1e-12; }

// Ortho-parallel arm with offsets and a spherical wrist (ik_offset_wrist.cpp): J1 vertical with the
// shoulder a1 out and d1 up, J2 and J3 parallel (upper arm a2), the forearm offset a3 across and d4
// along the J4 axis, J4 J5 J6 meeting in one point, the flange d6 along J6. Any angle offsets and
// axis senses.
bool hasOffsetWristStructure(const RobotSpec& s) {
  if (s.dof != 6) return false;
  const auto& r = s.dh;
  for (int i = 0; i < 6; ++i)
    if (std::abs(r[i].axis_sign) != 1) return false;
  return isQuarterTurn(r[0].alpha) && r[1].a > 0 && r[1].alpha == 0 && r[1].d == 0 && r[2].d == 0 &&
         isQuarterTurn(r[2].alpha) && r[3].a == 0 && r[3].d != 0 && isQuarterTurn(r[3].alpha) && r[4].a == 0 &&
         r[4].d == 0 && std::abs(r[4].alpha + r[3].alpha) <= 1e-12 && r[5].a == 0 && r[5].alpha == 0;
}

ArmGeometry geometryOf(const RobotSpec& spec) {
  ArmGeometry g;
  if (hasSrsStructure(spec)) {
    g = {spec.dh[0].d, spec.dh[2].d, spec.dh[4].d, spec.dh[6].d};
    g.kind = IkGeometry::kSrs;
    return g;
  }
  if (hasSixAxisStructure(spec)) {
    g = {spec.dh[0].d, spec.dh[1].a, spec.dh[3].d, spec.dh[5].d};
    g.kind = IkGeometry::kSixAxis;
    return g;
  }
  if (hasOffsetWristStructure(spec)) {
    g = {spec.dh[0].d, spec.dh[1].a, spec.dh[3].d, spec.dh[5].d};
    g.kind = IkGeometry::kOffsetWrist;
    g.shoulder_offset = spec.dh[0].a;
    g.elbow_offset = spec.dh[2].a;
    for (int i = 0; i < 6; ++i) g.dh[i] = spec.dh[i];
    return g;
  }
  throw std::runtime_error("RCI model: the DH table of " + std::string(spec.display_name) +
                           " is neither a 7-axis S-R-S arm nor a 6-axis arm with a spherical wrist (with or "
                           "without shoulder and elbow offsets); the closed-form IK supports only those (see "
                           "docs/kinematics.md)");
}

// Throws unless the chain's flange follows the DH table at a spread of configurations.
void requireDhAgreement(const ArmModel& arm, const RobotSpec& spec, const std::string& chain_name) {
  for (int k = 0; k < 8; ++k) {
    std::array<double, 7> q{};
    JointVector qv = JointVector::Zero();
    for (int i = 0; i < spec.dof; ++i) {
      const double t = std::sin(1.7 * k + 0.9 * i);  // deterministic, spread over the range
      q[i] = qv[i] = k == 0 ? 0.0 : spec.q_min[i] + 0.5 * (1 + t) * (spec.q_max[i] - spec.q_min[i]);
    }
    const Eigen::Isometry3d chain_pose = flangePose(arm, qv);
    const Eigen::Isometry3d dh_pose = dhFlangePose(spec, q);
    const double dp = (chain_pose.translation() - dh_pose.translation()).norm();
    const double dr = (chain_pose.linear() - dh_pose.linear()).norm();
    if (dp <= kDhAgreement && dr <= kDhAgreement) continue;
    std::ostringstream msg;
    msg << "RCI model: the flange of chain '" << chain_name << "' differs from the DH table of "
        << spec.display_name << " by " << dp << " m / " << dr << " (rotation) at test configuration " << k
        << "; the closed-form IK needs the DH geometry. Regenerate the URDF (resources/generator) "
           "or check that the right file is installed.";
    throw std::runtime_error(msg.str());
  }
}

void requireRigid(const Eigen::Isometry3d& t, const char* what) {
  const Eigen::Matrix3d r = t.linear();
  const bool ok = t.matrix().allFinite() &&
                  (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() <= 1e-6 &&
                  r.determinant() > 0;
  if (!ok)
    throw std::invalid_argument(std::string(what) +
                                ": not a rigid transform (NaN/Inf or rotation not orthonormal within "
                                "1e-6); pass a homogeneous matrix with a proper rotation");
}

}  // namespace

LinkInertia inertiaAboutOrigin(double mass, const Eigen::Vector3d& com, const Eigen::Matrix3d& inertia_about_com,
                               const Eigen::Isometry3d& a_T_b) {
  const Eigen::Matrix3d r = a_T_b.linear();
  const Eigen::Vector3d c = a_T_b * com;
  LinkInertia out;
  out.mass = mass;
  out.first_moment = mass * c;
  // Parallel-axis theorem: I_origin = R I_com R^T - m [c]x [c]x.
  out.rotational = r * inertia_about_com * r.transpose() - mass * skew(c) * skew(c);
  return out;
}

ArmModel makeArmModel(const Chain& chain, const RobotSpec& spec) {
  if (chain.dof != spec.dof)
    throw std::runtime_error("RCI model: chain '" + chain.name + "' has " + std::to_string(chain.dof) +
                             " joints but " + std::string(spec.display_name) + " has " +
                             std::to_string(spec.dof) + "; load the description of the same model");
  ArmModel arm;
  arm.dof = spec.dof;
  arm.arm_joint_count = spec.dof == 7 ? 4 : 3;
  arm.family = spec.family;
  for (int i = 0; i < spec.dof; ++i) {
    arm.joints[i] = placementOf(chain.joints[i]);
    arm.chain_links[i] = inertiaOf(chain.links[i]);
    arm.hardware_lower[i] = spec.q_min[i];
    arm.hardware_upper[i] = spec.q_max[i];
    arm.max_velocity[i] = spec.dq_max[i];
  }
  arm.links = arm.chain_links;
  arm.lower = arm.hardware_lower;
  arm.upper = arm.hardware_upper;
  arm.flange = chain.flange;
  arm.geometry = geometryOf(spec);
  requireDhAgreement(arm, spec, chain.name);
  return arm;
}

void setTool(ArmModel& arm, const Eigen::Isometry3d& flange_to_tcp) {
  requireRigid(flange_to_tcp, "SetCoor (F_T_EE)");
  arm.tool = flange_to_tcp;
  arm.tool_inverse = flange_to_tcp.inverse(Eigen::Isometry);
}

bool isSymmetricInertia(const Eigen::Matrix3d& inertia) {
  if (!inertia.allFinite()) return false;
  const double scale = std::max(1e-9, inertia.cwiseAbs().maxCoeff());
  return (inertia - inertia.transpose()).cwiseAbs().maxCoeff() <= 1e-9 * scale;
}

void setPayload(ArmModel& arm, const Payload& given) {
  Payload payload = given;
  if (!std::isfinite(payload.mass) || payload.mass < 0)
    throw std::invalid_argument("SetLoad: mass must be finite and >= 0 kg");
  if (!payload.com.allFinite())
    throw std::invalid_argument("SetLoad: centre of mass must be finite (m, flange frame)");
  if (!isSymmetricInertia(payload.inertia))
    throw std::invalid_argument(
        "SetLoad: inertia must be a finite symmetric 3x3 matrix (kg m^2, about the centre of mass, flange axes)");
  payload.inertia = 0.5 * (payload.inertia + payload.inertia.transpose()).eval();
  arm.payload = payload;
  arm.links = arm.chain_links;
  const LinkInertia load = inertiaAboutOrigin(payload.mass, payload.com, payload.inertia, arm.flange);
  LinkInertia& last = arm.links[arm.dof - 1];
  last.mass += load.mass;
  last.first_moment += load.first_moment;
  last.rotational += load.rotational;
}

void setSoftLimits(ArmModel& arm, const JointVector& lower, const JointVector& upper) {
  for (int i = 0; i < arm.dof; ++i) {
    const bool ok = std::isfinite(lower[i]) && std::isfinite(upper[i]) && lower[i] < upper[i] &&
                    lower[i] >= arm.hardware_lower[i] && upper[i] <= arm.hardware_upper[i];
    if (ok) continue;
    std::ostringstream msg;
    msg << "SetJointLimit: joint " << i + 1 << " limits [" << lower[i] << ", " << upper[i]
        << "] rad must satisfy " << arm.hardware_lower[i] << " <= lower < upper <= " << arm.hardware_upper[i]
        << " rad (the hardware range)";
    throw std::invalid_argument(msg.str());
  }
  arm.lower.head(arm.dof) = lower.head(arm.dof);
  arm.upper.head(arm.dof) = upper.head(arm.dof);
}

void setSpeedCheckInterval(ArmModel& arm, double seconds) {
  if (!std::isfinite(seconds) || seconds < 0)
    throw std::invalid_argument("SetSpeedCheckInterval: interval must be a finite number of seconds >= 0 (0 = off)");
  arm.speed_check_interval = seconds;
}

}  // namespace xmate::model
