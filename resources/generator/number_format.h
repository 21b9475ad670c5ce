// SPDX-License-Identifier: Apache-2.0
// How rci-robotgen prints numbers: shortest round-trip decimal text, so the generated files are
// byte-for-byte reproducible and 0.3415 stays "0.3415" while pi/2 keeps every digit.
#pragma once

#include <string>

namespace xmate::robotgen {

// Shortest text that reads back as exactly x (std::to_chars); -0 prints as "0".
std::string formatNumber(double x);

// x rounded to `digits` significant decimal digits (returned as the nearest double). Used for
// estimated quantities, whose last bits carry no information and could differ between libm builds.
double roundToSignificant(double x, int digits);

}  // namespace xmate::robotgen
