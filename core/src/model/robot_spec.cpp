// SPDX-License-Identifier: Apache-2.0
// Numbers transcribed from the vendor's xCore RCI user manual V2.0 (sections 2.3.1, 2.4.4, 2.4.5) and
// public link-mass estimates; docs/robot_models.md lists them all. Degrees and millimetres are converted
// here, once.
#include "model/robot_spec.h"

#include <cmath>

namespace xmate::model {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double deg(double d) { return d * kPi / 180.0; }
constexpr double mm(double v) { return v / 1000.0; }

// Limits shared by the two 7-axis models (xMatePro3, xMatePro7).
constexpr std::array<double, 7> kProQMax{deg(170), deg(120), deg(170), deg(120), deg(170), deg(120), deg(360)};
constexpr std::array<double, 7> kProQMin{-deg(170), -deg(120), -deg(170), -deg(120), -deg(170), -deg(120), -deg(360)};
constexpr std::array<double, 7> kProDqMax{2.175, 2.175, 2.175, 2.175, 2.610, 2.610, 2.610};
constexpr std::array<double, 7> kProDdqMax{15, 7.5, 10, 10, 15, 15, 20};
constexpr std::array<double, 7> kProJerkMax{5000, 3500, 5000, 5000, 7500, 7500, 7500};
constexpr std::array<double, 7> kProTauMax{85, 85, 85, 85, 36, 36, 36};
constexpr std::array<double, 7> kProDtauMax{1500, 1500, 1500, 1500, 1000, 1000, 1000};
constexpr std::array<double, 7> kProCollisionMax{75, 75, 60, 45, 30, 30, 20};
constexpr std::array<double, 7> kProStiffnessMax{3000, 3000, 3000, 3000, 300, 300, 300};

// Limits shared by the two 6-axis models (xMate3, xMate7; the manual names their joints
// J1 J2 J4 J5 J6 J7 -- here they are simply joints 1..6).
constexpr std::array<double, 7> kSixQMax{deg(170), deg(120), deg(120), deg(170), deg(120), deg(360), 0};
constexpr std::array<double, 7> kSixQMin{-deg(170), -deg(120), -deg(120), -deg(170), -deg(120), -deg(360), 0};
constexpr std::array<double, 7> kSixDqMax{2.175, 2.175, 2.175, 2.610, 2.610, 2.610, 0};
constexpr std::array<double, 7> kSixDdqMax{15, 7.5, 10, 15, 15, 20, 0};
constexpr std::array<double, 7> kSixJerkMax{5000, 3500, 5000, 7500, 7500, 7500, 0};
constexpr std::array<double, 7> kSixTauMax{85, 85, 85, 36, 36, 36, 0};
constexpr std::array<double, 7> kSixDtauMax{1500, 1500, 1500, 1000, 1000, 1000, 0};
constexpr std::array<double, 7> kSixCollisionMax{75, 75, 45, 30, 30, 20, 0};
constexpr std::array<double, 7> kSixStiffnessMax{3000, 3000, 3000, 300, 300, 300, 0};

constexpr double h = kPi / 2;

const std::array<RobotSpec, 4> kSpecs{{
    {XMATE3_PRO, "xmate3_pro", "xMate Pro 3", 7,
     {{{0, -h, mm(341.5), 0}, {0, h, 0, 0}, {0, -h, mm(394.0), 0}, {0, h, 0, 0},
       {0, -h, mm(366), 0}, {0, h, 0, 0}, {0, 0, mm(250.3), 0}}},
     kProQMax, kProQMin, kProDqMax, kProDdqMax, kProJerkMax, kProTauMax, kProDtauMax,
     kProCollisionMax, kProStiffnessMax,
     {5.483, 3.122, 3.660, 3.382, 2.732, 2.219, 2.181, 0.941}},
    {XMATE7_PRO, "xmate7_pro", "xMate Pro 7", 7,
     {{{0, -h, mm(404.0), 0}, {0, h, 0, 0}, {0, -h, mm(437.5), 0}, {0, h, 0, 0},
       {0, -h, mm(412.5), 0}, {0, h, 0, 0}, {0, 0, mm(275.5), 0}}},
     kProQMax, kProQMin, kProDqMax, kProDdqMax, kProJerkMax, kProTauMax, kProDtauMax,
     kProCollisionMax, kProStiffnessMax,
     {0, 5.962, 5.403, 3.957, 2.912, 2.471, 2.161, 1.268}},
    {XMATE3, "xmate3", "xMate 3", 6,
     {{{0, -h, mm(341.5), 0}, {mm(394), 0, 0, 0}, {0, h, 0, 0}, {0, -h, mm(366), 0},
       {0, h, 0, 0}, {0, 0, mm(250.3), 0}, {0, 0, 0, 0}}},
     kSixQMax, kSixQMin, kSixDqMax, kSixDdqMax, kSixJerkMax, kSixTauMax, kSixDtauMax,
     kSixCollisionMax, kSixStiffnessMax,
     {0, 3.441, 5.024, 2.440, 2.440, 2.423, 1.230, 0}},
    {XMATE7, "xmate7", "xMate 7", 6,
     {{{0, -h, mm(404), 0}, {mm(437.5), 0, 0, 0}, {0, h, 0, 0}, {0, -h, mm(412.5), 0},
       {0, h, 0, 0}, {0, 0, mm(275.5), 0}, {0, 0, 0, 0}}},
     kSixQMax, kSixQMin, kSixDqMax, kSixDdqMax, kSixJerkMax, kSixTauMax, kSixDtauMax,
     kSixCollisionMax, kSixStiffnessMax,
     {0, 5.179, 6.069, 2.990, 2.501, 2.192, 0.961, 0}},
}};

// Planner: the manual copy's values (1.0 m/s, 10 m/s^2, 5000 m/s^3; 2.5 rad/s, 10 rad/s^2,
// 5000 rad/s^3); arm angle 180 deg/s, 10 rad/s^2, 5000 rad/s^3 (docs/robot_models.md, "Cartesian limits").
constexpr CartesianLimits kPlannerCartesian{1.0, 10.0, 5000.0, 2.5, 10.0, 5000.0, kPi, 10.0, 5000.0};
// Controller: the vendor rate limiter's constants (docs/robot_models.md, "Cartesian limits").
constexpr CartesianLimits kControllerCartesian{1.5, 10.0, 5000.0, 2.5, 25.0, 12500.0, kPi, 10.0, 5000.0};

constexpr std::array<XmateType, 4> kAllTypes{XMATE3_PRO, XMATE7_PRO, XMATE3, XMATE7};

}  // namespace

const CartesianLimits& plannerCartesianLimits() { return kPlannerCartesian; }
const CartesianLimits& controllerCartesianLimits() { return kControllerCartesian; }

const RobotSpec& robotSpec(XmateType type) {
  for (const auto& s : kSpecs)
    if (s.type == type) return s;
  return kSpecs[1];  // unreachable for valid enum values
}

const RobotSpec* findRobotSpec(std::string_view name) {
  for (const auto& s : kSpecs)
    if (s.name == name) return &s;
  return nullptr;
}

const std::array<XmateType, 4>& allRobotTypes() { return kAllTypes; }

}  // namespace xmate::model
