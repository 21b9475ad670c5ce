// rci-cli: headless tools for xMate robots. With no arguments it describes the default model.
#include <cstdio>
#include <cstring>
#include <string>

#include "model/robot_spec.h"

namespace {

void printModel(const xmate::model::RobotSpec& s) {
  std::printf("%s (%s), %d axes\n", std::string(s.display_name).c_str(), std::string(s.name).c_str(), s.dof);
  std::printf("  joint   q_min    q_max   dq_max  ddq_max  jerk_max  tau_max\n");
  for (int i = 0; i < s.dof; ++i)
    std::printf("  J%-4d %7.1f  %7.1f  %7.3f  %7.1f  %8.0f  %7.1f\n", i + 1, s.q_min[i] * 180 / 3.141592653589793,
                s.q_max[i] * 180 / 3.141592653589793, s.dq_max[i], s.ddq_max[i], s.jerk_max[i], s.tau_max[i]);
}

}  // namespace

int main(int argc, char** argv) {
  const char* name = argc > 2 && std::strcmp(argv[1], "model") == 0 ? argv[2] : "xmate7_pro";
  const auto* spec = xmate::model::findRobotSpec(name);
  if (!spec) {
    std::fprintf(stderr, "rci-cli: unknown model '%s' (known: xmate3_pro, xmate7_pro, xmate3, xmate7)\n", name);
    return 2;
  }
  printModel(*spec);
  return 0;
}
