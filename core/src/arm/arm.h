// SPDX-License-Identifier: Apache-2.0
// arm::Arm: one robot arm, whichever family drives it -- an xMate over RCI (RciArm), a KUKA over
// RSI (RsiArm). The model, the newest state in SI units, every cycle's sample, a joint (or, where
// the controller has its own Cartesian control, a TCP) motion streamed at the controller's cycle,
// the joint range a motion can reach, digital IO, and what the backend can do. docs/architecture.md,
// "One interface for both robot families".
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "model/robot_spec.h"

namespace xmate::arm {

// What a backend can do. A panel names the capabilities it needs and is hidden without them.
enum class Capability : uint32_t {
  kJointTorques = 1u << 0,      // measured joint torques, Nm (the xMate's torque sensors)
  kMotorCurrents = 1u << 1,     // motor currents, A (a KUKA's DEF_MACur)
  kGearTorques = 1u << 2,       // gear torques, Nm (a KUKA's GEARTORQUE wired to the PC)
  kExternalWrench = 1u << 3,    // the external wrench at the TCP (the controller's estimate)
  kPowerControl = 1u << 4,      // motors on/off and error recovery from the PC
  kBuiltInGuiding = 1u << 5,    // the controller's own hand guiding (the xMate's drag)
  kCorrectionLimits = 1u << 6,  // motions stay within limits around where the session started (RSI)
  kControllerSafety = 1u << 7,  // settings on the controller: collision thresholds, safety box, soft limits, filters, tool, impedance
  kDigitalIo = 1u << 8,         // digital inputs and outputs reachable from the PC
  kTcpSetPoint = 1u << 9,       // the commanded TCP (or flange) position in every sample (RSI's DEF_RSol sent)
  kCartesianMotion = 1u << 10,  // TCP poses streamed to the controller's own Cartesian control (runCartesianMotion)
};
using Capabilities = uint32_t;
constexpr Capabilities operator|(Capability a, Capability b) { return uint32_t(a) | uint32_t(b); }
constexpr Capabilities operator|(Capabilities a, Capability b) { return a | uint32_t(b); }
constexpr bool has(Capabilities set, Capability c) { return (set & uint32_t(c)) != 0; }

// One controller cycle, in SI units; joints beyond the model's axes are 0. Trivially copyable.
struct ArmSample {
  uint64_t cycle = 0;                    // the controller's cycle counter (message id, cycles since RSI_ON)
  double time = 0;                       // takeSamples(): s since the connection opened, by the PC's clock at arrival (latest(): 0)
  uint32_t session = 0;                  // 1, 2, ...: a new one after the controller stopped sending and began again
  std::array<double, 7> q{};             // measured joints, rad
  std::array<double, 7> q_command{};     // the joints the controller is commanded to, rad (a motion starts from them)
  std::array<double, 7> tau{};           // Capability::kJointTorques, Nm
  std::array<double, 7> motor_current{}; // Capability::kMotorCurrents, A
  std::array<double, 7> gear_torque{};   // Capability::kGearTorques, Nm
  std::array<double, 6> wrench{};        // Capability::kExternalWrench: at the TCP, base frame, N and Nm
  std::array<double, 3> tcp_position{};  // measured TCP (or flange) in the base frame, m
  std::array<double, 3> tcp_position_command{};  // Capability::kTcpSetPoint: where the controller takes it, m
};

// The newest state: a sample and the whole TCP pose.
struct ArmState {
  ArmSample sample;
  std::array<double, 16> tcp{};  // measured pose, base frame, row-major, m
};

// A joint motion streamed one command per controller cycle.
class JointMotion {
 public:
  virtual ~JointMotion() = default;
  // The controller's cycle (the backend's real-time thread): no allocation, no lock, no I/O.
  // Writes this cycle's joint command (rad; the model's axes); returns true when it was the last.
  virtual bool command(const ArmSample& now, std::array<double, 7>& q) = 0;
};

// A TCP motion streamed one pose per controller cycle (Capability::kCartesianMotion); the controller
// finds the joints, keeping the arm angle of a redundant arm.
class CartesianMotion {
 public:
  virtual ~CartesianMotion() = default;
  // The controller's cycle (the backend's real-time thread): no allocation, no lock, no I/O.
  // Writes this cycle's TCP pose command (base frame, row-major 4x4, m); returns true when it was the last.
  virtual bool command(const ArmState& now, std::array<double, 16>& pose) = 0;
};

// The joint range (rad) a motion can reach now: the model's range, on RSI narrowed to the context's
// correction limits around where RSI was switched on (Capability::kCorrectionLimits). session: the
// session the range belongs to (0: any) -- a motion planned within it ends, holding still, when
// another session begins. Joints beyond the model's axes: 0.
struct MotionBounds {
  std::array<double, 7> lower{}, upper{};
  uint32_t session = 0;
};

class RciArm;
class RsiArm;

// For the few places above that hold one implementation per family (the executor's ports,
// teach/arm_port.h): Arm::accept() calls the visit() of the arm's own kind, so no one asks which
// kind an arm is.
class ArmVisitor {
 public:
  virtual ~ArmVisitor() = default;
  virtual void visit(RciArm& arm) = 0;
  virtual void visit(RsiArm& arm) = 0;
};

class Arm {
 public:
  virtual ~Arm() = default;

  // Any thread: calls visitor.visit(*this) as the arm's own kind.
  virtual void accept(ArmVisitor& visitor) = 0;

  // Any thread.
  virtual const model::RobotSpec& spec() const = 0;
  virtual Capabilities capabilities() const = 0;
  virtual double cycleSeconds() const = 0;  // 0.001 (RCI), 0.004 or 0.012 (RSI)

  // Any thread, lock-free, never blocks. False until the first state arrived.
  virtual bool latest(ArmState& out) const = 0;
  // Exactly one consumer thread: pops up to `max` samples of the cycles since the last call, oldest
  // first (every cycle, until the backend's ring is full: samplesDropped() counts what it lost).
  virtual size_t takeSamples(ArmSample* out, size_t max) = 0;
  virtual uint64_t samplesDropped() const = 0;

  // The caller's thread, blocking, one at a time: streams `motion` until its last command, starting
  // from where the arm is. Throws std::runtime_error saying what ended it otherwise (a controller
  // error, the robot stopped sending, RSI stopped) and what to do.
  virtual void runJointMotion(JointMotion& motion) = 0;
  // The same for a TCP motion, on an arm with Capability::kCartesianMotion; others throw
  // std::runtime_error saying so.
  virtual void runCartesianMotion(CartesianMotion& motion);

  // Any thread, lock-free. Throws std::runtime_error when the range is not known yet (RSI not
  // running: what to start on the robot).
  virtual MotionBounds motionBounds() const;

  // Digital IO (Capability::kDigitalIo): the signals by name ("DO0_1", "$OUT[3]"), in the order
  // setOutput / input take them. The caller's thread; may block on the network. Throw
  // std::runtime_error saying what failed and what to do.
  virtual std::vector<std::string> outputNames() const = 0;
  virtual std::vector<std::string> inputNames() const = 0;
  virtual void setOutput(size_t index, bool level) = 0;
  virtual bool input(size_t index) = 0;
};

}  // namespace xmate::arm
