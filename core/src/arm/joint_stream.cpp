// SPDX-License-Identifier: Apache-2.0
// arm::JointStream (joint_stream.h): joint commands as AXISCORR corrections, and the checks before a
// motion is streamed.
#include "arm/joint_stream.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <thread>


namespace xmate::arm {

using rsi::Correction;
using rsi::Link;
using rsi::RobDecoder;
namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;

std::string fmt(const char* format, double a, double b = 0, double c = 0) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, format, a, b, c);
  return buffer;
}

}  // namespace

JointStream::JointStream(Link& link, const model::RobotSpec& spec, const rsi::AxisCorrectionLimits& limits)
    : link_(link), spec_(spec), limits_(limits), cycle_s_(link.options().cycle_ms * 1e-3) {
  for (int i = 0; i < 6; ++i) {
    const std::string axis = "A" + std::to_string(i + 1);
    actual_slots_[size_t(i)] = link.slot("AIPos", axis);
    set_slots_[size_t(i)] = link.slot("ASPos", axis);
    if (actual_slots_[size_t(i)] < 0)
      throw std::invalid_argument("JointStream: the Ethernet config does not send DEF_AIPos (the actual axes); add "
                                  "<ELEMENT TAG=\"DEF_AIPos\" TYPE=\"DOUBLE\" INDX=\"INTERNAL\" /> to its SEND elements");
    if (set_slots_[size_t(i)] < 0) set_slots_[size_t(i)] = actual_slots_[size_t(i)];
  }
  link.setCallback([this](const RobDecoder& rob) { return onCycle(rob); });
}

Correction JointStream::onCycle(const RobDecoder& rob) {
  const uint32_t session = link_.callbackSession();
  for (size_t i = 0; i < 6; ++i) {
    now_.q[i] = rob.value(actual_slots_[i]) / kDeg;
    now_.q_set[i] = rob.value(set_slots_[i]) / kDeg;
  }
  if (session != now_.session) {  // RSI_ON: corrections start again from zero, at this set-point
    now_.session = session;
    now_.cycles = 0;
    now_.q_on = now_.q_set;
    now_.ipoc_step = 0;
    correction_ = {};
  } else {
    now_.ipoc_step = rob.ipoc() - now_.ipoc;
  }
  now_.ipoc = rob.ipoc();
  ++now_.cycles;
  // in_motion_ is up while the motion may be in use here: run() takes a motion back by clearing
  // motion_ and then waiting for in_motion_ to fall (both sequentially consistent, so either this
  // thread sees the cleared pointer or run() sees the flag).
  in_motion_.store(true);
  JointMotion* motion = motion_.load();
  if (motion && motion_session_.load() == now_.session) {  // never into another RSI session
    sample_.cycle = now_.cycles;
    sample_.session = now_.session;
    for (size_t i = 0; i < 6; ++i) {
      sample_.q[i] = now_.q[i];
      sample_.q_command[i] = now_.q_command[i];  // the command of the cycle before
    }
    std::array<double, 7> q{};
    const bool last = motion->command(sample_, q);
    for (size_t i = 0; i < 6; ++i) correction_[i] = q[i] - now_.q_on[i];
    if (last) {
      motion_.store(nullptr);
      motion_done_.store(true, std::memory_order_release);
    }
  }
  in_motion_.store(false);
  Correction c;
  c.kind = Correction::Kind::kAxis;
  for (size_t i = 0; i < 6; ++i) {
    now_.q_command[i] = now_.q_on[i] + correction_[i];
    c.values[i] = correction_[i] * kDeg;
  }
  state_.store(now_);
  return c;
}

