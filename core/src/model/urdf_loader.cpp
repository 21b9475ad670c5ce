// SPDX-License-Identifier: Apache-2.0
// URDF -> Chain with urdfdom (see urdf_loader.h): checks the file is one serial chain of 6 or 7
// revolute joints ending in a fixed joint to "flange", and converts urdfdom's poses, limits,
// inertials and meshes into Eigen types with absolute mesh paths.
#include "model/urdf_loader.h"

#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <system_error>

#include <tinyxml.h>
#include <urdf_parser/urdf_parser.h>

#include "model/resource_locator.h"

namespace xmate::model {
namespace {

constexpr int kMinJoints = 6;
constexpr int kMaxJoints = 7;

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& what) {
  throw std::runtime_error("Robot description " + file.string() + ": " + what);
}

std::string readText(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    throw std::runtime_error("Robot description not found: " + file.string() +
                             ". Check the path, or set RCI_DATA_DIR to the folder holding resources/robots/.");
  std::ifstream in(file, std::ios::binary);
  if (!in) fail(file, "the file exists but cannot be read; check its permissions.");
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// urdfdom only prints XML errors to the console; parse once with TinyXML (the parser urdfdom
// itself uses) so the exception can say where the XML is broken.
void checkWellFormed(const std::filesystem::path& file, const std::string& text) {
  TiXmlDocument doc;
  doc.Parse(text.c_str());
  if (doc.Error())
    fail(file, "malformed XML at line " + std::to_string(doc.ErrorRow()) + ", column " +
                   std::to_string(doc.ErrorCol()) + ": " + doc.ErrorDesc() +
                   ". Fix the file, or regenerate the shipped descriptions with rci-robotgen.");
}

Eigen::Isometry3d toIsometry(const urdf::Pose& pose) {
  double x = 0, y = 0, z = 0, w = 1;
  pose.rotation.getQuaternion(x, y, z, w);
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = Eigen::Quaterniond(w, x, y, z).normalized().toRotationMatrix();  // Eigen takes w first
  t.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  return t;
}

Eigen::Vector3d toVector(const urdf::Vector3& v) { return {v.x, v.y, v.z}; }

std::string typeName(int type) {
  switch (type) {
    case urdf::Joint::REVOLUTE: return "revolute";
    case urdf::Joint::CONTINUOUS: return "continuous";
    case urdf::Joint::PRISMATIC: return "prismatic";
    case urdf::Joint::FLOATING: return "floating";
    case urdf::Joint::PLANAR: return "planar";
    case urdf::Joint::FIXED: return "fixed";
    default: return "unknown";
  }
}

// package://<pkg>/<rest> against the data root, file:// stripped, relative against the URDF's folder.
std::string resolveMeshPath(const std::filesystem::path& urdf_file, const std::string& name) {
  const std::string package = "package://";
  const std::string file_scheme = "file://";
  std::filesystem::path p;
  if (name.rfind(package, 0) == 0) {
    const std::string rest = name.substr(package.size());
    const auto slash = rest.find('/');
    p = dataDirectory() / (slash == std::string::npos ? rest : rest.substr(slash + 1));
  } else if (name.rfind(file_scheme, 0) == 0) {
    p = name.substr(file_scheme.size());
  } else {
    p = std::filesystem::path(name);
    if (p.is_relative()) p = urdf_file.parent_path() / p;
  }
  return std::filesystem::absolute(p).lexically_normal().string();
}

ChainLink toChainLink(const std::filesystem::path& file, const urdf::Link& link) {
  ChainLink out;
  out.name = link.name;
  if (link.inertial) {
    const urdf::Inertial& in = *link.inertial;
    const Eigen::Isometry3d frame = toIsometry(in.origin);
    Eigen::Matrix3d inertia;
    inertia << in.ixx, in.ixy, in.ixz,
               in.ixy, in.iyy, in.iyz,
               in.ixz, in.iyz, in.izz;
    out.mass = in.mass;
    out.com = frame.translation();
    // The URDF gives the inertia in the inertial origin's axes; the Chain wants link axes.
    out.inertia = frame.linear() * inertia * frame.linear().transpose();
  }
  for (const auto& visual : link.visual_array) {
    if (!visual || !visual->geometry || visual->geometry->type != urdf::Geometry::MESH) continue;
    const auto& mesh = static_cast<const urdf::Mesh&>(*visual->geometry);
    out.mesh = resolveMeshPath(file, mesh.filename);
    out.mesh_scale = toVector(mesh.scale);
    out.visual_origin = toIsometry(visual->origin);
    break;
  }
  return out;
}

ChainJoint toChainJoint(const std::filesystem::path& file, const urdf::Joint& joint) {
  ChainJoint out;
  out.name = joint.name;
  out.origin = toIsometry(joint.parent_to_joint_origin_transform);
  const Eigen::Vector3d axis = toVector(joint.axis);
  if (!(axis.norm() > 0)) fail(file, "joint \"" + joint.name + "\" has a zero axis; give it <axis xyz=\"0 0 1\"/>.");
  out.axis = axis.normalized();
  constexpr double inf = std::numeric_limits<double>::infinity();
  const bool bounded = joint.type == urdf::Joint::REVOLUTE;
  out.lower = bounded && joint.limits ? joint.limits->lower : -inf;
  out.upper = bounded && joint.limits ? joint.limits->upper : inf;
  out.velocity = joint.limits && joint.limits->velocity > 0 ? joint.limits->velocity : inf;
  out.effort = joint.limits && joint.limits->effort > 0 ? joint.limits->effort : inf;
  return out;
}

// The one joint leaving `link`; throws when the tree branches there, nullptr at a leaf.
const urdf::Joint* onlyChildJoint(const std::filesystem::path& file, const urdf::Link& link) {
  if (link.child_joints.size() > 1)
    fail(file, "the kinematic tree branches at link \"" + link.name + "\" (joints \"" + link.child_joints[0]->name +
                   "\" and \"" + link.child_joints[1]->name + "\" both leave it); RCI models must be one serial "
                   "chain from the base to the flange.");
  return link.child_joints.empty() ? nullptr : link.child_joints.front().get();
}

const urdf::Link& childLink(const std::filesystem::path& file, const urdf::ModelInterface& model,
                            const urdf::Joint& joint) {
  const auto link = model.getLink(joint.child_link_name);
  if (!link) fail(file, "joint \"" + joint.name + "\" names a child link \"" + joint.child_link_name + "\" that does not exist.");
  return *link;
}

Chain walkChain(const std::filesystem::path& file, const urdf::ModelInterface& model) {
  const auto root = model.getRoot();
  if (!root) fail(file, "the URDF has no root link.");
  Chain chain;
  chain.name = model.getName();
  chain.base = toChainLink(file, *root);
  const urdf::Link* link = root.get();
  for (;;) {
    const urdf::Joint* joint = onlyChildJoint(file, *link);
    if (!joint)
      fail(file, "no flange: the chain ends at link \"" + link->name + "\" after " + std::to_string(chain.dof) +
                     " joints; it must end with a fixed joint to a link named \"flange\".");
    if (joint->type == urdf::Joint::FIXED) {
      if (joint->child_link_name != "flange")
        fail(file, "fixed joint \"" + joint->name + "\" leads to link \"" + joint->child_link_name +
                       "\"; the only fixed joint allowed is the last one, to a link named \"flange\".");
      chain.flange = toIsometry(joint->parent_to_joint_origin_transform);
      break;
    }
    if (joint->type != urdf::Joint::REVOLUTE && joint->type != urdf::Joint::CONTINUOUS)
      fail(file, "joint \"" + joint->name + "\" is " + typeName(joint->type) +
                     "; RCI models take only revolute (or continuous) joints before the fixed flange joint.");
    if (chain.dof == kMaxJoints)
      fail(file, "more than " + std::to_string(kMaxJoints) + " revolute joints before the flange; RCI models have 6 or 7.");
    link = &childLink(file, model, *joint);
    chain.joints[chain.dof] = toChainJoint(file, *joint);
    chain.links[chain.dof] = toChainLink(file, *link);
    ++chain.dof;
  }
  if (chain.dof < kMinJoints)
    fail(file, "only " + std::to_string(chain.dof) + " revolute joints before the flange; RCI models have 6 or 7.");
  return chain;
}

}  // namespace

Chain loadChain(const std::filesystem::path& urdf_file) {
  const std::string text = readText(urdf_file);
  checkWellFormed(urdf_file, text);
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(text);
  if (!model)
    fail(urdf_file, "not a valid URDF (urdfdom rejected it and printed the reason on stderr): check that it has a "
                    "<robot> element, that every link and joint is named, that joints name existing parent and "
                    "child links, that revolute joints have <limit>, and that there is exactly one root link.");
  return walkChain(urdf_file, *model);
}

Chain loadRobotChain(const RobotSpec& spec) {
  const std::filesystem::path file = robotDescriptionPath(spec);
  Chain chain = loadChain(file);
  if (chain.dof != spec.dof)
    fail(file, "it has " + std::to_string(chain.dof) + " joints but the " + std::string(spec.display_name) + " has " +
                   std::to_string(spec.dof) + "; regenerate it with rci-robotgen.");
  return chain;
}

}  // namespace xmate::model
