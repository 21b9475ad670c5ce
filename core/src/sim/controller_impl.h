// SPDX-License-Identifier: Apache-2.0
// The inside of sim::Controller: its state as plain structs, and the member functions that
// controller.cpp (construction, scene, status), controller_requests.cpp (TCP commands),
// controller_motion.cpp (StartMove, streamed commands, stops), controller_cycle.cpp (servo and
// physics of one cycle, supervision) and controller_state.cpp (the RobotState) share.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include <Eigen/Geometry>

#include "model/arm_model.h"
#include "model/chain.h"
#include "model/robot_spec.h"
#include "sim/allowance.h"
#include "sim/command_checks.h"
#include "sim/controller.h"
#include "sim/controller_settings.h"
#include "sim/drag_walls.h"
#include "sim/error_bits.h"
#include "sim/plant.h"
#include "sim/reference.h"
#include "sim/sampled_derivatives.h"
#include "sim/servo.h"
#include "sim/success_window.h"

namespace xmate::sim {

using RCI::robot::RobotCommand;
using RCI::robot::RobotState;
using MoveController = RCI::robot::StartMoveRequest::ControllerMode;
using MoveGenerator = RCI::robot::StartMoveRequest::MotionGeneratorMode;

inline constexpr double kCycle = 0.001;  // s
inline constexpr int kSubsteps = 4;      // servo and integration steps per cycle (4 kHz)
inline constexpr double kSubstep = kCycle / kSubsteps;
// A motion's first command this close to the measured position (rad, m, rad) counts as starting
// exactly there; farther away, the jump is judged by the velocity/acceleration rules.
inline constexpr double kStartTolerance = 1e-3;
inline constexpr int kRecoveryCycles = 50;        // robot_mode kAutomaticErrorRecovery after a recovery
inline constexpr double kObserverCutoffHz = 100;  // bandwidth of the external torque estimate

// Hand guiding: damping of the free directions and joints (docs/simulator_controller.md, "Hand guiding (drag)").
inline constexpr double kDragTranslationDamping = 100;  // N s/m
inline constexpr double kDragRotationDamping = 10;      // Nm s/rad
inline constexpr double kDragJointDampingLarge = 20;    // Nm s/rad, 85 Nm joints
inline constexpr double kDragJointDampingSmall = 5;     // Nm s/rad, 36 Nm joints
// Cartesian impedance: posture control of the redundant joint (7-axis), minimum damping.
inline constexpr double kNullspaceStiffness = 10;      // Nm/rad
inline constexpr double kNullspaceDamping = 2;         // Nm s/rad
inline constexpr double kMinCartesianDamping = 5;      // N s/m and Nm s/rad for axes with K = 0

enum class Activity {
  kHold,    // motors on (or off: brakes), no motion: holding or stopping
  kMotion,  // between StartMove and the motion's end: the client streams commands
  kDrag,    // hand guiding
};

// A streamed motion between StartMove and its end.
struct Motion {
  MoveController controller = MoveController::kJointPosition;
  MoveGenerator generator = MoveGenerator::kJointPosition;
  uint64_t origin_id = 0;  // message_id at StartMove; command times count from here
  bool awaiting_first_command = true;
  int consecutive_lost = 0;
  // The last accepted command (origin of the next increment).
  JointVector q_command = JointVector::Zero();  // joint command, or the IK solution of the pose
  Eigen::Isometry3d pose_command = Eigen::Isometry3d::Identity();
  double psi_command = 0;
  JointVector torque_command = JointVector::Zero();  // the client's torque
  SampledDerivatives<7> joint_rates;
  SampledDerivatives<3> translation_rates;
  SampledDerivatives<3> rotation_rates;
  SampledDerivatives<1> psi_rates;
  SampledDerivatives<7> torque_rates;
  // Servo targets before filtering.
  JointVector joint_target = JointVector::Zero();
  Eigen::Isometry3d pose_target = Eigen::Isometry3d::Identity();
  JointVector nullspace_q = JointVector::Zero();
  // The first command after lost ones set the rejoin offset's position; the next one, if it comes
  // in the following cycle, sets its velocity (the extrapolation's, expected over that cycle).
  bool rejoin_velocity_pending = false;
  JointVector rejoin_velocity = JointVector::Zero();
};

struct Drag {
  int space = 0;  // wire numbering: 0 joint, 1 Cartesian
  int type = 2;   // 0 translation, 1 rotation, 2 free
  Eigen::Isometry3d anchor = Eigen::Isometry3d::Identity();  // TCP pose when guiding started
};

// Filters and references feeding the servo.
struct ServoReference {
  JointVector joint_filter = JointVector::Zero();  // low-passed joint target
  JointTrack track;                                // joint reference of the current cycle
  StopRamp ramp;                                   // a stop in progress
  SoftLimitClamp soft_limit_clamp;                 // auto_limit
  JointVector hold_target = JointVector::Zero();   // where the arm rests while holding
  Eigen::Isometry3d pose_filter = Eigen::Isometry3d::Identity();  // low-passed pose target
  Vector6d pose_filter_twist = Vector6d::Zero();
  JointVector torque_filter = JointVector::Zero();  // low-passed client torque
  RejoinBlend rejoin;                               // added to the joint target after lost commands
};

// What the last cycle measured and estimated.
struct Measurements {
  JointVector ddq = JointVector::Zero();
  JointVector motor_torque = JointVector::Zero();         // mean over the cycle
  JointVector joint_torque = JointVector::Zero();         // link side (tau_m)
  JointVector motor_torque_filtered = JointVector::Zero();
  JointVector joint_torque_filtered = JointVector::Zero();
  JointVector external_torque = JointVector::Zero();      // estimate, low-passed
  Vector6d external_wrench = Vector6d::Zero();            // at the TCP, base frame
  Eigen::Isometry3d tcp = Eigen::Isometry3d::Identity();
  model::Jacobian jacobian = model::Jacobian::Zero();
  Vector6d twist = Vector6d::Zero();
  Vector6d twist_rate = Vector6d::Zero();
  double psi = 0;
  double psi_rate = 0;
};

// The commanded quantities reported in RobotState.
struct Commanded {
  JointVector q = JointVector::Zero(), dq = JointVector::Zero(), ddq = JointVector::Zero();
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  Vector6d twist = Vector6d::Zero(), twist_rate = Vector6d::Zero();
  double psi = 0, psi_rate = 0, psi_acceleration = 0;
  JointVector torque = JointVector::Zero(), torque_rate = JointVector::Zero();
};

struct Controller::Impl {
  explicit Impl(const SimConfig& config);

