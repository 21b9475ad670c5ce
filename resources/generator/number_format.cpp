// SPDX-License-Identifier: Apache-2.0
// Shortest round-trip number text and significant-digit rounding (see number_format.h).
#include "generator/number_format.h"

#include <array>
#include <charconv>
#include <stdexcept>
#include <system_error>

namespace xmate::robotgen {

std::string formatNumber(double x) {
  if (x == 0) return "0";  // also turns -0 into "0"
  std::array<char, 64> buffer{};
  const auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), x);
  if (ec != std::errc()) throw std::runtime_error("formatNumber: could not print a double");
  return std::string(buffer.data(), end);
}

double roundToSignificant(double x, int digits) {
  if (x == 0) return 0;
  std::array<char, 64> buffer{};
  const auto printed = std::to_chars(buffer.data(), buffer.data() + buffer.size(), x,
                                     std::chars_format::scientific, digits - 1);
  if (printed.ec != std::errc()) throw std::runtime_error("roundToSignificant: could not print a double");
  double rounded = 0;
  const auto parsed = std::from_chars(buffer.data(), printed.ptr, rounded);
  if (parsed.ec != std::errc()) throw std::runtime_error("roundToSignificant: could not read back a double");
  return rounded;
}

}  // namespace xmate::robotgen
