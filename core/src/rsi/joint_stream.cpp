// SPDX-License-Identifier: Apache-2.0
// rsi::JointStream (joint_stream.h): joint commands as AXISCORR corrections, and the checks before a
// motion is streamed.
#include "rsi/joint_stream.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <thread>


namespace xmate::rsi {
namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;
constexpr double kKukaDefaultLimitDeg = 5.0;  // AXISCORR's limits when the context does not set them

double limitParameter(const Context& context, const Object& object, const std::string& name, double fallback) {
  const std::string* text = object.parameter(name);
  if (!text) return fallback;
  char* end = nullptr;
  const double value = std::strtod(text->c_str(), &end);
  if (text->empty() || *end != '\0' || !std::isfinite(value))
    throw ConfigError(context.path + ":" + std::to_string(object.line) + ": " + object.id + "'s " + name + " = \"" +
                      *text + "\" is not a number; give the limit in degrees, e.g. 90");
  return value;
}

std::string fmt(const char* format, double a, double b = 0, double c = 0) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, format, a, b, c);
  return buffer;
}

}  // namespace

AxisCorrectionLimits axisCorrectionLimits(const Context& context) {
  for (const Object& object : context.objects) {
    if (object.type != "AXISCORR") continue;
    AxisCorrectionLimits limits;
    limits.object = object.id;
    for (int i = 0; i < 6; ++i) {
      const std::string axis = "A" + std::to_string(i + 1);
      limits.lower[size_t(i)] = limitParameter(context, object, "LowerLim" + axis, -kKukaDefaultLimitDeg) / kDeg;
      limits.upper[size_t(i)] = limitParameter(context, object, "UpperLim" + axis, kKukaDefaultLimitDeg) / kDeg;
    }
    return limits;
  }
  throw ConfigError(context.path + ": the context has no AXISCORR object, so the PC cannot move the robot by axis "
                    "corrections; add one in RSI Visual, wired to the ETHERNET object's outputs 1..6");
}

JointStream::JointStream(Link& link, const model::RobotSpec& spec, const AxisCorrectionLimits& limits)
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
    correction_ = {};
  }
  ++now_.cycles;
  if (CycleMotion* motion = motion_.load(std::memory_order_acquire)) {
    std::array<double, 6> q{};
    const bool last = motion->command(now_, q);
    for (size_t i = 0; i < 6; ++i) correction_[i] = q[i] - now_.q_on[i];
    if (last) {
      motion_.store(nullptr, std::memory_order_relaxed);
      motion_done_.store(true, std::memory_order_release);
    }
  }
  Correction c;
  c.kind = Correction::Kind::kAxis;
  for (size_t i = 0; i < 6; ++i) {
    now_.q_command[i] = now_.q_on[i] + correction_[i];
    c.values[i] = correction_[i] * kDeg;
  }
  state_.store(now_);
  return c;
}

void JointStream::run(CycleMotion& motion, std::chrono::milliseconds wait_for_robot) {
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
  motion_done_.store(false, std::memory_order_relaxed);
  motion_.store(&motion, std::memory_order_release);
  for (;;) {
    if (motion_done_.load(std::memory_order_acquire)) return;
    const bool receiving = link_.receiving();
    state(s);
    if (!receiving || s.session != session) {
      // The link's thread may still hold the pointer: take it back before `motion` goes away.
      CycleMotion* expected = &motion;
      motion_.compare_exchange_strong(expected, nullptr);
      while (link_.receiving() && !motion_done_.load() && motion_.load()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
      throw std::runtime_error(receiving ? "RSI was switched on again during the motion (a new RSI session): the "
                                           "motion was abandoned; run it again from where the robot is"
                                         : "RSI stopped during the motion (the robot stopped sending): check the "
                                           "smartPAD's messages (e.g. RSITimeout, a correction limit), restart the "
                                           "KRL program, then run the motion again");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

std::string JointStream::checkSamples(const double* q, size_t count, const std::array<double, 6>& q_on) const {
  for (size_t k = 0; k < count; ++k) {
    const double* sample = q + 6 * k;
    for (int i = 0; i < 6; ++i) {
      const std::string axis = "A" + std::to_string(i + 1);
      const double value = sample[i];
      if (value < spec_.q_min[size_t(i)] - 1e-9 || value > spec_.q_max[size_t(i)] + 1e-9)
        return axis + " would reach " + fmt("%.2f deg, outside its range %.1f .. %.1f deg", value * kDeg,
                                             spec_.q_min[size_t(i)] * kDeg, spec_.q_max[size_t(i)] * kDeg);
      if (k > 0) {
        const double speed = std::abs(value - q[6 * (k - 1) + size_t(i)]) / cycle_s_;
        if (speed > spec_.dq_max[size_t(i)] * (1 + 1e-6))
          return axis + " would move at " + fmt("%.1f deg/s, above its rated %.1f deg/s", speed * kDeg,
                                                spec_.dq_max[size_t(i)] * kDeg);
      }
      const double correction = value - q_on[size_t(i)];
      if (correction < limits_.lower[size_t(i)] - 1e-9 || correction > limits_.upper[size_t(i)] + 1e-9) {
        const bool above = correction > 0;
        return axis + " would need a correction of " + fmt("%.2f deg from where RSI was switched on", correction * kDeg) +
               ", beyond " + limits_.object + "'s " + (above ? "UpperLim" : "LowerLim") + axis + " = " +
               fmt("%.1f deg", (above ? limits_.upper[size_t(i)] : limits_.lower[size_t(i)]) * kDeg) +
               "; raise the limit in the RSI context or teach a target closer to the RSI start pose";
      }
    }
  }
  return {};
}

}  // namespace xmate::rsi