  // ---- controller_requests.cpp: one function per TCP command, returning the status byte
  protocol::Frame handleRequest(uint32_t sequence, const uint8_t* payload, size_t size);
  uint8_t setMotorPower(const uint8_t* p, size_t n);
  uint8_t setCartesianLimit(const uint8_t* p, size_t n);
  uint8_t setJointLimit(const uint8_t* p, size_t n);
  uint8_t setCollisionBehavior(const uint8_t* p, size_t n);
  uint8_t setJointImpedance(const uint8_t* p, size_t n);
  uint8_t setCartesianImpedance(const uint8_t* p, size_t n);
  uint8_t setCoor(const uint8_t* p, size_t n);
  uint8_t setLoad(const uint8_t* p, size_t n);
  uint8_t setCartImpDesiredTau(const uint8_t* p, size_t n);
  uint8_t setFilters(const uint8_t* p, size_t n);
  uint8_t setTorqueFilterCutOffFrequency(const uint8_t* p, size_t n);
  uint8_t automaticErrorRecovery(const uint8_t* p, size_t n);
  uint8_t setFcCoor(const uint8_t* p, size_t n);
  uint8_t enableVirtualGuide(const uint8_t* p, size_t n);
  uint8_t setDO(const uint8_t* p, size_t n);
  uint8_t startDrag(const uint8_t* p, size_t n);
  uint8_t stopDrag(const uint8_t* p, size_t n);
  uint8_t rebootRobot(const uint8_t* p, size_t n);
  // Records why a request was refused (Controller::lastRefusal) and returns `status`.
  uint8_t refuse(uint8_t status, std::string reason);
  // True (and a refusal recorded) when a setting that changes the model or a frame arrives
  // while a motion or hand guiding runs.
  bool busyForModelChange(const char* call);

