// SPDX-License-Identifier: Apache-2.0
// The closed-form double-S planner of double_s.h. Notation follows Biagiotti & Melchiorri sec. 3.4:
// Tj (constant-jerk phase), Ta (acceleration phase), Tv (cruise), vlim, alim. With v0 = v1 = 0 the
// profile is symmetric (Td = Ta), so only the acceleration phase is written out; the deceleration
// phase is its mirror image.
#include "planning/double_s.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace xmate::planning {
namespace {

void requirePositiveLimit(double value, const char* name) {
  if (std::isfinite(value) && value > 0) return;
  std::ostringstream msg;
  msg << "double-S planner: " << name << " = " << value << " is not a usable limit; pass a finite value > 0";
  throw std::invalid_argument(msg.str());
}

// Phase durations of a profile that reaches peak velocity v_peak from rest (eq. 3.19 with v0 = 0):
// the acceleration limit is reached only if v_peak * j_max >= a_max^2.
struct AccelerationPhase {
  double t_jerk, t_acc;
};
AccelerationPhase accelerationPhaseTo(double v_peak, double a_max, double j_max) {
  if (v_peak * j_max >= a_max * a_max) {
    const double t_jerk = a_max / j_max;
    return {t_jerk, t_jerk + v_peak / a_max};
  }
  const double t_jerk = std::sqrt(v_peak / j_max);
  return {t_jerk, 2 * t_jerk};
}

// The acceleration phase of a positive move at time tau in [0, Ta] (eq. 3.30a-c).
DoubleSSample sampleAccelerationPhase(const DoubleSProfile& s, double tau) {
  const double j = s.jerk, tj = s.t_jerk, ta = s.t_acc;
  if (tau < tj) return {j * tau * tau * tau / 6, j * tau * tau / 2, j * tau, j};
  if (tau < ta - tj) {
    const double a = s.a_peak;
    return {a / 6 * (3 * tau * tau - 3 * tj * tau + tj * tj), a * (tau - tj / 2), a, 0};
  }
  const double r = ta - tau;  // time left in the acceleration phase
  return {s.v_peak * ta / 2 - s.v_peak * r + j * r * r * r / 6, s.v_peak - j * r * r / 2, j * r, -j};
}

}  // namespace

DoubleSProfile planDoubleS(double distance, double v_max, double a_max, double j_max) {
  if (!std::isfinite(distance)) {
    std::ostringstream msg;
    msg << "double-S planner: distance = " << distance << " is not finite; pass a finite distance";
    throw std::invalid_argument(msg.str());
  }
  requirePositiveLimit(v_max, "maximum velocity");
  requirePositiveLimit(a_max, "maximum acceleration");
  requirePositiveLimit(j_max, "maximum jerk");

  DoubleSProfile s;
  s.distance = distance;
  const double h = std::abs(distance);
  if (h == 0) return s;

  // Case 1: the move is long enough to cruise at v_max (Tv > 0 in eq. 3.25).
  AccelerationPhase phase = accelerationPhaseTo(v_max, a_max, j_max);
  const bool cruises = v_max * phase.t_acc <= h;
  if (!cruises) {
    if (h >= 2 * a_max * a_max * a_max / (j_max * j_max)) {
      // Case 2: v_max is not reached but a_max is. The peak velocity solves
      // v^2 / a_max + v a_max / j_max = h (distance of acceleration + deceleration).
      const double v_peak =
          a_max / 2 * (std::sqrt(a_max * a_max / (j_max * j_max) + 4 * h / a_max) - a_max / j_max);
      phase = {a_max / j_max, a_max / j_max + v_peak / a_max};
    } else {
      // Case 3: neither v_max nor a_max is reached: four jerk phases only, h = 2 jmax Tj^3.
      const double t_jerk = std::cbrt(h / (2 * j_max));
      phase = {t_jerk, 2 * t_jerk};
    }
  }

  s.jerk = j_max;
  s.t_jerk = phase.t_jerk;
  s.t_acc = phase.t_acc;
  s.a_peak = j_max * phase.t_jerk;
  s.v_peak = s.a_peak * (phase.t_acc - phase.t_jerk);
  // h = vlim (Ta + Tv); written from vlim itself so the phases join without a rounding step.
  s.t_cruise = cruises ? std::max(0.0, h / s.v_peak - s.t_acc) : 0.0;
  s.duration = 2 * s.t_acc + s.t_cruise;
  return s;
}

DoubleSSample sampleDoubleS(const DoubleSProfile& s, double t) {
  if (!(t > 0)) return {};
  if (t >= s.duration) return {s.distance, 0, 0, 0};

  const double h = std::abs(s.distance);
  DoubleSSample m;
  if (t < s.t_acc) {
    m = sampleAccelerationPhase(s, t);
  } else if (t < s.t_acc + s.t_cruise) {
    m = {s.v_peak * s.t_acc / 2 + s.v_peak * (t - s.t_acc), s.v_peak, 0, 0};
  } else {
    // Deceleration: the acceleration phase played backwards from the end.
    const DoubleSSample mirror = sampleAccelerationPhase(s, s.duration - t);
    m = {h - mirror.p, mirror.v, -mirror.a, mirror.j};
  }
  if (s.distance < 0) m = {-m.p, -m.v, -m.a, -m.j};
  return m;
}

}  // namespace xmate::planning