void JointStream::run(JointMotion& motion, std::chrono::milliseconds wait_for_robot, uint32_t planned_in) {
  const auto deadline = std::chrono::steady_clock::now() + wait_for_robot;
  StreamState s;
  while (!link_.receiving() || !state(s)) {
    if (std::chrono::steady_clock::now() > deadline)
      throw std::runtime_error("RSI is not running: no <Rob> datagram arrived within " +
                               std::to_string(wait_for_robot.count()) +
                               " ms; start the KRL program (RSI_ON, RSI_MOVECORR) on the robot");
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  const uint32_t session = s.session;
  if (planned_in != 0 && planned_in != session)
    throw std::runtime_error("RSI was switched on again after the motion was planned (a new RSI session): run it "
                             "again from where the robot is");
  const int cycle_ms = link_.options().cycle_ms;
  if ((s.ipoc_step == 4 || s.ipoc_step == 12) && s.ipoc_step != uint64_t(cycle_ms))
    throw std::runtime_error("the robot runs RSI every " + std::to_string(s.ipoc_step) + " ms (its IPOC advances so), " +
                             "but the motion was planned for " + std::to_string(cycle_ms) +
                             " ms cycles; set the cycle to " + std::to_string(s.ipoc_step) + " ms (" +
                             (s.ipoc_step == 4 ? "RSI_ON with #IPO_FAST" : "RSI_ON without #IPO_FAST") + ")");
  motion_done_.store(false, std::memory_order_relaxed);
  motion_session_.store(session);
  motion_.store(&motion);
  for (;;) {
    if (motion_done_.load(std::memory_order_acquire)) return;
    const bool receiving = link_.receiving();
    state(s);
    if (!receiving || s.session != session) {
      // Take the motion back, and wait until the link's thread is not inside it, before `motion`
      // goes away.
      motion_.store(nullptr);
      while (in_motion_.load()) std::this_thread::yield();
      throw std::runtime_error(receiving ? "RSI was switched on again during the motion (a new RSI session): the "
                                           "motion was abandoned; run it again from where the robot is"
                                         : "RSI stopped during the motion (the robot stopped sending): check the "
                                           "smartPAD's messages (e.g. RSITimeout, a correction limit), restart the "
                                           "KRL program, then run the motion again");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

std::string JointStream::checkSample(const double* q, const double* previous, double spacing,
                                     const std::array<double, 6>& q_on) const {
  for (int i = 0; i < 6; ++i) {
    const size_t j = size_t(i);
    const std::string axis = "A" + std::to_string(i + 1);
    if (q[i] < spec_.q_min[j] - 1e-9 || q[i] > spec_.q_max[j] + 1e-9)
      return axis + " would reach " +
             fmt("%.2f deg, outside its range %.1f .. %.1f deg", q[i] * kDeg, spec_.q_min[j] * kDeg, spec_.q_max[j] * kDeg);
    if (previous) {
      const double speed = std::abs(q[i] - previous[i]) / spacing;
      if (speed > spec_.dq_max[j] * (1 + 1e-6))
        return axis + " would move at " + fmt("%.1f deg/s, above its rated %.1f deg/s", speed * kDeg, spec_.dq_max[j] * kDeg);
    }
    const double correction = q[i] - q_on[j];
    if (correction < limits_.lower[j] - 1e-9 || correction > limits_.upper[j] + 1e-9) {
      const bool above = correction > 0;
      return axis + " would need a correction of " + fmt("%.2f deg from where RSI was switched on", correction * kDeg) +
             ", beyond " + (above ? limits_.upper_by[j] : limits_.lower_by[j]) + " = " +
             fmt("%.1f deg", (above ? limits_.upper[j] : limits_.lower[j]) * kDeg) +
             "; raise the limit in the RSI context or teach a target closer to the RSI start pose";
    }
  }
  return {};
}

bool JointStream::reachableBounds(std::array<double, 7>& lower, std::array<double, 7>& upper) const {
  StreamState s;
  if (!state(s)) return false;
  lower = {};
  upper = {};
  for (size_t i = 0; i < 6; ++i) {
    lower[i] = std::max(s.q_on[i] + limits_.lower[i], spec_.q_min[i]);
    upper[i] = std::min(s.q_on[i] + limits_.upper[i], spec_.q_max[i]);
  }
  return true;
}

}  // namespace xmate::arm
