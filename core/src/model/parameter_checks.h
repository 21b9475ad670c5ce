// SPDX-License-Identifier: Apache-2.0
// What the controller accepts for each setting (docs/api.md, "Settings and their ranges"; docs/protocol.md choices):
// one place for the client (which throws std::invalid_argument), the simulator (which answers
// kInvalidArgument) and the GUI's editors (which explain the refusal).
// Every check returns "" when the value is acceptable, else a sentence naming the call, the
// parameter, the index, the value and the allowed range.
#pragma once

#include <array>
#include <string>

#include "model/robot_spec.h"

namespace xmate::model {

// Rated payload in kg (RobotSpec::rated_payload_kg): the number in the model name (xMate 3/7, KR 6, KR 16).
double ratedPayloadKg(const RobotSpec& spec);

inline constexpr double kFilterMinHz = 1.0, kFilterMaxHz = 1000.0;
inline constexpr double kFilterRecommendedMinHz = 10.0, kFilterRecommendedMaxHz = 100.0;
inline constexpr double kLoadCenterMaxM = 0.5;
inline constexpr double kLoadInertiaMaxKgM2 = 2.0;  // per diagonal moment: 7 kg as a 1.8 m rod
inline constexpr double kToolOffsetMaxM = 0.5;
inline constexpr double kSafetyBoxMaxSizeM = 5.0;
inline constexpr double kDesiredForceMaxN = 60.0, kDesiredTorqueMaxNm = 10.0;
inline constexpr double kHomogeneousTolerance = 1e-6;

std::string checkHomogeneous(const char* call, const char* parameter, const std::array<double, 16>& pose);
std::string checkCollisionThresholds(const RobotSpec& spec, const std::array<double, 7>& thresholds);
std::string checkJointImpedance(const RobotSpec& spec, const std::array<double, 7>& stiffness);
std::string checkCartesianImpedance(const std::array<double, 6>& stiffness);
std::string checkFilters(double joint_hz, double cartesian_hz, double torque_hz);
std::string checkLoad(const RobotSpec& spec, double mass, const std::array<double, 3>& center,
                      const std::array<double, 9>& inertia);
std::string checkToolFrame(const std::array<double, 16>& flange_to_tool);
std::string checkCartesianLimit(const std::array<double, 3>& size, const std::array<double, 16>& frame);
// Soft limits in degrees, as setJointLimit takes them.
std::string checkSoftLimits(const RobotSpec& spec, const std::array<double, 7>& upper_deg,
                            const std::array<double, 7>& lower_deg);
std::string checkDesiredWrench(const std::array<double, 6>& wrench);
// API numbering: fc_type 1 world, 2 tool, 3 path.
std::string checkForceFrame(const std::array<double, 16>& frame, int fc_type);
// API numbering: space 1 joint, 2 Cartesian; type 1 translation, 2 rotation, 3 free.
std::string checkDrag(int drag_space, int drag_type);
std::string checkMotorPower(int state);

}  // namespace xmate::model
