// SPDX-License-Identifier: Apache-2.0
// rci-robotgen: writes the robot descriptions (URDF) and link meshes (STL) of every model (xMate and
// KUKA) from core/src/model/robot_spec.cpp. Usage: rci-robotgen <data root> [model ...]
#include <cstring>
#include <exception>
#include <iostream>
#include <string>

#include "generator/robot_generator.h"
#include "model/robot_spec.h"

namespace {

std::string modelNames() {
  std::string names;
  for (const auto& spec : xmate::model::allRobotSpecs()) names += (names.empty() ? "" : " ") + std::string(spec.name);
  return names;
}

void printUsage() {
  std::cout << "usage: rci-robotgen <data root> [model ...]\n"
               "Writes <data root>/resources/robots/<model>.urdf and <data root>/meshes/<model>/*.stl\n"
               "for the given models (default: all of " + modelNames() + ").\n"
               "The data root of the source tree is its top folder; the build target\n"
               "regenerate-robots runs this tool on it.\n";
}

void generate(const xmate::model::RobotSpec& spec, const char* root) {
  const auto robot = xmate::robotgen::generateRobot(spec);
  for (const auto& file : xmate::robotgen::writeRobot(robot, root)) std::cout << "wrote " << file.string() << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0) {
    printUsage();
    return argc < 2 ? 2 : 0;
  }
  try {
    if (argc == 2) {
      for (const auto& spec : xmate::model::allRobotSpecs()) generate(spec, argv[1]);
      return 0;
    }
    for (int i = 2; i < argc; ++i) {
      const auto* spec = xmate::model::findRobotSpec(argv[i]);
      if (!spec) {
        std::cerr << "rci-robotgen: unknown model \"" << argv[i] << "\"; known: " << modelNames() << "\n";
        return 2;
      }
      generate(*spec, argv[1]);
    }
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "rci-robotgen: " << e.what() << "\n";
    return 1;
  }
}
