// SPDX-License-Identifier: Apache-2.0
// Poses as the Cartesian planners take them: checks that a 4x4 matrix is a proper rigid transform,
// and conversions between Eigen::Isometry3d and the row-major std::array<double, 16> of the RCI API.
#pragma once

#include <array>

#include <Eigen/Geometry>

namespace xmate::planning {

// Throws std::invalid_argument naming `what` (e.g. "MOVEL target") unless the matrix is finite,
// its rotation part is orthonormal with determinant +1 (within 1e-6) and its last row is 0 0 0 1 (within
// 1e-9).
void requireRigidTransform(const Eigen::Matrix4d& matrix, const char* what);

// Row-major 4x4 (RCI's toolTobase_pos_c, cart_pos::pos) -> pose, checked as above.
Eigen::Isometry3d poseFromRowMajor(const std::array<double, 16>& row_major, const char* what);

// Pose -> row-major 4x4. Allocation-free.
std::array<double, 16> poseToRowMajor(const Eigen::Isometry3d& pose);

}  // namespace xmate::planning
