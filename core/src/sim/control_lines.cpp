// SPDX-License-Identifier: Apache-2.0
// The control ports' word splitting and argument parsers (control_lines.h).
#include "sim/control_lines.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace xmate::sim {

Words splitWords(std::string_view line) {
  Words words;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    const size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

double parseNumber(std::string_view word, const char* what) {
  double value = 0;
  const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (ec != std::errc() || end != word.data() + word.size() || !std::isfinite(value))
    throw ControlUsageError(std::string(what) + " must be a finite number, got '" + std::string(word) + "'");
  return value;
}

int parseInteger(std::string_view word, const char* what, int min, int max) {
  int value = 0;
  const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (ec != std::errc() || end != word.data() + word.size() || value < min || value > max)
    throw ControlUsageError(std::string(what) + " must be a whole number from " + std::to_string(min) + " to " +
                            std::to_string(max) + ", got '" + std::string(word) + "'");
  return value;
}

bool parseOnOff(std::string_view word) {
  if (word == "on" || word == "1") return true;
  if (word == "off" || word == "0") return false;
  throw ControlUsageError("expected on or off, got '" + std::string(word) + "'");
}

void expectWords(const Words& w, size_t count) {
  if (w.size() != count)
    throw ControlUsageError("expected " + std::to_string(count - 1) + " argument" + (count == 2 ? "" : "s") + ", got " +
                            std::to_string(w.size() - 1));
}

std::array<double, 6> parseWrench(const Words& w) {
  expectWords(w, 7);
  std::array<double, 6> wrench{};
  const char* names[6] = {"fx", "fy", "fz", "tx", "ty", "tz"};
  for (size_t i = 0; i < 6; ++i) wrench[i] = parseNumber(w[i + 1], names[i]);
  return wrench;
}

std::string wrenchText(const std::array<double, 6>& wrench, const char* where) {
  char text[200];
  std::snprintf(text, sizeof text, "wrench %g %g %g N, %g %g %g Nm (base frame, %s)", wrench[0], wrench[1], wrench[2],
                wrench[3], wrench[4], wrench[5], where);
  return text;
}

}  // namespace xmate::sim
