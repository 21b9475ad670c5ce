// SPDX-License-Identifier: Apache-2.0
// rci-robotgen's whole job for one model: link shells -> meshes and estimated inertials -> URDF,
// and writing them under a data root (resources/robots/<model>.urdf, meshes/<model>/<link>.stl).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "generator/arm_layout.h"
#include "generator/mass_properties.h"
#include "generator/triangle_mesh.h"
#include "generator/urdf_writer.h"
#include "model/robot_spec.h"

namespace xmate::robotgen {

struct GeneratedLink {
  LinkShell shell;
  TriangleMesh mesh;       // the shell's surface, link frame, metres
  UrdfLink urdf;           // name, inertial (exactly as written), note, mesh file
  bool mass_published = false;  // false: derived from the shell volume (base of most models)
  double density = 0;           // kg/m^3 the mass was spread with
};

struct GeneratedRobot {
  std::string name;                 // file stem, "xmate7_pro"
  std::vector<GeneratedLink> links; // base_link, link1..link<dof>
  std::string urdf;                 // the file's text
};

GeneratedRobot generateRobot(const model::RobotSpec& spec);

// Paths relative to a data root.
std::filesystem::path urdfRelativePath(std::string_view model_name);
std::filesystem::path meshRelativePath(std::string_view model_name, std::string_view link_name);

// Writes the URDF and the meshes under data_root, creating folders as needed; returns the files written.
std::vector<std::filesystem::path> writeRobot(const GeneratedRobot& robot, const std::filesystem::path& data_root);

}  // namespace xmate::robotgen
