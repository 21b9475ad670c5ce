// SPDX-License-Identifier: Apache-2.0
// Reads a robot description (URDF) with urdfdom into a Chain: the serial chain from the base
// link through the revolute joints to the flange, with inertias and visual meshes.
#pragma once

#include <filesystem>

#include "model/chain.h"
#include "model/robot_spec.h"

namespace xmate::model {

// Parses the URDF at urdf_file. Mesh file names are resolved to absolute paths: relative names
// against the URDF's folder, package://<pkg>/<rest> against the data root (resource_locator.h).
// Throws std::runtime_error saying what is wrong (missing file, XML error, not a serial chain of
// 6 or 7 revolute joints ending in a link named "flange") and what to do.
Chain loadChain(const std::filesystem::path& urdf_file);

// The installed or in-tree description of one model (resources/robots/<name>.urdf).
Chain loadRobotChain(const RobotSpec& spec);

}  // namespace xmate::model
