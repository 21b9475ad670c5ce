// SPDX-License-Identifier: Apache-2.0
// The data exchanged with the controller every millisecond (docs/protocol.md, "Real-time datagrams")
// and the callback command types of the vendor API (docs/api.md, "Types"). Plain structs, no behaviour.
#pragma once

#include <array>
#include <cstdint>
#include <functional>

namespace RCI {
namespace robot {

// Modes reported in RobotState (wire values in docs/protocol.md, "Real-time datagrams").
enum class MotionGeneratorMode : uint8_t {
  kIdle, kJointPosition, kJointVelocity, kCartesianPosition, kCartesianVelocity
};
enum class ControllerMode : uint8_t {
  kJointPosition, kCartesianPosition, kJointImpedance, kCartesianImpedance, kTorque, kOther
};
enum class RobotMode : uint8_t {
  kOther, kIdle, kMove, kGuiding, kReflex, kUserStopped, kAutomaticErrorRecovery
};

// Modes requested by startMove().
struct StartMoveRequest {
  enum class ControllerMode : uint8_t {
    kJointPosition, kCartesianPosition, kJointImpedance, kCartesianImpedance, kTorque
  };
  enum class MotionGeneratorMode : uint8_t { kIdle, kJointPosition, kCartesianPosition };
};

enum class DOSIGNAL : uint8_t { DO0_0, DO0_1, DO0_2, DO0_3, DO1_0, DO1_1 };
enum class DISIGNAL : uint8_t { DI0_0, DI0_1, DI0_2, DI0_3, DI1_0, DI1_1 };

// What the controller sends every cycle. Poses are 4x4 row-major (m, rad); 6-axis models leave
// element 6 of the joint arrays at 0.
struct RobotState {
  uint64_t message_id = 0;
  std::array<double, 7> q{};      // measured joint positions, rad
  std::array<double, 7> q_c{};    // commanded joint positions
  std::array<double, 7> dq_m{};   // measured joint velocities, rad/s
  std::array<double, 7> dq_c{};   // commanded joint velocities
  std::array<double, 7> ddq_c{};  // commanded joint accelerations, rad/s^2
  std::array<double, 16> toolTobase_pos_m{};  // measured TCP pose in the base frame
  std::array<double, 16> toolTobase_pos_c{};  // commanded TCP pose
  std::array<double, 6> toolTobase_vel_c{};   // commanded TCP twist [v; omega]
  std::array<double, 6> toolTobase_acc_c{};
  double psi_m = 0;      // measured arm angle, rad (7-axis)
  double psi_c = 0;      // commanded arm angle
  double psi_vel_c = 0;
  double psi_acc_c = 0;
  std::array<double, 7> tau_m{};           // measured joint torques, Nm
  std::array<double, 7> tau_m_filtered{};
  std::array<double, 7> tau_c{};           // commanded joint torques
  std::array<double, 7> tau_vel_c{};       // commanded torque derivative, Nm/s
  std::array<double, 6> tau_ext_in_base{};   // estimated external wrench, base frame [F; M]
  std::array<double, 6> tau_ext_in_stiff{};  // the same in the force-control frame (setFcCoor)
  std::array<double, 7> theta_m{};         // motor positions
  std::array<double, 7> theta_vel_m{};
  std::array<double, 7> motor_tau{};
  std::array<double, 7> motor_tau_filtered{};
  std::array<bool, 20> errors{};            // error bits, docs/error_bits.md
  double control_command_success_rate = 0;  // share of the last 100 commands that arrived
  MotionGeneratorMode motion_generator_mode = MotionGeneratorMode::kIdle;
  ControllerMode controller_mode = ControllerMode::kJointPosition;
  RobotMode robot_mode = RobotMode::kOther;
};

struct MotionCommand {
  std::array<double, 7> q_c{};
  std::array<double, 16> toolTobase_pos_c{};  // row-major
  bool psi_valid = false;
  double psi_c = 0;
  bool motion_generation_finished = false;
  std::array<double, 4> dynamic_wall{};  // present on the wire since SDK 1.4; unused
};
struct TorqueCommand {
  std::array<double, 7> tau_c{};
};
// What the client sends back in answer to each RobotState during motion.
struct RobotCommand {
  uint64_t message_id = 0;
  MotionCommand motion;
  TorqueCommand torque;
};

}  // namespace robot
}  // namespace RCI

namespace xmate {

// Returned by the control callbacks; motion_finished marks the last command.
struct JointPositions {
  std::array<double, 7> q{};
  bool motion_finished = false;
};
// psi_valid == false keeps the current arm angle.
struct CartesianPose {
  std::array<double, 16> toolTobase_pos_c{};
  bool psi_valid = false;
  double psi_c = 0;
  bool motion_finished = false;
};
// Joint torques on top of the controller's own gravity compensation.
struct Torques {
  std::array<double, 7> tau{};
  bool motion_finished = false;
};

using JointControl = std::function<JointPositions(RCI::robot::RobotState)>;
using CartesianControl = std::function<CartesianPose(RCI::robot::RobotState)>;
using TorqueControl = std::function<Torques(RCI::robot::RobotState)>;

// Returns command with motion_finished set: the callback's way to end Control().
template <class T>
T MotionFinished(T command) {
  command.motion_finished = true;
  return command;
}

}  // namespace xmate
