// SPDX-License-Identifier: Apache-2.0
// The range checks of parameter_checks.h, with messages that say what to change.
#include "model/parameter_checks.h"

#include "model/arm_model.h"

#include <cmath>
#include <cstdio>

#include <Eigen/Dense>

namespace xmate::model {
namespace {

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// A problem with `parameter` (element `index`, -1 for none): "call: <text>".
ParameterProblem problem(const char* parameter, int index, std::string text) {
  return {std::move(text), parameter, index};
}

// "call: parameter[i]"
std::string named(const char* call, const char* parameter, int index) {
  std::string s = std::string(call) + ": " + parameter;
  if (index >= 0) s += "[" + std::to_string(index) + "]";
  return s;
}

// "call: parameter[i] = v is outside [lo, hi] unit"
ParameterProblem outside(const char* call, const char* parameter, int index, double value, const std::string& range,
                         const char* unit) {
  return problem(parameter, index,
                 named(call, parameter, index) + " = " + fmt(value) + " is outside " + range +
                     (unit[0] ? std::string(" ") + unit : std::string()));
}

ParameterProblem notFinite(const char* call, const char* parameter, int index) {
  return problem(parameter, index, named(call, parameter, index) + " is not a finite number");
}

template <size_t N>
ParameterProblem checkFiniteArray(const char* call, const char* parameter, const std::array<double, N>& a) {
  for (size_t i = 0; i < N; ++i)
    if (!std::isfinite(a[i])) return notFinite(call, parameter, int(i));
  return {};
}

// Per-joint upper bounds; entries at index >= dof must be exactly 0.
ParameterProblem checkPerJoint(const char* call, const char* parameter, const RobotSpec& spec,
                          const std::array<double, 7>& values, const std::array<double, 7>& max,
                          bool allow_zero, const char* unit) {
  if (auto e = checkFiniteArray(call, parameter, values); !e.empty()) return e;
  for (int i = 0; i < 7; ++i) {
    if (i >= spec.dof) {
      if (values[i] != 0)
        return problem(parameter, i, named(call, parameter, i) + " must be 0 on the 6-axis " +
                                         std::string(spec.display_name));
      continue;
    }
    const bool low = allow_zero ? values[i] < 0 : values[i] <= 0;
    if (low || values[i] > max[i])
      return outside(call, parameter, i, values[i], (allow_zero ? "[0, " : "(0, ") + fmt(max[i]) + "]", unit);
  }
  return {};
}

}  // namespace

double ratedPayloadKg(const RobotSpec& spec) {
  return spec.rated_payload_kg;
}

ParameterProblem checkHomogeneous(const char* call, const char* parameter, const std::array<double, 16>& m) {
  if (auto e = checkFiniteArray(call, parameter, m); !e.empty()) return e;
  if (m[12] != 0 || m[13] != 0 || m[14] != 0 || m[15] != 1)
    return problem(parameter, -1, named(call, parameter, -1) +
                                      " is not a homogeneous transform: its last row must be 0 0 0 1 (row-major 4x4)");
  Eigen::Matrix3d r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = m[4 * i + j];
  const double orth = (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (orth > kHomogeneousTolerance || std::abs(r.determinant() - 1.0) > kHomogeneousTolerance)
    return problem(parameter, -1,
                   named(call, parameter, -1) + " has a rotation part that is not orthonormal (error " + fmt(orth) +
                       ", allowed " + fmt(kHomogeneousTolerance) + "); re-orthonormalise it");
  return {};
}

ParameterProblem checkCollisionThresholds(const RobotSpec& spec, const std::array<double, 7>& t) {
  return checkPerJoint("setCollisionBehavior", "upper_torque_thresholds_nominal", spec, t,
                       spec.collision_threshold_max, false, "Nm");
}

ParameterProblem checkJointImpedance(const RobotSpec& spec, const std::array<double, 7>& k) {
  return checkPerJoint("setJointImpedance", "K_theta", spec, k, spec.joint_stiffness_max, true, "Nm/rad");
}

ParameterProblem checkCartesianImpedance(const std::array<double, 6>& k) {
  if (auto e = checkFiniteArray("setCartesianImpedance", "K_x", k); !e.empty()) return e;
  for (int i = 0; i < 6; ++i)
    if (k[i] < 0 || k[i] > kCartesianStiffnessMax[i])
      return outside("setCartesianImpedance", "K_x", i, k[i], "[0, " + fmt(kCartesianStiffnessMax[i]) + "]",
                     i < 3 ? "N/m" : "Nm/rad");
  return {};
}

ParameterProblem checkFilters(double joint_hz, double cartesian_hz, double torque_hz) {
  const char* names[3] = {"joint_hz", "cartesian_hz", "torque_hz"};
  const double v[3] = {joint_hz, cartesian_hz, torque_hz};
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(v[i])) return notFinite("setFilters", names[i], -1);
    if (v[i] < kFilterMinHz || v[i] > kFilterMaxHz)
      return outside("setFilters", names[i], -1, v[i], "[" + fmt(kFilterMinHz) + ", " + fmt(kFilterMaxHz) + "]",
                     "Hz (10-100 Hz recommended)");
  }
  return {};
}

