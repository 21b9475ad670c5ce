// Jerk-limited S-curve of a scalar path coordinate s from rest to rest (API.md). MOVEL and MOVEC
// map s onto a straight line or an arc. Limits: the Cartesian translation limits of
// docs/planning.md (velocity, acceleration, jerk) times speed_ratio, s in metres.
#pragma once

namespace xmate {

class CartMotionGenerator {
 public:
  // speed_ratio in (0, 1]; throws std::invalid_argument outside it or for a non-finite s_goal.
  CartMotionGenerator(double speed_ratio, double s_goal);

  // Plans from s_start to s_goal. Cheap to call again with the same s_start.
  void calculateSynchronizedValues_cart(double s_start);

  // Writes the offset from s_start at time t (s) into *s; returns true once t >= GetTime(),
  // when *s is exactly s_goal - s_start.
  bool calculateDesiredValues_cart(double t, double* s) const;

  // Duration of the planned motion in seconds.
  double GetTime() const;

 private:
  // Owned by core/src/planning/cart_motion.cpp; see there.
  double speed_ratio_;
  double s_goal_;
};

}  // namespace xmate
