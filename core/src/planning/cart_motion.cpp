// SPDX-License-Identifier: Apache-2.0
// CartMotionGenerator (xmate/cart_motion.h): one double-S profile of the path coordinate s, within
// the planner's Cartesian translation limits (model::plannerCartesianLimits(), docs/planning.md)
// times speed_ratio.
#include <xmate/cart_motion.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

#include <xmate/exception.h>

#include "model/robot_spec.h"
#include "planning/double_s.h"

namespace xmate {
namespace {

void requireFinite(double value, const char* name) {
  if (std::isfinite(value)) return;
  std::ostringstream msg;
  msg << "CartMotionGenerator: " << name << " = " << value << " is not finite; pass a path coordinate in m";
  throw std::invalid_argument(msg.str());
}

}  // namespace

CartMotionGenerator::CartMotionGenerator(double speed_ratio, double s_goal)
    : speed_ratio_(speed_ratio), s_goal_(s_goal) {
  if (!(std::isfinite(speed_ratio) && speed_ratio > 0 && speed_ratio <= 1)) {
    std::ostringstream msg;
    msg << "CartMotionGenerator: speed_ratio = " << speed_ratio << " is outside (0, 1]; pass e.g. 0.2";
    throw std::invalid_argument(msg.str());
  }
  requireFinite(s_goal, "s_goal");
}

void CartMotionGenerator::calculateSynchronizedValues_cart(double s_start) {
  if (planned_ && s_start == s_start_) return;  // vendor programs call this every cycle
  requireFinite(s_start, "s_start");
  const model::CartesianLimits& limits = model::plannerCartesianLimits();
  profile_ = planning::planDoubleS(s_goal_ - s_start, limits.v_trans * speed_ratio_,
                                   limits.a_trans * speed_ratio_, limits.j_trans * speed_ratio_);
  s_start_ = s_start;
  planned_ = true;
}

bool CartMotionGenerator::calculateDesiredValues_cart(double t, double* s) const {
  if (!planned_)
    throw MotionException(
        "CartMotionGenerator: no plan yet; call calculateSynchronizedValues_cart(s_start) first");
  if (s == nullptr) throw std::invalid_argument("CartMotionGenerator: output pointer s is null; pass &s");
  if (std::isnan(t))
    throw std::invalid_argument(
        "CartMotionGenerator: time t is NaN; pass the time since the motion began, in s");
  *s = planning::sampleDoubleS(profile_, t).p;
  return t >= profile_.duration;
}

double CartMotionGenerator::GetTime() const { return planned_ ? profile_.duration : 0.0; }

}  // namespace xmate
