// SPDX-License-Identifier: Apache-2.0
// URDF text of one robot model: joints and limits from robot_spec.h (placed by chainFromDh),
// link inertials and meshes as the generator worked them out.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "generator/mass_properties.h"
#include "model/robot_spec.h"

namespace xmate::robotgen {

struct UrdfLink {
  std::string name;              // base_link, link1, ...
  MassProperties inertial;       // as it is to be written
  std::string estimate_note;     // says where mass, com and inertia come from (an XML comment)
  std::string mesh_file;         // relative to the URDF file
  bool flange_colour = false;    // the darker material of the flange end
};

// URDF roll-pitch-yaw (R = Rz(yaw) Ry(pitch) Rx(roll)) of a rotation matrix.
Eigen::Vector3d urdfRpy(const Eigen::Matrix3d& r);

// The whole file; links[0] is base_link, links[i] is link i.
std::string robotUrdf(const model::RobotSpec& spec, const std::vector<UrdfLink>& links);

}  // namespace xmate::robotgen
