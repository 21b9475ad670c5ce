// SPDX-License-Identifier: Apache-2.0
// What the controller accepts for each setting (docs/api.md, "Settings and their ranges"; docs/protocol.md choices):
// one place for the client (which throws std::invalid_argument), the simulator (which answers
// kInvalidArgument) and the GUI's editors (which explain the refusal).
// Every check returns an empty ParameterProblem when the value is acceptable, else a sentence naming
// the call, the parameter, the index, the value and the allowed range -- and the parameter and index
// as fields, so that an editor marks the refused field without reading the sentence.
#pragma once

#include <array>
#include <string>

#include "model/robot_spec.h"

namespace xmate::model {

struct ParameterProblem {
  std::string text;       // "" when the value is acceptable
  std::string parameter;  // as the call names it: "joint_hz", "center", "upper", ... ("" if none applies)
  int index = -1;         // the element of an array parameter, -1 for a scalar or the whole array
  bool empty() const { return text.empty(); }
  // For callers that only report the sentence (exceptions, refusals).
  operator const std::string&() const { return text; }
};

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

ParameterProblem checkHomogeneous(const char* call, const char* parameter, const std::array<double, 16>& pose);
ParameterProblem checkCollisionThresholds(const RobotSpec& spec, const std::array<double, 7>& thresholds);
ParameterProblem checkJointImpedance(const RobotSpec& spec, const std::array<double, 7>& stiffness);
ParameterProblem checkCartesianImpedance(const std::array<double, 6>& stiffness);
ParameterProblem checkFilters(double joint_hz, double cartesian_hz, double torque_hz);
ParameterProblem checkLoad(const RobotSpec& spec, double mass, const std::array<double, 3>& center,
                      const std::array<double, 9>& inertia);
ParameterProblem checkToolFrame(const std::array<double, 16>& flange_to_tool);
ParameterProblem checkCartesianLimit(const std::array<double, 3>& size, const std::array<double, 16>& frame);
// Soft limits in degrees, as setJointLimit takes them.
ParameterProblem checkSoftLimits(const RobotSpec& spec, const std::array<double, 7>& upper_deg,
                            const std::array<double, 7>& lower_deg);
ParameterProblem checkDesiredWrench(const std::array<double, 6>& wrench);
// API numbering: fc_type 1 world, 2 tool, 3 path.
ParameterProblem checkForceFrame(const std::array<double, 16>& frame, int fc_type);
// API numbering: space 1 joint, 2 Cartesian; type 1 translation, 2 rotation, 3 free.
ParameterProblem checkDrag(int drag_space, int drag_type);
ParameterProblem checkMotorPower(int state);

}  // namespace xmate::model
