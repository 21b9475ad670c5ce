// SPDX-License-Identifier: Apache-2.0
// Numbers transcribed from the vendor's xCore RCI user manual V2.0 (sections 2.3.1, 2.4.4, 2.4.5) and
// public link-mass estimates for the xMates; KUKA's published geometry, ranges and speeds with our
// estimates for the rest (docs/robot_models.md lists them all and says which are estimates). Degrees
// and millimetres are converted here, once.
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

// KUKA: degrees (per second) to radians; accelerations and jerks are not published and are chosen
// (docs/robot_models.md, "KUKA: what is chosen"): full speed in 1/3 s, full acceleration in 50 ms,
// full torque in 50 ms.
constexpr std::array<double, 7> degrees(std::array<double, 7> v) {
  for (double& x : v) x = deg(x);
  return v;
}
constexpr std::array<double, 7> times(std::array<double, 7> v, double k) {
  for (double& x : v) x *= k;
  return v;
}
constexpr double kKukaAccelPerSpeed = 3.0;   // 1/s
constexpr double kKukaJerkPerAccel = 20.0;   // 1/s
constexpr double kKukaTauRatePerTau = 20.0;  // 1/s
constexpr std::array<double, 7> kNoSetting{0, 0, 0, 0, 0, 0, 0};

// KR 6 R900 sixx (Agilus): ranges and speeds from KUKA's data sheet, geometry of the public
// ROS-Industrial description, in DH form (docs/robot_models.md, "DH parameters").
constexpr std::array<double, 7> kKr6QMax = degrees({170, 45, 156, 185, 120, 350, 0});
constexpr std::array<double, 7> kKr6QMin = degrees({-170, -190, -120, -185, -120, -350, 0});
constexpr std::array<double, 7> kKr6DqMax = degrees({360, 300, 360, 381, 388, 615, 0});
constexpr std::array<double, 7> kKr6DdqMax = times(kKr6DqMax, kKukaAccelPerSpeed);
constexpr std::array<double, 7> kKr6JerkMax = times(kKr6DdqMax, kKukaJerkPerAccel);
constexpr std::array<double, 7> kKr6TauMax{345, 485, 150, 20, 20, 5, 0};  // estimates
constexpr std::array<double, 7> kKr6DtauMax = times(kKr6TauMax, kKukaTauRatePerTau);

// KR 16-2: the same structure, larger.
constexpr std::array<double, 7> kKr16QMax = degrees({185, 35, 154, 350, 130, 350, 0});
constexpr std::array<double, 7> kKr16QMin = degrees({-185, -155, -130, -350, -130, -350, 0});
constexpr std::array<double, 7> kKr16DqMax = degrees({156, 156, 156, 330, 330, 615, 0});
constexpr std::array<double, 7> kKr16DdqMax = times(kKr16DqMax, kKukaAccelPerSpeed);
constexpr std::array<double, 7> kKr16JerkMax = times(kKr16DdqMax, kKukaJerkPerAccel);
constexpr std::array<double, 7> kKr16TauMax{1560, 2090, 540, 70, 70, 10, 0};  // estimates
constexpr std::array<double, 7> kKr16DtauMax = times(kKr16TauMax, kKukaTauRatePerTau);

