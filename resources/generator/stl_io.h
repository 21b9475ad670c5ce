// SPDX-License-Identifier: Apache-2.0
// Binary STL: little-endian, 80-byte header, one facet normal + three float vertices per
// triangle, metres. Writing is deterministic; reading is used by the tests.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "generator/triangle_mesh.h"

namespace xmate::robotgen {

// The file's bytes. `header` (at most 80 characters, must not start with "solid", which would make
// readers take the file for ASCII STL) is padded with spaces.
std::string binaryStl(const TriangleMesh& mesh, std::string_view header);

struct StlTriangle {
  Eigen::Vector3f normal;
  std::array<Eigen::Vector3f, 3> vertices;
};

// Reads a binary STL file; throws std::runtime_error when it is missing, truncated or not binary.
std::vector<StlTriangle> readBinaryStl(const std::filesystem::path& file);

}  // namespace xmate::robotgen