  // ---- controller_motion.cpp
  uint8_t startMove(const uint8_t* p, size_t n);
  uint8_t stopMove();
  void takeCommand(const RobotCommand* command);
  void acceptJointCommand(const RobotCommand& command, double t, ErrorBits& bits);
  void acceptCartesianCommand(const RobotCommand& command, double t, ErrorBits& bits);
  void acceptTorqueCommand(const RobotCommand& command, double t, ErrorBits& bits);
  void startReferenceAt(const JointVector& q);
  void extrapolateLostCommand();
  bool jointTargetFollowsCommands() const;
  void extrapolate(double t, JointVector& q, JointVector& dq) const;
  void rejoinAfterGap(int gap, const JointVector& extrapolated, const JointVector& extrapolated_velocity,
                      const JointVector& previous_target);
  void finishMotion();
  void stopFromMeasured();               // controlled stop, then hold
  void raiseErrors(const ErrorBits& bits);  // motion stops, bits stay until recovery
  void powerOn();
  void powerOff();                       // brakes engage; any motion or guiding ends
  void startGuiding(int space, int type);
  // The scene puts the arm at q, at rest (as if moved there unpowered): motion or guiding ends.
  void placeArm(const JointVector& q);

  // ---- controller_limits.cpp: allowances (allowance.h) and the walls of hand guiding (drag_walls.h)
  void resetAllowances();         // afresh at the current pose: power-on, StartMove, StartDrag, placed arm
  void ratchetAllowances();       // every cycle, after the physics
  void widenIkLimitsToAllowance();  // the IK may return solutions as far out as the allowance
  TcpLinearization tcpLinearization() const;
  ArmAngleLinearization armAngleLinearization() const;  // 7-axis: psi and the wrist centre over the cycle
  double wristAxisRadius() const;  // the wrist centre's distance from the J1 axis, m (7-axis)
  // Walls and the guiding speed limits (joints, TCP, arm angle).
  JointVector dragWallTorque(const TcpLinearization& tcp, const ArmAngleLinearization& arm_angle) const;
  void holdAtDragWalls(const TcpLinearization& tcp, const ArmAngleLinearization& arm_angle,
                       const FrozenDynamics& physical);

  // ---- controller_cycle.cpp
  void step(const RobotCommand* command);
  void advanceReference();
  void simulateCycle();
  JointVector servoTorque(double fraction, const CartesianImpedance& cartesian, const JointVector& gravity,
                          const JointVector& joint_damping) const;
  void measure(const JointVector& dq_before, const JointVector& motor_sum, const JointVector& drive_sum,
               const JointVector& scene_torque, const JointVector& physical_bias);
  void supervise();
  bool positionControlled() const;
  bool cartesianLawActive() const;
  CartesianImpedance cartesianLaw() const;

  // ---- controller_state.cpp
  void updateCommanded();
  void fillState();
  RCI::robot::RobotMode robotMode() const;
  SimStatus status() const;

  // ---- helpers
  double alpha(double hz) const;
  int safetyStop() const { return estop ? 2 : guard_stop ? 3 : 1; }  // API numbering
  bool hasErrors() const { return anyError(errors); }
  void updateDigitalInputs();

  SimConfig config;
  const model::RobotSpec& spec;
  model::Chain chain;        // as loaded from the URDF (LoadRobotModel reports its inertias)
  model::ArmModel arm;       // the controller's model: tool and load as configured
  model::ArmModel plant_arm;  // the physical arm: the scene's actual payload
  bool plant_follows_load = true;  // actual payload = configured load until the scene says otherwise
  PlantParams params;
  JointLimitVectors limits;
  ControllerSettings settings;

  PlantState plant;
  JointAllowance joint_allowance;  // the joint limits enforced: soft limits, or wider where the arm is beyond them
  BoxAllowance box_allowance;      // the same for the faces of the safety box
  WallOnsets wall_onsets;          // where the springs of the drag walls begin
  WristAxisStop wrist_stop;        // 7-axis: how close to the J1 axis guiding may bring the wrist centre
  FrozenDynamics model_dynamics;
  FrozenDynamics plant_dynamics;

  bool motors_on = false;
  bool estop = false;
  bool guard_stop = false;
  bool reboot_requested = false;
  Activity activity = Activity::kHold;
  Motion motion;
  Drag drag;
  ServoReference ref;
  Measurements meas;
  Commanded commanded;
  ErrorBits errors{};
  int recovery_cycles_left = 0;
  SuccessWindow success;
  std::array<bool, 6> digital_out{};
  std::array<bool, 6> scene_digital_in{};
  std::array<bool, 6> digital_in{};
  bool loopback = false;
  Vector6d scene_wrench = Vector6d::Zero();
  uint64_t cycles = 0;
  uint64_t lost_commands = 0;
  std::string last_refusal;
  RobotState state;
};

}  // namespace xmate::sim