const std::array<RobotSpec, 6> kSpecs{{
    {XMATE3_PRO, "xmate3_pro", "xMate Pro 3", 7,
     {{{0, -h, mm(341.5), 0}, {0, h, 0, 0}, {0, -h, mm(394.0), 0}, {0, h, 0, 0},
       {0, -h, mm(366), 0}, {0, h, 0, 0}, {0, 0, mm(250.3), 0}}},
     kProQMax, kProQMin, kProDqMax, kProDdqMax, kProJerkMax, kProTauMax, kProDtauMax,
     kProCollisionMax, kProStiffnessMax,
     {5.483, 3.122, 3.660, 3.382, 2.732, 2.219, 2.181, 0.941}, RobotFamily::kXmate, 3},
    {XMATE7_PRO, "xmate7_pro", "xMate Pro 7", 7,
     {{{0, -h, mm(404.0), 0}, {0, h, 0, 0}, {0, -h, mm(437.5), 0}, {0, h, 0, 0},
       {0, -h, mm(412.5), 0}, {0, h, 0, 0}, {0, 0, mm(275.5), 0}}},
     kProQMax, kProQMin, kProDqMax, kProDdqMax, kProJerkMax, kProTauMax, kProDtauMax,
     kProCollisionMax, kProStiffnessMax,
     {0, 5.962, 5.403, 3.957, 2.912, 2.471, 2.161, 1.268}, RobotFamily::kXmate, 7},
    {XMATE3, "xmate3", "xMate 3", 6,
     {{{0, -h, mm(341.5), 0}, {mm(394), 0, 0, 0}, {0, h, 0, 0}, {0, -h, mm(366), 0},
       {0, h, 0, 0}, {0, 0, mm(250.3), 0}, {0, 0, 0, 0}}},
     kSixQMax, kSixQMin, kSixDqMax, kSixDdqMax, kSixJerkMax, kSixTauMax, kSixDtauMax,
     kSixCollisionMax, kSixStiffnessMax,
     {0, 3.441, 5.024, 2.440, 2.440, 2.423, 1.230, 0}, RobotFamily::kXmate, 3},
    {XMATE7, "xmate7", "xMate 7", 6,
     {{{0, -h, mm(404), 0}, {mm(437.5), 0, 0, 0}, {0, h, 0, 0}, {0, -h, mm(412.5), 0},
       {0, h, 0, 0}, {0, 0, mm(275.5), 0}, {0, 0, 0, 0}}},
     kSixQMax, kSixQMin, kSixDqMax, kSixDdqMax, kSixJerkMax, kSixTauMax, kSixDtauMax,
     kSixCollisionMax, kSixStiffnessMax,
     {0, 5.179, 6.069, 2.990, 2.501, 2.192, 0.961, 0}, RobotFamily::kXmate, 7},
    // KUKA: A1, A4 and A6 turn about -z of their DH frame (axis_sign -1). The elbow offset a3 is
    // signed: the A4 axis runs 35 mm above the A3 axis on the KR 6, 35 mm below it on the KR 16.
    // theta6 = pi turns the flange frame so that x points along the flange as KUKA's does.
    {XMATE7_PRO /* filler, see RobotSpec::type */, "kr6_r900_sixx", "KR 6 R900 sixx", 6,
     {{{mm(25), -h, mm(400), 0, -1}, {mm(455), 0, 0, 0, 1}, {mm(35), -h, 0, -h, 1}, {0, h, mm(420), 0, -1},
       {0, -h, 0, 0, 1}, {0, 0, mm(80), kPi, -1}, {0, 0, 0, 0}}},
     kKr6QMax, kKr6QMin, kKr6DqMax, kKr6DdqMax, kKr6JerkMax, kKr6TauMax, kKr6DtauMax, kNoSetting, kNoSetting,
     {9, 14, 10, 8, 6, 3.5, 1.5, 0}, RobotFamily::kKuka, 6},
    {XMATE7_PRO /* filler, see RobotSpec::type */, "kr16_2", "KR 16-2", 6,
     {{{mm(260), -h, mm(675), 0, -1}, {mm(680), 0, 0, 0, 1}, {mm(-35), -h, 0, -h, 1}, {0, h, mm(670), 0, -1},
       {0, -h, 0, 0, 1}, {0, 0, mm(158), kPi, -1}, {0, 0, 0, 0}}},
     kKr16QMax, kKr16QMin, kKr16DqMax, kKr16DdqMax, kKr16JerkMax, kKr16TauMax, kKr16DtauMax, kNoSetting, kNoSetting,
     {45, 75, 45, 40, 18, 8, 4, 0}, RobotFamily::kKuka, 16},
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
    if (s.family == RobotFamily::kXmate && s.type == type) return s;
  return kSpecs[1];  // unreachable for valid enum values
}

const RobotSpec* findRobotSpec(std::string_view name) {
  for (const auto& s : kSpecs)
    if (s.name == name) return &s;
  return nullptr;
}

const RobotSpec* findXmateSpec(std::string_view name) {
  const RobotSpec* spec = findRobotSpec(name);
  return spec && spec->family == RobotFamily::kXmate ? spec : nullptr;
}

const std::array<XmateType, 4>& allRobotTypes() { return kAllTypes; }

std::span<const RobotSpec> allRobotSpecs() { return kSpecs; }

std::optional<XmateType> xmateType(const RobotSpec& spec) {
  if (spec.family != RobotFamily::kXmate) return std::nullopt;
  return spec.type;
}

}  // namespace xmate::model
