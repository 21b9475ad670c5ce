// SPDX-License-Identifier: Apache-2.0
// Pose checks and conversions of cartesian_pose.h.
#include "planning/cartesian_pose.h"

#include <sstream>
#include <stdexcept>

namespace xmate::planning {
namespace {

constexpr double kRotationTolerance = 1e-6;
constexpr double kLastRowTolerance = 1e-9;

[[noreturn]] void rejectPose(const char* what, const std::string& problem) {
  throw std::invalid_argument(std::string(what) + ": " + problem +
                              "; pass a homogeneous transform [R p; 0 0 0 1] with R a rotation matrix");
}

}  // namespace

void requireRigidTransform(const Eigen::Matrix4d& m, const char* what) {
  if (!m.allFinite()) rejectPose(what, "the pose contains NaN or infinite values");
  const double last_row_error = (m.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff();
  if (last_row_error > kLastRowTolerance) {
    std::ostringstream row;
    row << "the last row is [" << m(3, 0) << " " << m(3, 1) << " " << m(3, 2) << " " << m(3, 3)
        << "], not [0 0 0 1]";
    rejectPose(what, row.str());
  }
  const Eigen::Matrix3d r = m.topLeftCorner<3, 3>();
  const double orthonormality_error = (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (orthonormality_error > kRotationTolerance) {
    std::ostringstream problem;
    problem << "the rotation part is not orthonormal (|R^T R - I| = " << orthonormality_error << " > "
            << kRotationTolerance << ")";
    rejectPose(what, problem.str());
  }
  if (r.determinant() < 0) rejectPose(what, "the rotation part is a reflection (determinant -1)");
}

Eigen::Isometry3d poseFromRowMajor(const std::array<double, 16>& row_major, const char* what) {
  const Eigen::Matrix4d m = Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(row_major.data());
  requireRigidTransform(m, what);
  Eigen::Isometry3d pose;
  pose.matrix() = m;
  pose.makeAffine();  // the last row exactly 0 0 0 1
  return pose;
}

std::array<double, 16> poseToRowMajor(const Eigen::Isometry3d& pose) {
  std::array<double, 16> row_major;
  Eigen::Map<Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(row_major.data()) = pose.matrix();
  return row_major;
}

}  // namespace xmate::planning
