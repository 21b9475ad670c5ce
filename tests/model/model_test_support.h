// SPDX-License-Identifier: Apache-2.0
// Shared helpers of the model tests: arms with known (random) inertias built from the DH tables,
// random configurations, DH reference frames, pose comparison.
#pragma once

#include <array>
#include <random>

#include <Eigen/Geometry>

#include "model/arm_model.h"
#include "model/chain.h"
#include "model/robot_spec.h"

namespace xmate::model::test {

// chainFromDh(spec) with random but physically valid link inertias (the spec's masses, random
// centres of mass within 0.1 m of the link origin, random principal moments obeying the triangle
// inequality, random principal axes). Deterministic for a given seed.
Chain dhChainWithInertias(const RobotSpec& spec, unsigned seed);

// Uniform random joint angles within [lower + margin, upper - margin] (margin in rad).
JointVector randomConfiguration(const RobotSpec& spec, std::mt19937& rng, double margin = 0.0);
std::array<double, 7> toArray(const JointVector& q);
JointVector fromArray(const std::array<double, 7>& q);

// DH frames T_0^i of the spec's table for i = 0..dof (index 0 is the base), computed directly from
// T(i-1 -> i) = Rz(theta + axis_sign q_i) Tz(d) Tx(a) Rx(alpha): an independent reference for the model.
std::array<Eigen::Isometry3d, 8> dhFrames(const RobotSpec& spec, const JointVector& q);

// Position error (m) and rotation error (rad, angle of a^T b) between two poses.
double positionError(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b);
double rotationError(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b);

Eigen::Isometry3d fromRowMajor(const std::array<double, 16>& m);
std::array<double, 16> toRowMajor(const Eigen::Isometry3d& pose);

}  // namespace xmate::model::test