ParameterProblem checkLoad(const RobotSpec& spec, double mass, const std::array<double, 3>& center,
                      const std::array<double, 9>& inertia) {
  if (!std::isfinite(mass)) return notFinite("setLoad", "mass", -1);
  if (mass < 0 || mass > ratedPayloadKg(spec))
    return outside("setLoad", "mass", -1, mass, "[0, " + fmt(ratedPayloadKg(spec)) + "]",
                   ("kg (the rated payload of the " + std::string(spec.display_name) + ")").c_str());
  if (auto e = checkFiniteArray("setLoad", "center", center); !e.empty()) return e;
  for (int i = 0; i < 3; ++i)
    if (std::abs(center[i]) > kLoadCenterMaxM)
      return outside("setLoad", "center", i, center[i], "[-" + fmt(kLoadCenterMaxM) + ", " + fmt(kLoadCenterMaxM) + "]", "m");
  if (auto e = checkFiniteArray("setLoad", "inertia", inertia); !e.empty()) return e;
  Eigen::Matrix3d I;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) I(i, j) = inertia[3 * i + j];
  if (!isSymmetricInertia(I))
    return problem("inertia", -1, "setLoad: inertia must be symmetric (row-major 3x3 about the centre of mass, kg m^2)");
  for (int i = 0; i < 3; ++i)
    if (I(i, i) > kLoadInertiaMaxKgM2)
      return outside("setLoad", "inertia", 4 * i, I(i, i), "[0, " + fmt(kLoadInertiaMaxKgM2) + "]",
                     "kg m^2 (a diagonal moment of inertia)");
  const double scale = std::max(1e-9, I.cwiseAbs().maxCoeff());
  const Eigen::Vector3d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I).eigenvalues();
  if (ev.minCoeff() < -1e-12)
    return problem("inertia", -1,
                   "setLoad: inertia must be positive semi-definite (smallest eigenvalue " + fmt(ev.minCoeff()) + ")");
  const double a = I(0, 0), b = I(1, 1), c = I(2, 2), tol = 1e-9 * scale;
  if (a + b < c - tol || b + c < a - tol || a + c < b - tol)
    return problem("inertia", -1,
                   "setLoad: inertia diagonal violates the triangle inequality (Ixx + Iyy >= Izz, ...): no real body has it");
  return {};
}

ParameterProblem checkToolFrame(const std::array<double, 16>& f) {
  if (auto e = checkHomogeneous("setCoor", "F_T_EE", f); !e.empty()) return e;
  const double d = std::sqrt(f[3] * f[3] + f[7] * f[7] + f[11] * f[11]);
  if (d > kToolOffsetMaxM)
    return problem("F_T_EE", -1,
                   "setCoor: the TCP is " + fmt(d) + " m from the flange; at most " + fmt(kToolOffsetMaxM) + " m is accepted");
  return {};
}

