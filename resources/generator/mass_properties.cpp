// SPDX-License-Identifier: Apache-2.0
// Volume integrals of solids of revolution, turned into line integrals along the profile
// (Green's theorem in the (r, z) half-plane), and their combination into link inertias.
#include "generator/mass_properties.h"

#include <array>
#include <stdexcept>

namespace xmate::robotgen {
namespace {

constexpr double kPi = 3.14159265358979323846;

// 5-point Gauss-Legendre rule on [-1, 1].
constexpr std::array<double, 5> kNodes{-0.9061798459386640, -0.5384693101056831, 0.0,
                                       0.5384693101056831, 0.9061798459386640};
constexpr std::array<double, 5> kWeights{0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                         0.4786286704993665, 0.2369268850561891};
// Sub-intervals per profile piece: arcs are trigonometric, this makes the rule exact to ~1e-16.
constexpr int kSubIntervals = 16;

// The volume integrals a solid of revolution about z needs, per unit density, about its own origin.
struct AxialMoments {
  double volume = 0;  // integral of dV
  double z1 = 0;      // integral of z dV
  double z2 = 0;      // integral of z^2 dV
  double r2 = 0;      // integral of (x^2 + y^2) dV
};

// For a region of the (r, z) plane turned about z, dV = 2 pi r dr dz. Green's theorem turns
// the area integral of g(r, z) 2 pi r into the boundary integral of G dz with dG/dr = 2 pi r g;
// the axis (r = 0) contributes nothing because every G below vanishes there.
AxialMoments axialMoments(const Profile& profile) {
  AxialMoments m;
  for (const ProfilePiece& piece : profile) {
    for (int k = 0; k < kSubIntervals; ++k) {
      const double t0 = double(k) / kSubIntervals;
      const double half = 0.5 / kSubIntervals;
      for (std::size_t i = 0; i < kNodes.size(); ++i) {
        const double t = t0 + half * (1 + kNodes[i]);
        const Eigen::Vector2d p = piecePoint(piece, t);
        const double w = kWeights[i] * half * pieceTangent(piece, t).y();  // weight * dz/dt
        const double r2 = p.x() * p.x(), z = p.y();
        m.volume += w * kPi * r2;
        m.z1 += w * kPi * r2 * z;
        m.z2 += w * kPi * r2 * z * z;
        m.r2 += w * kPi * r2 * r2 / 2;
      }
    }
  }
  if (!(m.volume > 0))
    throw std::logic_error("mass properties: a solid profile encloses no volume (wrong orientation?)");
  return m;
}

}  // namespace

VolumeMoments volumeMoments(const Solid& solid) {
  const AxialMoments m = axialMoments(solid.profile);
  const double zc = m.z1 / m.volume;
  // Per unit density about the solid's own centroid, in the solid frame.
  const double izz = m.r2;
  const double ixx = m.r2 / 2 + (m.z2 - m.volume * zc * zc);
  const Eigen::Matrix3d local = Eigen::Vector3d(ixx, ixx, izz).asDiagonal();
  const Eigen::Matrix3d r = solid.pose.linear();
  VolumeMoments v;
  v.volume = m.volume;
  v.centroid = solid.pose * Eigen::Vector3d(0, 0, zc);
  v.inertia_per_density = r * local * r.transpose();
  return v;
}

double totalVolume(const std::vector<Solid>& solids) {
  double v = 0;
  for (const Solid& s : solids) v += volumeMoments(s).volume;
  return v;
}

MassProperties distributeMass(const std::vector<Solid>& solids, double mass) {
  if (solids.empty() || !(mass > 0))
    throw std::invalid_argument("distributeMass: needs at least one solid and a positive mass");
  std::vector<VolumeMoments> parts;
  for (const Solid& s : solids) parts.push_back(volumeMoments(s));
  double volume = 0;
  for (const VolumeMoments& p : parts) volume += p.volume;
  const double density = mass / volume;

  MassProperties out;
  out.mass = mass;
  for (const VolumeMoments& p : parts) out.com += density * p.volume * p.centroid;
  out.com /= mass;
  for (const VolumeMoments& p : parts) {
    const Eigen::Vector3d d = p.centroid - out.com;
    const double m = density * p.volume;
    out.inertia += density * p.inertia_per_density +
                   m * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  }
  return out;
}

}  // namespace xmate::robotgen
