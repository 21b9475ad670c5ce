// SPDX-License-Identifier: Apache-2.0
// Writes the URDF text (see urdf_writer.h). The frame convention is chain.h's: link i's frame
// sits on joint i's axis, joint i+1's origin is the fixed part of DH row i.
#include "generator/urdf_writer.h"

#include <cmath>
#include <stdexcept>

#include "generator/number_format.h"
#include "model/chain.h"

namespace xmate::robotgen {
namespace {

std::string triple(double x, double y, double z) {
  return formatNumber(x) + " " + formatNumber(y) + " " + formatNumber(z);
}

std::string triple(const Eigen::Vector3d& v) { return triple(v.x(), v.y(), v.z()); }

std::string originElement(const Eigen::Isometry3d& t) {
  return "<origin xyz=\"" + triple(t.translation()) + "\" rpy=\"" + triple(urdfRpy(t.linear())) + "\"/>";
}

std::string kukaHeader(const model::RobotSpec& spec) {
  return "<?xml version=\"1.0\"?>\n"
         "<!-- SPDX-License-Identifier: Apache-2.0\n"
         "     GENERATED FILE, DO NOT EDIT BY HAND. Written by rci-robotgen (resources/generator) from\n"
         "     core/src/model/robot_spec.cpp; change those and build the target regenerate-robots\n"
         "     (docs/robot_descriptions.md).\n"
         "     " + std::string(spec.display_name) + " (KUKA): joint placements from its DH table (docs/robot_models.md),\n"
         "     the geometry of KUKA's published dimensions. Joint values are the controller's A1..A6: A1, A4\n"
         "     and A6 turn about -z of their frames. Position limits (rad) and velocities (rad/s) from KUKA's\n"
         "     data sheet; efforts (Nm) are ESTIMATES. Frames: link i sits on joint i's axis; base_link is\n"
         "     the robot base frame. ESTIMATES: every mass, centre of mass and inertia below is an estimate\n"
         "     (see the comment in each link and docs/robot_models.md, \"Link masses\"). -->\n";
}

std::string header(const model::RobotSpec& spec) {
  if (spec.family == model::RobotFamily::kKuka) return kukaHeader(spec);
  return "<?xml version=\"1.0\"?>\n"
         "<!-- SPDX-License-Identifier: Apache-2.0\n"
         "     GENERATED FILE, DO NOT EDIT BY HAND. Written by rci-robotgen (resources/generator) from\n"
         "     core/src/model/robot_spec.cpp; change those and build the target regenerate-robots\n"
         "     (docs/robot_descriptions.md).\n"
         "     " + std::string(spec.display_name) + ": joint placements from the DH table of the vendor manual\n"
         "     (docs/robot_models.md), joint limits from its limit tables (position rad, velocity rad/s,\n"
         "     effort Nm). Frames: link i sits on joint i's axis; base_link is the robot base frame.\n"
         "     ESTIMATES: every mass, centre of mass and inertia below is an estimate (see the comment\n"
         "     in each link and docs/robot_descriptions.md). -->\n";
}

// Housing colour: the xMates' white, KUKA's orange.
std::string materials(const model::RobotSpec& spec) {
  const bool kuka = spec.family == model::RobotFamily::kKuka;
  return "  <material name=\"housing\">\n"
         "    <color rgba=\"" + std::string(kuka ? "0.96 0.47 0.05 1" : "0.92 0.93 0.94 1") + "\"/>\n"
         "  </material>\n"
         "  <material name=\"flange\">\n"
         "    <color rgba=\"0.3 0.31 0.33 1\"/>\n"
         "  </material>\n";
}

std::string inertialElement(const MassProperties& m) {
  const Eigen::Matrix3d& i = m.inertia;
  return "    <inertial>\n"
         "      <origin xyz=\"" + triple(m.com) + "\" rpy=\"0 0 0\"/>\n"
         "      <mass value=\"" + formatNumber(m.mass) + "\"/>\n"
         "      <inertia ixx=\"" + formatNumber(i(0, 0)) + "\" ixy=\"" + formatNumber(i(0, 1)) +
         "\" ixz=\"" + formatNumber(i(0, 2)) + "\" iyy=\"" + formatNumber(i(1, 1)) +
         "\" iyz=\"" + formatNumber(i(1, 2)) + "\" izz=\"" + formatNumber(i(2, 2)) + "\"/>\n"
         "    </inertial>\n";
}

std::string geometryElement(const std::string& kind, const UrdfLink& link, bool with_material) {
  std::string s = "    <" + kind + ">\n"
                  "      <origin xyz=\"0 0 0\" rpy=\"0 0 0\"/>\n"
                  "      <geometry>\n"
                  "        <mesh filename=\"" + link.mesh_file + "\"/>\n"
                  "      </geometry>\n";
  if (with_material) s += std::string("      <material name=\"") + (link.flange_colour ? "flange" : "housing") + "\"/>\n";
  return s + "    </" + kind + ">\n";
}

std::string linkElement(const UrdfLink& link) {
  return "  <link name=\"" + link.name + "\">\n"
         "    <!-- ESTIMATE: " + link.estimate_note + " -->\n" +
         inertialElement(link.inertial) + geometryElement("visual", link, true) +
         geometryElement("collision", link, false) + "  </link>\n";
}

std::string revoluteJoint(const model::ChainJoint& j, const std::string& parent, const std::string& child) {
  return "  <joint name=\"" + j.name + "\" type=\"revolute\">\n"
         "    <parent link=\"" + parent + "\"/>\n"
         "    <child link=\"" + child + "\"/>\n"
         "    " + originElement(j.origin) + "\n"
         "    <axis xyz=\"" + triple(j.axis) + "\"/>\n"
         "    <limit lower=\"" + formatNumber(j.lower) + "\" upper=\"" + formatNumber(j.upper) +
         "\" velocity=\"" + formatNumber(j.velocity) + "\" effort=\"" + formatNumber(j.effort) + "\"/>\n"
         "  </joint>\n";
}

std::string flangeJoint(const Eigen::Isometry3d& flange, const std::string& parent) {
  return "  <joint name=\"flange_joint\" type=\"fixed\">\n"
         "    <parent link=\"" + parent + "\"/>\n"
         "    <child link=\"flange\"/>\n"
         "    " + originElement(flange) + "\n"
         "  </joint>\n"
         "  <!-- The tool mounting face: z out of the flange (the DH table's last frame). -->\n"
         "  <link name=\"flange\"/>\n";
}

}  // namespace

Eigen::Vector3d urdfRpy(const Eigen::Matrix3d& r) {
  const double sp = -r(2, 0);
  if (std::abs(sp) >= 1 - 1e-12) {  // pitch = +-90 deg: roll and yaw share an axis, put it all in yaw
    const double pitch = std::copysign(std::acos(-1.0) / 2, sp);
    return {0, pitch, std::atan2(-r(0, 1), r(1, 1))};
  }
  return {std::atan2(r(2, 1), r(2, 2)), std::atan2(sp, std::hypot(r(0, 0), r(1, 0))), std::atan2(r(1, 0), r(0, 0))};
}

std::string robotUrdf(const model::RobotSpec& spec, const std::vector<UrdfLink>& links) {
  if (int(links.size()) != spec.dof + 1)
    throw std::invalid_argument("robotUrdf: expected base_link and " + std::to_string(spec.dof) + " links");
  const model::Chain chain = model::chainFromDh(spec);
  std::string s = header(spec) + "<robot name=\"" + std::string(spec.name) + "\">\n" + materials(spec);
  s += linkElement(links[0]);
  for (int i = 0; i < spec.dof; ++i) {
    s += revoluteJoint(chain.joints[i], links[i].name, links[i + 1].name);
    s += linkElement(links[i + 1]);
  }
  s += flangeJoint(chain.flange, links[spec.dof].name);
  return s + "</robot>\n";
}

}  // namespace xmate::robotgen
