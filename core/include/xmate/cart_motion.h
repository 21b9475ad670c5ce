// SPDX-License-Identifier: Apache-2.0
// Jerk-limited S-curve of a scalar path coordinate s from rest to rest (docs/api.md). MOVEL and MOVEC
// map s onto a straight line or an arc. Limits: the Cartesian translation limits of
// docs/planning.md (velocity, acceleration, jerk) times speed_ratio, s in metres.
#pragma once

namespace xmate {

namespace planning {

// The timing of one rest-to-rest jerk-limited ("double S") profile as core/src/planning/double_s.cpp
// plans it (Biagiotti & Melchiorri, "Trajectory Planning for Automatic Machines and Robots",
// sec. 3.4, with v0 = v1 = a0 = a1 = 0). The deceleration mirrors the acceleration. It is declared
// in this public header only so that the motion generators can hold their plan by value.
struct DoubleSProfile {
  double distance = 0;  // signed displacement from start to end
  double jerk = 0;      // jmax: jerk magnitude during the four constant-jerk phases
  double t_jerk = 0;    // Tj: duration of each constant-jerk phase, s
  double t_acc = 0;     // Ta: duration of the acceleration phase (= of the deceleration phase), s
  double t_cruise = 0;  // Tv: duration of the constant-velocity phase, s
  double duration = 0;  // T = 2 Ta + Tv, s
  double a_peak = 0;    // alim = jmax Tj: largest |acceleration| reached
  double v_peak = 0;    // vlim = alim (Ta - Tj): largest |velocity| reached
};

}  // namespace planning

// Threads: one generator belongs to one thread at a time. calculateSynchronizedValues_cart and
// calculateDesiredValues_cart are real-time safe (no allocation, no lock, no system call) for valid
// arguments, so a Control() callback may call them every cycle -- only a refused argument throws.
class CartMotionGenerator {
 public:
  // speed_ratio in (0, 1]; throws std::invalid_argument outside it or for a non-finite s_goal.
  CartMotionGenerator(double speed_ratio, double s_goal);

  // Plans from s_start to s_goal. Cheap to call again with the same s_start (the plan is only
  // recomputed when s_start changes). Throws std::invalid_argument for a non-finite s_start.
  void calculateSynchronizedValues_cart(double s_start);

  // Writes the offset from s_start at time t (s) into *s; returns true once t >= GetTime(),
  // when *s is exactly s_goal - s_start. Throws xmate::MotionException before the first
  // calculateSynchronizedValues_cart, std::invalid_argument for a NaN t or a null s.
  bool calculateDesiredValues_cart(double t, double* s) const;

  // Duration of the planned motion in seconds (0 before planning or for a zero move).
  double GetTime() const;

 private:
  // Owned by core/src/planning/cart_motion.cpp; see there.
  double speed_ratio_;
  double s_goal_;
  bool planned_ = false;
  double s_start_ = 0;
  planning::DoubleSProfile profile_;  // s - s_start as a function of time
};

}  // namespace xmate
