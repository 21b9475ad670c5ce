// SPDX-License-Identifier: Apache-2.0
// How far the PC may correct each axis over RSI: the context's AXISCORR limits, tightened by its
// AXISCORRMON. Read once at set-up; arm::JointStream checks motions against them.
#pragma once

#include <array>
#include <string>

#include "rsi/config.h"

namespace xmate::rsi {

// The total axis correction the context lets through, per axis (rad), and what sets each limit
// ("AXISCORR1's UpperLimA2", "AXISCORRMON1's MaxA2").
struct AxisCorrectionLimits {
  std::array<double, 6> lower{}, upper{};
  std::array<std::string, 6> lower_by, upper_by;
};

// The first AXISCORR object's LowerLimA1..A6 / UpperLimA1..A6 (KUKA's default +-5 deg where one is
// not given), tightened by the first AXISCORRMON's MaxA1..A6 where it has one (it stops RSI beyond
// it). Throws ConfigError naming the file when the context has no AXISCORR object (it then cannot
// move the robot by axis corrections) or a limit is not a number. Set-up; any thread.
AxisCorrectionLimits axisCorrectionLimits(const Context& context);

}  // namespace xmate::rsi
