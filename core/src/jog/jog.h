// SPDX-License-Identifier: Apache-2.0
// Jogging one axis: per-cycle command generators for Robot::Control() (xMate) and, for the joint
// jog, an arm::JointMotion for any arm (a KUKA over RSI). While the jog is held (the window's jog
// button) the axis ramps up to the jog speed; on release (or a stop request) it ramps down and the motion
// ends with MotionFinished. It brakes on its own before a soft or hardware limit (on a KUKA also
// before the RSI context's correction limits). The ramp advances by the controller's elapsed cycles
// (message_id / ArmSample::cycle), so a lost state does not turn the next command into a double
// step. next(), advance() and command() run on the controller's real-time thread: no allocation, no
// locks; constructors on any thread, before the motion starts.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>

#include <xmate/rci_types.h>
#include <xmate/types.h>

#include "arm/arm.h"
#include "guide/admittance.h"
#include "jog/ramp.h"
#include "model/robot_spec.h"
#include "rsi/axis_correction.h"

namespace xmate::jog {

// Jog speeds at 100 % of the speed slider (fractions of the model's limits, docs/robot_models.md, "Limits").
inline constexpr double kJogJointSpeedFraction = 0.5;    // of dq_max
inline constexpr double kJogJointAccelFraction = 0.25;   // of ddq_max
inline constexpr double kJogTranslationSpeed = 0.25;     // m/s
inline constexpr double kJogTranslationAccel = 0.5;      // m/s^2
inline constexpr double kJogRotationSpeed = 0.5;         // rad/s
inline constexpr double kJogRotationAccel = 1.0;         // rad/s^2
inline constexpr double kJogJerkPerAccel = 10.0;         // jerk = 10/s x acceleration (0.1 s ramps)
inline constexpr double kJogLimitMargin = 1.0 / 57.29577951308232;  // stay 1 deg inside a joint limit

// A jog's holder ends it (ramps it down) when it has not heard from itself for this long: in the
// window, when the display tick is older than this, since the GUI thread may miss the button's
// release (docs/reliability.md, "Stop and disconnect").
inline constexpr double kJogDeadManMs = 150.0;

// Flags shared between the thread holding the jog (writes held and stop) and the real-time
// callback (reads them; sets window_silent).
struct JogFlags {
  std::atomic<bool> held{true};   // the jog button is still pressed
  std::atomic<bool> stop{false};  // stop now (session stop request, panel closing)
  std::atomic<bool> window_silent{false};  // the dead-man ended it (set by the callback)
};

// Cycles since the previous state (at least 1, at most 20: longer gaps end the motion anyway).
int elapsedCycles(uint64_t previous_id, uint64_t id);

struct JointLimitsRad {
  std::array<double, 7> lower{}, upper{};
};

// The joint limits a jog must stay inside: the soft limits (degrees) when enabled, within the
// hardware range, each narrowed by kJogLimitMargin.
JointLimitsRad jogLimits(const model::RobotSpec& spec, bool soft_enabled, const std::array<double, 7>& soft_lower_deg,
                         const std::array<double, 7>& soft_upper_deg);

// `limits` narrowed to the total axis corrections an RSI context lets through (AXISCORR, AXISCORRMON:
// rad, relative to q_on, the set-point where RSI was switched on), each kJogLimitMargin inside.
// Any thread; real-time safe.
JointLimitsRad withinCorrectionLimits(const JointLimitsRad& limits, const std::array<double, 6>& q_on,
                                      const rsi::AxisCorrectionLimits& correction);

// `limits` narrowed to what the arm can reach now (Arm::motionBounds()), each of the model's `dof`
// joints kJogLimitMargin inside. Any thread; real-time safe.
JointLimitsRad withinBounds(const JointLimitsRad& limits, const arm::MotionBounds& bounds, int dof);

// Joint jog of one joint: startMove(kJointPosition, kJointPosition) + Control(JointControl) on an
// xMate, or through JointJogMotion on any arm. cycle_s: the controller's cycle (Arm::cycleSeconds()).
class JointJog {
 public:
  JointJog(const model::RobotSpec& spec, int joint, int direction, double speed_fraction,
           const JointLimitsRad& limits, const JogFlags& flags, double cycle_s = 0.001);
  // The controller's cycle: this cycle's command (starting from the measured joints).
  JointPositions next(const RCI::robot::RobotState& state);
  // The same for any controller: `cycle` its cycle counter, `start` the joints the first command
  // equals. Writes q; returns true on the last command (at rest after release or stop).
  bool advance(uint64_t cycle, const std::array<double, 7>& start, std::array<double, 7>& q);

