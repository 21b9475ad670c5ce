// SPDX-License-Identifier: Apache-2.0
// arm::JointStream moves a KUKA over RSI by joint positions: on the link's thread it turns the joint
// command of the running arm::JointMotion into the axis corrections AK (the total since RSI_ON, in
// degrees) and holds still between motions; before a motion starts, checkMotion() samples it at the
// RSI cycle against the axis speeds and the context's AXISCORR limits. docs/rsi.md, "Motion".
#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <string>

#include "arm/arm.h"
#include "model/robot_spec.h"
#include "net/seqlock.h"
#include "rsi/axis_correction.h"
#include "rsi/config.h"
#include "rsi/link.h"

namespace xmate::arm {

// What the stream knows on a cycle (rad).
struct StreamState {
  uint32_t session = 0;           // RSI session (a new RSI_ON starts a new one)
  uint64_t cycles = 0;            // <Rob> datagrams of this session
  std::array<double, 6> q_on{};   // set-point axes when this session began: corrections are relative to it
  std::array<double, 6> q{};      // actual axes (DEF_AIPos)
  std::array<double, 6> q_set{};  // set-point axes (DEF_ASPos; the actual ones if the config does not send it)
  std::array<double, 6> q_command{};  // the axes the last correction asks for (q_on + correction)
  uint64_t ipoc = 0;
  uint64_t ipoc_step = 0;  // IPOC's last advance: a KRC's clock advances by the cycle in ms (4 or 12)
};

class JointStream {
 public:
  // Installs itself as the link's callback: call before link.start(). The link must send DEF_AIPos.
  // Throws std::invalid_argument if the config does not send DEF_AIPos or receive AK.A1..A6.
  JointStream(rsi::Link& link, const model::RobotSpec& spec, const rsi::AxisCorrectionLimits& limits);

  // Any thread, lock-free. False until the first <Rob> arrived.
  bool state(StreamState& out) const { return state_.load(out) > 0; }

  // The caller's thread (one at a time): waits (at most `wait_for_robot`) for RSI to run, streams
  // `motion` until its last command, and returns. Throws std::runtime_error when RSI does not run,
  // when the robot's IPOC advances by 4 or 12 ms a cycle and that is not the link's cycle_ms (the
  // motion would run at the wrong speed), or when RSI stops or restarts during the motion (the robot
  // then holds where RSI left it). `session` (non-zero): the RSI session the motion was planned in
  // (StreamState::session); a motion is never streamed into another one.
  void run(JointMotion& motion, std::chrono::milliseconds wait_for_robot = std::chrono::seconds(5),
           uint32_t session = 0);

  // Refusal text (empty when fine) for one joint sample (6 values, rad) `spacing` seconds after
  // `previous` (nullptr for the first): outside the axis range, an axis faster than its rated
  // speed, or a total correction q - q_on beyond the AXISCORR limits. Names the axis, the limit and
  // the value, in degrees. Any thread.
  std::string checkSample(const double* q, const double* previous, double spacing,
                          const std::array<double, 6>& q_on) const;

  double cycleSeconds() const { return cycle_s_; }
  const model::RobotSpec& spec() const { return spec_; }
  const rsi::AxisCorrectionLimits& limits() const { return limits_; }
  // The joints (rad) this RSI session can reach: the start pose q_on plus the correction limits,
  // within the axis ranges (entries past the sixth: 0). False until the first <Rob>. Any thread,
  // lock-free, real-time safe.
  bool reachableBounds(std::array<double, 7>& lower, std::array<double, 7>& upper) const;

 private:
  rsi::Correction onCycle(const rsi::RobDecoder& rob);

  rsi::Link& link_;
  const model::RobotSpec& spec_;
  const rsi::AxisCorrectionLimits limits_;
  double cycle_s_;
  std::array<int, 6> actual_slots_{}, set_slots_{};
  // The link's thread's own values.
  StreamState now_;
  std::array<double, 6> correction_{};  // rad, total since RSI_ON
  ArmSample sample_;                    // what the motion is given each cycle
  std::atomic<JointMotion*> motion_{nullptr};
  std::atomic<uint32_t> motion_session_{0};  // the session motion_ belongs to
  std::atomic<bool> motion_done_{false};
  std::atomic<bool> in_motion_{false};  // the link's thread may be using motion_ (see onCycle)
  net::Seqlock<StreamState> state_;
};

}  // namespace xmate::arm