ParameterProblem checkCartesianLimit(const std::array<double, 3>& size, const std::array<double, 16>& frame) {
  if (auto e = checkFiniteArray("setCartesianLimit", "size", size); !e.empty()) return e;
  for (int i = 0; i < 3; ++i)
    if (size[i] <= 0 || size[i] > kSafetyBoxMaxSizeM)
      return outside("setCartesianLimit", "size", i, size[i], "(0, " + fmt(kSafetyBoxMaxSizeM) + "]", "m");
  return checkHomogeneous("setCartesianLimit", "frame", frame);
}

ParameterProblem checkSoftLimits(const RobotSpec& spec, const std::array<double, 7>& upper_deg,
                            const std::array<double, 7>& lower_deg) {
  if (auto e = checkFiniteArray("setJointLimit", "upper", upper_deg); !e.empty()) return e;
  if (auto e = checkFiniteArray("setJointLimit", "lower", lower_deg); !e.empty()) return e;
  constexpr double kDeg = 180.0 / 3.14159265358979323846;
  for (int i = 0; i < spec.dof; ++i) {
    const double hi = spec.q_max[i] * kDeg, lo = spec.q_min[i] * kDeg;
    const std::string range = "[" + fmt(std::round(lo * 1e6) / 1e6) + ", " + fmt(std::round(hi * 1e6) / 1e6) + "]";
    if (upper_deg[i] > hi + 1e-9 || upper_deg[i] < lo - 1e-9)
      return outside("setJointLimit", "upper", i, upper_deg[i], range, "deg (the hardware range)");
    if (lower_deg[i] > hi + 1e-9 || lower_deg[i] < lo - 1e-9)
      return outside("setJointLimit", "lower", i, lower_deg[i], range, "deg (the hardware range)");
    if (!(lower_deg[i] < upper_deg[i]))
      return problem("lower", i,
                     "setJointLimit: lower[" + std::to_string(i) + "] = " + fmt(lower_deg[i]) + " must be below upper[" +
                         std::to_string(i) + "] = " + fmt(upper_deg[i]));
  }
  return {};
}

ParameterProblem checkDesiredWrench(const std::array<double, 6>& w) {
  if (auto e = checkFiniteArray("setCartImpDesiredTau", "tau", w); !e.empty()) return e;
  for (int i = 0; i < 6; ++i) {
    const double max = i < 3 ? kDesiredForceMaxN : kDesiredTorqueMaxNm;
    if (std::abs(w[i]) > max)
      return outside("setCartImpDesiredTau", "tau", i, w[i], "[-" + fmt(max) + ", " + fmt(max) + "]", i < 3 ? "N" : "Nm");
  }
  return {};
}

ParameterProblem checkForceFrame(const std::array<double, 16>& frame, int fc_type) {
  if (fc_type < 1 || fc_type > 3)
    return problem("fc_type", -1,
                   "setFcCoor: fc_type = " + std::to_string(fc_type) + " must be 1 (world), 2 (tool) or 3 (path)");
  return checkHomogeneous("setFcCoor", "fc_coor", frame);
}

ParameterProblem checkDrag(int drag_space, int drag_type) {
  if (drag_space < 1 || drag_space > 2)
    return problem("drag_space", -1,
                   "startDrag: drag_space = " + std::to_string(drag_space) + " must be 1 (joint space) or 2 (Cartesian space)");
  if (drag_type < 1 || drag_type > 3)
    return problem("drag_type", -1,
                   "startDrag: drag_type = " + std::to_string(drag_type) +
                       " must be 1 (translation only), 2 (rotation only) or 3 (free)");
  if (drag_space == 1 && drag_type != 3)
    return problem("drag_type", -1,
                   "startDrag: joint-space drag (drag_space = 1) is always free: use drag_type = 3, or drag_space = 2 "
                   "to restrict to translation or rotation");
  return {};
}

ParameterProblem checkMotorPower(int state) {
  if (state != 0 && state != 1)
    return problem("state", -1,
                   "setMotorPower: state = " + std::to_string(state) + " must be 1 (power on) or 0 (power off)");
  return {};
}

}  // namespace xmate::model
