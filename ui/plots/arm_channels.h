// SPDX-License-Identifier: Apache-2.0
// ArmChannels: the channel values of one arm sample (a KUKA's over RSI) -- axes, set-points, the
// velocity from consecutive samples, gear torques, motor currents, and the per-tick extras (F/T
// sensor wrench, late-answer count) held over the samples of a display tick.
#pragma once

#include <array>
#include <cstdint>

#include "arm/arm.h"
#include "plots/plot_buffer.h"

namespace rci::ui::plots {

// What the session reports once per display tick rather than per cycle.
struct ArmExtras {
  bool force_valid = false;        // the F/T sensor's reading is recent and healthy
  std::array<double, 6> force{};   // Fx Fy Fz (N), Tx Ty Tz (Nm), sensor frame
  double late_answers = 0;         // the robot's count of late answers (RSI Delay)
};

class ArmChannels {
 public:
  // The arm's cycle, s: the time step between consecutive cycles of one session.
  void setCycleSeconds(double seconds) { cycle_s_ = seconds; }
  // Forgets the previous sample (a new session, a cleared buffer): the next velocity reads NaN.
  void reset() { has_previous_ = false; }

  // Fills out for sample s. Velocity: (q - previous q) / dt with dt = the cycles between the two
  // times the cycle when they are of one RSI session, else their arrival times' difference; NaN for
  // the first sample (of a session). Sensor values are NaN without a valid reading. The owner's
  // thread; real-time safe (no allocation).
  void map(const xmate::arm::ArmSample& s, const ArmExtras& extras, ChannelValues& out);

 private:
  double cycle_s_ = 0.004;
  bool has_previous_ = false;
  uint32_t previous_session_ = 0;
  uint64_t previous_cycle_ = 0;
  double previous_time_ = 0;
  std::array<double, 7> previous_q_{};
};

}  // namespace rci::ui::plots
