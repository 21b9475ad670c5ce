// SPDX-License-Identifier: Apache-2.0
// axisCorrectionLimits (axis_correction.h): the AXISCORR / AXISCORRMON parameters of a context.
#include "rsi/axis_correction.h"

#include <cmath>

namespace xmate::rsi {
namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;
constexpr double kKukaDefaultLimitDeg = 5.0;  // AXISCORR's limits when the context does not set them

}  // namespace

AxisCorrectionLimits axisCorrectionLimits(const Context& context) {
  const Object* corr = nullptr;
  const Object* monitor = nullptr;
  for (const Object& object : context.objects) {
    if (!corr && object.type == "AXISCORR") corr = &object;
    if (!monitor && object.type == "AXISCORRMON") monitor = &object;
  }
  if (!corr)
    throw ConfigError(context.path + ": the context has no AXISCORR object, so the PC cannot move the robot by axis "
                      "corrections; add one in RSI Visual, wired to the ETHERNET object's outputs 1..6");
  AxisCorrectionLimits limits;
  for (size_t i = 0; i < 6; ++i) {
    const std::string axis = "A" + std::to_string(i + 1);
    limits.lower[i] = numberParameter(context, *corr, "LowerLim" + axis, -kKukaDefaultLimitDeg) / kDeg;
    limits.upper[i] = numberParameter(context, *corr, "UpperLim" + axis, kKukaDefaultLimitDeg) / kDeg;
    limits.lower_by[i] = corr->id + "'s LowerLim" + axis;
    limits.upper_by[i] = corr->id + "'s UpperLim" + axis;
    if (!monitor || !monitor->parameter("Max" + axis)) continue;
    const double max = std::abs(numberParameter(context, *monitor, "Max" + axis, 0)) / kDeg;
    if (max < limits.upper[i]) {
      limits.upper[i] = max;
      limits.upper_by[i] = monitor->id + "'s Max" + axis;
    }
    if (-max > limits.lower[i]) {
      limits.lower[i] = -max;
      limits.lower_by[i] = monitor->id + "'s Max" + axis;
    }
  }
  return limits;
}

}  // namespace xmate::rsi
