// SPDX-License-Identifier: Apache-2.0
// Shell layout rules (see arm_layout.h). Joint placements come from model::chainFromDh, so the
// shells follow the same frames the URDF joints use. Sizes are in units of the housing radius.
#include "generator/arm_layout.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "model/chain.h"

namespace xmate::robotgen {
namespace {

// Shoulder housing radius as a fraction of the reach (sum of the DH lengths): the xMate Pro 3
// gets a 135 mm wide shoulder, the Pro 7 a 153 mm one, in line with cobots of that size.
constexpr double kRadiusPerReach = 0.05;
constexpr double kTaperPerJoint = 0.02;       // each joint 2 % slimmer than the one before
// Housings scale with the cube root of the joint torque, but no joint is slimmer than this share of
// joint 1's (a KUKA wrist needs far less torque than its base; the xMates' ratios are all above).
constexpr double kMinTorqueScale = 0.6;
constexpr double kTubeRatio = 0.88;           // tube radius / smaller neighbouring housing radius
constexpr double kFilletRatio = 0.2;          // housing rim fillet / housing radius
constexpr double kPitchHousingLength = 2.0;   // across a joint whose link leaves sideways
constexpr double kRollHousingStart = 0.1;     // a joint whose link runs along its axis: the housing
constexpr double kRollHousingLength = 1.8;    // starts just past the joint centre, reaches forward
constexpr double kPedestalRadius = 1.35;      // pedestal under joint 1, in joint 1 radii
constexpr double kPedestalHeight = 0.35;
// The last link is the dark flange part: a collar of kCollarLength (plus kCollarOverlap hidden in
// the last joint's housing) ending in the flange disc; all in last-joint radii.
constexpr double kCollarRadius = 0.85;
constexpr double kCollarLength = 1.2;
constexpr double kCollarOverlap = 0.5;
constexpr double kCollarFillet = 0.1;         // in collar radii
constexpr double kFlangeRadius = 0.7;
constexpr double kFlangeThickness = 0.2;
constexpr double kTiny = 1e-9;                // m: shorter segments count as zero

double reach(const model::RobotSpec& spec) {
  double sum = 0;
  for (int i = 0; i < spec.dof; ++i) sum += std::abs(spec.dh[i].a) + std::abs(spec.dh[i].d);
  return sum;
}

// From joint j's centre to the next joint's centre (the flange after the last joint), in link j's frame.
Eigen::Vector3d segment(const model::Chain& chain, int j) {
  return j < chain.dof ? chain.joints[j].origin.translation() : chain.flange.translation();
}

// The segment from joint j to the next joint in two legs, as the DH row builds it: first along
// joint j's axis (d), then across it (a). Every xMate row has only one of the two.
Eigen::Vector3d alongLeg(const model::Chain& chain, int j) {
  const Eigen::Vector3d axis = chain.joints[j - 1].axis;
  return segment(chain, j).dot(axis) * axis;
}

// True when link j leaves joint j along its own axis (a "roll" joint such as joint 1).
bool isRollJoint(const model::Chain& chain, int j) { return alongLeg(chain, j).norm() > kTiny; }

// Housing around joint j, in the frame of the link before it (base_link for joint 1).
Solid jointHousing(const model::RobotSpec& spec, const model::Chain& chain, int j) {
  const model::ChainJoint& joint = chain.joints[j - 1];
  const Eigen::Vector3d centre = joint.origin.translation();
  const Eigen::Vector3d axis = joint.origin.linear() * joint.axis;
  const double r = housingRadius(spec, j);
  const double fillet = kFilletRatio * r;
  const std::string what = "joint " + std::to_string(j) + " housing";
  if (isRollJoint(chain, j)) {
    const double forward = segment(chain, j).dot(joint.axis) > 0 ? 1.0 : -1.0;
    const double z0 = kRollHousingStart * r;
    // The last joint's housing runs on up to the flange collar, as on the real wrists.
    const double z1 = j == chain.dof ? segment(chain, j).norm() - kCollarLength * r : z0 + kRollHousingLength * r;
    if (z1 - z0 <= 2 * fillet)
      throw std::invalid_argument("rci-robotgen: joint " + std::to_string(j) + " of " + std::string(spec.name) +
                                  " is too close to the next joint or the flange for its housing");
    return {what, roundedCylinder(r, z0, z1, fillet), axisFrame(centre, forward * axis)};
  }
  const double half = kPitchHousingLength * r / 2;
  return {what, roundedCylinder(r, -half, half, fillet), axisFrame(centre, axis)};
}

// Capsules from joint j's centre to joint j+1's, in link j's frame: one per leg of the segment
// (alongLeg, then across); none for a leg shorter than the joint housing's radius, which the
// housings cover (the KUKA shoulder and elbow offsets).
void addLinkTube(const model::RobotSpec& spec, const model::Chain& chain, int j, std::vector<Solid>& out) {
  const Eigen::Vector3d along = alongLeg(chain, j);
  const Eigen::Vector3d across = segment(chain, j) - along;
  const bool two_legs = along.norm() > kTiny && across.norm() > kTiny;
  const double r = kTubeRatio * std::min(housingRadius(spec, j), housingRadius(spec, j + 1));
  const std::string what = "link " + std::to_string(j) + " tube";
  for (int leg = 0; leg < 2; ++leg) {
    const Eigen::Vector3d s = leg == 0 ? along : across;
    const Eigen::Vector3d from = leg == 0 ? Eigen::Vector3d::Zero() : along;
    if (s.norm() <= kTiny) continue;
    if (s.norm() <= housingRadius(spec, leg == 0 ? j : j + 1)) continue;
    // Along a roll joint's axis the rounded end would poke out behind the joint: start it later.
    const double start = leg == 0 ? r : 0.0;
    if (s.norm() - start <= r)
      throw std::invalid_argument("rci-robotgen: link " + std::to_string(j) + " of " + std::string(spec.name) +
                                  " is too short for its tube; check the DH table or the shell sizes");
    const Eigen::Vector3d dir = s.normalized();
    out.push_back({two_legs ? what + (leg == 0 ? " (along)" : " (across)") : what, capsule(r, s.norm() - start),
                   axisFrame(from + start * dir, dir)});
  }
}

// The last link, the flange part: a collar coming out of the last joint's housing and the flange
// disc, both along the line from the last joint to the flange (the flange's z on every model).
void addFlange(const model::RobotSpec& spec, const model::Chain& chain, std::vector<Solid>& out) {
  const int n = chain.dof;
  const Eigen::Vector3d f = chain.flange.translation();
  const double rn = housingRadius(spec, n);
  const double thickness = kFlangeThickness * rn;
  const double collar_r = kCollarRadius * rn;
  const double start = isRollJoint(chain, n) ? f.norm() - (kCollarLength + kCollarOverlap) * rn : 0.0;
  const double end = f.norm() - thickness;
  if (!(f.norm() > kTiny) || end - start <= 2 * kCollarFillet * collar_r || start < 0)
    throw std::invalid_argument("rci-robotgen: the flange of " + std::string(spec.name) +
                                " is too close to the last joint for the flange shell");
  const Eigen::Isometry3d along = axisFrame(Eigen::Vector3d::Zero(), f);
  out.push_back({"flange collar", roundedCylinder(collar_r, start, end, kCollarFillet * collar_r), along});
  out.push_back({"flange disc", roundedCylinder(kFlangeRadius * rn, end, f.norm(), thickness / 4), along});
}

LinkShell baseShell(const model::RobotSpec& spec, const model::Chain& chain) {
  const double r1 = housingRadius(spec, 1);
  LinkShell base{"base_link", {}};
  base.solids.push_back({"pedestal",
                         roundedCylinder(kPedestalRadius * r1, 0, kPedestalHeight * r1, kFilletRatio * kPedestalHeight * r1),
                         Eigen::Isometry3d::Identity()});
  base.solids.push_back(jointHousing(spec, chain, 1));
  return base;
}

}  // namespace

double housingRadius(const model::RobotSpec& spec, int joint) {
  if (joint < 1 || joint > spec.dof)
    throw std::out_of_range("housingRadius: joint " + std::to_string(joint) + " does not exist");
  const double torque_scale = std::max(kMinTorqueScale, std::cbrt(spec.tau_max[joint - 1] / spec.tau_max[0]));
  return kRadiusPerReach * reach(spec) * torque_scale * (1 - kTaperPerJoint * (joint - 1));
}

std::vector<LinkShell> armShells(const model::RobotSpec& spec) {
  const model::Chain chain = model::chainFromDh(spec);
  std::vector<LinkShell> shells;
  shells.push_back(baseShell(spec, chain));
  for (int j = 1; j <= spec.dof; ++j) {
    LinkShell link{"link" + std::to_string(j), {}};
    if (j < spec.dof) {
      addLinkTube(spec, chain, j, link.solids);
      link.solids.push_back(jointHousing(spec, chain, j + 1));
    } else {
      addFlange(spec, chain, link.solids);
    }
    shells.push_back(std::move(link));
  }
  return shells;
}

}  // namespace xmate::robotgen
