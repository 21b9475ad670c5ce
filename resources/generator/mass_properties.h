// SPDX-License-Identifier: Apache-2.0
// Mass, centre of mass and inertia of a link modelled as a set of solids of uniform density
// (overlaps counted twice), computed exactly from the solids' profile curves.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "generator/solid.h"

namespace xmate::robotgen {

// Geometry of one solid per unit density, in the link frame.
struct VolumeMoments {
  double volume = 0;                                          // m^3
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();         // m
  Eigen::Matrix3d inertia_per_density = Eigen::Matrix3d::Zero();  // about the centroid, m^5
};

struct MassProperties {
  double mass = 0;                                   // kg
  Eigen::Vector3d com = Eigen::Vector3d::Zero();     // m, link frame
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero(); // kg m^2, about the com, link axes
};

VolumeMoments volumeMoments(const Solid& solid);

// Sum of the solids' volumes (overlaps counted twice), m^3.
double totalVolume(const std::vector<Solid>& solids);

// Spreads `mass` over the solids in proportion to volume and combines them with the
// parallel-axis theorem.
MassProperties distributeMass(const std::vector<Solid>& solids, double mass);

}  // namespace xmate::robotgen
