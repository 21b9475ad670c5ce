// SPDX-License-Identifier: Apache-2.0
// Where the shell solids of each link go: joint housings around the joint axes, tubes between
// consecutive joint centres, a pedestal under joint 1 and a flange disc on the last link, all
// sized from the model's DH table and joint torques (robot_spec.h).
#pragma once

#include <string>
#include <vector>

#include "generator/solid.h"
#include "model/robot_spec.h"

namespace xmate::robotgen {

struct LinkShell {
  std::string name;             // "base_link", "link1", ...
  std::vector<Solid> solids;    // in the link's own frame (chain.h convention), metres
};

// Radius of the housing around joint j (1-based), m. Scales with the arm's reach and the joint's
// torque (the wrist is slimmer than the shoulder, down to 60 % of it) and tapers a little towards
// the tool.
double housingRadius(const model::RobotSpec& spec, int joint);

// Shells of base_link and link1..link<dof>, in that order.
std::vector<LinkShell> armShells(const model::RobotSpec& spec);

}  // namespace xmate::robotgen