 private:
  int joint_, direction_;
  JointLimitsRad limits_;
  const JogFlags& flags_;
  JogRamp ramp_;
  bool started_ = false;
  uint64_t last_id_ = 0;  // message_id of the previous state: the ramp advances by elapsed cycles
  std::array<double, 7> q_{};
};

// A JointJog as an arm::JointMotion (streamed by Arm::runJointMotion). Each
// cycle it first calls `watch` (the dead-man and stop checks, which set the jog's flags), then
// advances the jog from where the arm is commanded to be (RSI holds the last correction between
// motions). Ends at once, holding still, if the arm's session is not `session` (0: any). The arm's
// real-time thread; `watch` must be real-time safe.
class JointJogMotion : public arm::JointMotion {
 public:
  JointJogMotion(JointJog& jog, std::function<void()> watch, uint32_t session = 0)
      : jog_(jog), watch_(std::move(watch)), session_(session) {}
  bool command(const arm::ArmSample& now, std::array<double, 7>& q) override;
  bool sessionChanged() const { return session_changed_; }  // after the motion: it ended for that

 private:
  JointJog& jog_;
  std::function<void()> watch_;
  uint32_t session_;
  bool session_changed_ = false;
};

// Cartesian jog of the TCP along or about one base axis (0..2 x, y, z; 3..5 rx, ry, rz):
// startMove(kCartesianPosition, kCartesianPosition) + Control(CartesianControl) on an xMate, or
// through CartesianJogMotion on an arm with Capability::kCartesianMotion. Brakes when the joints
// (extrapolated from the commanded joint velocities) would reach a limit while stopping.
class CartesianJog {
 public:
  CartesianJog(int axis, int direction, double speed_fraction, int dof, const JointLimitsRad& limits,
               const JogFlags& flags);
  // The controller's cycle: this cycle's command (starting from the measured pose).
  CartesianPose next(const RCI::robot::RobotState& state);
  // The same for an arm: writes the TCP pose (row-major 4x4); returns true on the last command. The
  // commanded joint velocities are taken from the change of the commanded joints.
  bool advance(const arm::ArmState& now, std::array<double, 16>& pose);

 private:
  // One cycle: `cycle` the controller's counter, `tcp` the measured pose, q_c / dq_c the commanded
  // joints and their velocities.
  bool step(uint64_t cycle, const std::array<double, 16>& tcp, const std::array<double, 7>& q_c,
            const std::array<double, 7>& dq_c, std::array<double, 16>& pose);
  bool jointsNearLimit(const std::array<double, 7>& q_c, const std::array<double, 7>& dq_c) const;
  std::array<double, 16> pose() const;

  int axis_, direction_, dof_;
  JointLimitsRad limits_;
  const JogFlags& flags_;
  JogRamp ramp_;
  double cycle_s_ = 0.001;
  bool started_ = false;
  uint64_t last_id_ = 0;
  std::array<double, 16> start_{};
  std::array<double, 7> last_q_c_{};  // advance(): the previous commanded joints
  double travelled_ = 0;  // m or rad along the axis
};

// A CartesianJog as an arm::CartesianMotion (streamed by Arm::runCartesianMotion). Each cycle it
// first calls `watch` (the dead-man and stop checks, which set the jog's flags). The arm's
// real-time thread; `watch` must be real-time safe.
class CartesianJogMotion : public arm::CartesianMotion {
 public:
  CartesianJogMotion(CartesianJog& jog, std::function<void()> watch) : jog_(jog), watch_(std::move(watch)) {}
  bool command(const arm::ArmState& now, std::array<double, 16>& pose) override;

 private:
  CartesianJog& jog_;
  std::function<void()> watch_;
};

// Cartesian jog of an arm without Cartesian control of its own (a KUKA over RSI): a push along (or a
// twist about) one base axis at the flange, handed to guide::AdmittanceGuide as its wrench, so the
// flange moves at the jog speed within the joint bounds and holds at the edge of the reach as hand
// guiding does; on release the guide brakes to rest and ends. The push is zero at the guide's first
// reading (its bias) and turned into the flange frame at the arm's newest pose. read(): the arm's
// real-time thread, lock-free.
class JogPush : public guide::WrenchSource {
 public:
  JogPush(const arm::Arm& arm, int axis, int direction, const guide::GuideParameters& parameters);
  bool read(std::array<double, 6>& wrench, int64_t& received_ns) const override;

 private:
  const arm::Arm& arm_;
  int axis_;
  double push_;                 // N (axes 0..2) or Nm (3..5), signed
  mutable bool biased_ = false;  // the first reading was handed out (zero)
};

// The guide's settings for a Cartesian jog along / about `axis` (0..5) at `speed_fraction` of the
// jog speeds (kJogTranslationSpeed, kJogRotationSpeed) and accelerations.
guide::GuideParameters cartesianJogParameters(int axis, double speed_fraction);

// The Cartesian jog of an arm without Cartesian control of its own, as the arm::JointMotion it
// streams: the admittance guide pushed by a JogPush, told to brake and end when the jog is released
// or stopped (`watch` sets the flags first each cycle). The arm's real-time thread.
class GuidedCartesianJogMotion : public arm::JointMotion {
 public:
  GuidedCartesianJogMotion(guide::AdmittanceGuide& guide, const JogFlags& flags, std::function<void()> watch)
      : guide_(guide), flags_(flags), watch_(std::move(watch)) {}
  bool command(const arm::ArmSample& now, std::array<double, 7>& q) override;

 private:
  guide::AdmittanceGuide& guide_;
  const JogFlags& flags_;
  std::function<void()> watch_;
};

}  // namespace xmate::jog
