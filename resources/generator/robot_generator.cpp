// SPDX-License-Identifier: Apache-2.0
// Assembles one model's description (see robot_generator.h): shells, meshes, mass estimates
// (published link masses spread over the shell; an unpublished base mass from the mean density of
// the published links), URDF text; then writes the files.
#include "generator/robot_generator.h"

#include <cmath>
#include <fstream>
#include <stdexcept>

#include "generator/number_format.h"
#include "generator/stl_io.h"

namespace xmate::robotgen {
namespace {

// Estimated quantities are written with this many significant digits: far more than they are
// worth, and it keeps the files stable against last-bit differences between maths libraries.
constexpr int kEstimateDigits = 6;

double estimate(double x) { return roundToSignificant(x, kEstimateDigits); }

// Rounds centre of mass and inertia for writing (the mass is kept); integration noise around zero
// (every shell is symmetric about its link's axes) becomes exactly 0.
MassProperties rounded(const MassProperties& m) {
  MassProperties out;
  out.mass = m.mass;
  for (int i = 0; i < 3; ++i) out.com[i] = std::abs(m.com[i]) < 1e-10 ? 0.0 : estimate(m.com[i]);
  const double scale = m.inertia.diagonal().maxCoeff();
  for (int r = 0; r < 3; ++r) {
    for (int c = r; c < 3; ++c) {
      const double v = 0.5 * (m.inertia(r, c) + m.inertia(c, r));
      out.inertia(r, c) = out.inertia(c, r) = std::abs(v) < 1e-9 * scale ? 0.0 : estimate(v);
    }
  }
  return out;
}

std::string solidList(const LinkShell& shell) {
  std::string s;
  for (const Solid& solid : shell.solids) s += (s.empty() ? "" : ", ") + solid.what;
  return s;
}

std::string estimateNote(const model::RobotSpec& spec, const GeneratedLink& link, double volume, double mean_density) {
  std::string mass_part;
  if (link.mass_published && spec.family == model::RobotFamily::kKuka) {
    mass_part = "mass " + formatNumber(link.urdf.inertial.mass) +
                " kg is our estimate listed in docs/robot_models.md, \"Link masses\" (KUKA publishes\n"
                "         only the robot's total weight).";
  } else if (link.mass_published) {
    mass_part = "mass " + formatNumber(link.urdf.inertial.mass) +
                " kg is the public estimate listed in docs/robot_models.md, \"Link masses\".";
  } else {
    mass_part = "mass not published: " + formatNumber(link.urdf.inertial.mass) + " kg = shell volume " +
                formatNumber(estimate(volume)) + " m^3 times " + formatNumber(estimate(mean_density)) +
                " kg/m^3,\n         the mean density of this model's published links.";
  }
  return mass_part + "\n         Centre of mass and inertia: that mass spread uniformly (" +
         formatNumber(estimate(link.density)) + " kg/m^3) over the shell solids\n         (" +
         solidList(link.shell) + "), overlaps counted twice, parallel-axis theorem.";
}

// Mean density of the links whose mass is published (links 1..dof), kg/m^3.
double meanPublishedDensity(const model::RobotSpec& spec, const std::vector<LinkShell>& shells) {
  double mass = 0, volume = 0;
  for (int i = 1; i <= spec.dof; ++i) {
    if (spec.link_mass[i] <= 0) continue;
    mass += spec.link_mass[i];
    volume += totalVolume(shells[i].solids);
  }
  if (!(volume > 0))
    throw std::invalid_argument("rci-robotgen: " + std::string(spec.name) + " has no published link mass to derive "
                                "a density from; add masses to robot_spec.cpp");
  return mass / volume;
}

GeneratedLink generateLink(const model::RobotSpec& spec, LinkShell shell, double published_mass,
                           double fallback_density) {
  GeneratedLink link;
  link.shell = std::move(shell);
  link.mesh = shellMesh(link.shell.solids);
  const double volume = totalVolume(link.shell.solids);
  link.mass_published = published_mass > 0;
  const double mass = link.mass_published ? published_mass : estimate(fallback_density * volume);
  link.density = mass / volume;
  link.urdf.name = link.shell.name;
  link.urdf.inertial = rounded(distributeMass(link.shell.solids, mass));
  link.urdf.mesh_file = (std::filesystem::path("..") / ".." / meshRelativePath(spec.name, link.shell.name)).generic_string();
  link.urdf.estimate_note = estimateNote(spec, link, volume, fallback_density);
  return link;
}

void writeFile(const std::filesystem::path& file, const std::string& bytes) {
  std::filesystem::create_directories(file.parent_path());
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(bytes.size()));
  if (!out) throw std::runtime_error("rci-robotgen: could not write " + file.string() + "; check the folder is writable");
}

}  // namespace

GeneratedRobot generateRobot(const model::RobotSpec& spec) {
  const std::vector<LinkShell> shells = armShells(spec);
  const double fallback_density = meanPublishedDensity(spec, shells);
  GeneratedRobot robot;
  robot.name = std::string(spec.name);
  for (int i = 0; i <= spec.dof; ++i) robot.links.push_back(generateLink(spec, shells[i], spec.link_mass[i], fallback_density));
  robot.links.back().urdf.flange_colour = true;

  std::vector<UrdfLink> urdf_links;
  for (const GeneratedLink& l : robot.links) urdf_links.push_back(l.urdf);
  robot.urdf = robotUrdf(spec, urdf_links);
  return robot;
}

std::filesystem::path urdfRelativePath(std::string_view model_name) {
  return std::filesystem::path("resources") / "robots" / (std::string(model_name) + ".urdf");
}

std::filesystem::path meshRelativePath(std::string_view model_name, std::string_view link_name) {
  return std::filesystem::path("meshes") / std::string(model_name) / (std::string(link_name) + ".stl");
}

std::vector<std::filesystem::path> writeRobot(const GeneratedRobot& robot, const std::filesystem::path& data_root) {
  std::vector<std::filesystem::path> written;
  const auto urdf_file = data_root / urdfRelativePath(robot.name);
  writeFile(urdf_file, robot.urdf);
  written.push_back(urdf_file);
  for (const GeneratedLink& link : robot.links) {
    const auto mesh_file = data_root / meshRelativePath(robot.name, link.shell.name);
    writeFile(mesh_file, binaryStl(link.mesh, "rci-robotgen " + robot.name + " " + link.shell.name + ", binary STL, metres"));
    written.push_back(mesh_file);
  }
  return written;
}

}  // namespace xmate::robotgen
