// SPDX-License-Identifier: Apache-2.0
// For the teach tests: a smooth demonstrated path (PATH instruction) synthesized in code instead of
// recorded by hand guiding, so each test knows exactly what was demonstrated.
#pragma once

#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "teach/path.h"
#include "teach/program.h"

namespace teach_test {

// `seconds` at `rate_hz` from q0, at rest at both ends (a quintic time law s from 0 to 1): joint j
// goes out by out_and_back[j] and back, and moves by across[j] in all (rad).
inline xmate::teach::JointPath demonstration(const std::array<double, 7>& q0, const std::array<double, 7>& out_and_back,
                                             const std::array<double, 7>& across, double seconds,
                                             double rate_hz = 100) {
  xmate::teach::JointPath path;
  path.rate_hz = rate_hz;
  const int n = int(std::lround(seconds * rate_hz));
  for (int k = 0; k <= n; ++k) {
    const double u = double(k) / n;
    const double s = u * u * u * (10 - 15 * u + 6 * u * u);
    xmate::teach::JointPoint q = q0;
    for (size_t j = 0; j < 7; ++j)
      q[j] += out_and_back[j] * (1 - std::cos(2 * std::numbers::pi * s)) / 2 + across[j] * s;
    path.q.push_back(q);
  }
  return path;
}

// A PATH instruction replaying `path` at `speed` of the demonstrated pace.
inline xmate::teach::Instruction pathInstruction(const xmate::teach::JointPath& path, double speed,
                                                 const std::string& name = {}) {
  xmate::teach::Instruction in;
  in.type = xmate::teach::InstructionType::kPath;
  in.name = name;
  in.path = path;
  in.speed = speed;
  return in;
}

}  // namespace teach_test
