// SPDX-License-Identifier: Apache-2.0
// What colour each link gets beyond its material: amber near a joint limit, red on a collision or
// when the external torque exceeds the joint's collision threshold; and the mouse-pull spring force.
#pragma once

#include <QVector3D>

#include <array>
#include <vector>

namespace rci::ui {

enum class LinkTint { kNone, kNearLimit, kOverload };

inline constexpr double kNearLimitDeg = 5.0;

struct TintInputs {
  int dof = 7;
  std::array<double, 7> q{};                 // rad
  std::array<double, 7> lower{}, upper{};    // rad (hardware, or the tighter soft limits)
  std::array<double, 7> tau_ext{};           // Nm
  std::array<double, 7> thresholds{};        // Nm; 0 = not set (no check)
  bool collision = false;                    // the collision error bit
};

// One tint per moving link (index i: link i+1, driven by joint i+1). A collision tints every link
// red; otherwise a link is red when |tau_ext| of its joint exceeds that joint's threshold, amber
// when its joint is within kNearLimitDeg of a limit.
std::vector<LinkTint> linkTints(const TintInputs& in);

// Spring of the mouse pull: k (N/m) times (pointer - tcp), clamped to max_force (N).
QVector3D springForce(const QVector3D& tcp, const QVector3D& pointer, float k, float max_force);

}  // namespace rci::ui
