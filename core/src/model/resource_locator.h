// SPDX-License-Identifier: Apache-2.0
// Finds the robot descriptions and meshes: in the source tree while developing, under
// <prefix>/share/rci once installed, or wherever RCI_DATA_DIR points.
#pragma once

#include <filesystem>

#include "model/robot_spec.h"

namespace xmate::model {

// The data root: a folder holding resources/robots/ and meshes/. Searched in order:
// $RCI_DATA_DIR, <executable>/../share/rci, the install prefix, the source tree.
// Throws std::runtime_error naming every place it looked when none holds the robots.
std::filesystem::path dataDirectory();

// <data root>/resources/robots/<name>.urdf
std::filesystem::path robotDescriptionPath(const RobotSpec& spec);

}  // namespace xmate::model
