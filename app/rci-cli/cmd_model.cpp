// SPDX-License-Identifier: Apache-2.0
// rci-cli [model NAME]: the published limits of one model (from core/src/model/robot_spec.cpp).
#include <cstdio>
#include <numbers>

#include "cli.h"
#include "model/robot_spec.h"

namespace rci_cli {
namespace {

void printModel(const xmate::model::RobotSpec& s) {
  constexpr double kDeg = 180.0 / std::numbers::pi;
  std::printf("%s (%s), %d axes\n", std::string(s.display_name).c_str(), std::string(s.name).c_str(), s.dof);
  std::printf("  joint   q_min    q_max   dq_max  ddq_max  jerk_max  tau_max\n");
  for (int i = 0; i < s.dof; ++i)
    std::printf("  J%-4d %7.1f  %7.1f  %7.3f  %7.1f  %8.0f  %7.1f\n", i + 1, s.q_min[i] * kDeg, s.q_max[i] * kDeg,
                s.dq_max[i], s.ddq_max[i], s.jerk_max[i], s.tau_max[i]);
}

}  // namespace

int runModel(xmate::XmateType type) {
  printModel(xmate::model::robotSpec(type));
  return 0;
}

}  // namespace rci_cli
