// SPDX-License-Identifier: Apache-2.0
// PlotSetup: what the live plots offer for the connected arm -- its signals, how many joints and what
// they are called, the sample rate (which sizes the ~60 s ring) and which samples feed the plots.
#pragma once

#include <QString>

#include <vector>

#include "arm/arm.h"
#include "model/robot_spec.h"
#include "plots/plot_signals.h"

namespace rci::ui::plots {

struct PlotSetup {
  // Which Session signal feeds the plots: the xMate's state samples or the arm samples of any family.
  enum class Source { kStateSamples, kArmSamples };
  Source source = Source::kStateSamples;
  std::vector<Signal> offered;      // in the chooser's order
  std::vector<Signal> ticked;       // of those, on when the setup is applied
  int joints = kJointCount;         // joints offered in the chooser (A7 of a 6-axis KUKA is not shown)
  QString joint_prefix = QStringLiteral("J");             // "J1" / "A1": chooser and CSV columns
  QString joints_caption = QStringLiteral("Joints");      // the chooser's caption
  QString joint_title = QStringLiteral("joint %1");       // tooltips: "joint 1" / "axis A1"
  double sample_rate_hz = 1000;     // samples per second the ring is sized for
  double cycle_seconds = 0.001;     // the controller's cycle: velocity from consecutive samples

  bool offers(Signal signal) const;
  bool operator==(const PlotSetup& other) const = default;
};

// The xMate's plots (the widget's default): position, velocity, torque (measured, commanded,
// external) of J1..J7 from its 1 kHz state samples. Any thread.
PlotSetup xmateSetup();

// What an arm fed through arm samples offers: actual and set-point positions and the velocity from
// them always; gear torques and motor currents with those capabilities; the F/T sensor's wrench with
// a sensor; the late-answer count with RSI (late_answers). Joints are the model's axes, named A1..A6
// on a KUKA. cycle_seconds: the arm's cycle (0.004 or 0.012 s). Any thread.
PlotSetup armSetup(const xmate::model::RobotSpec& spec, xmate::arm::Capabilities capabilities, double cycle_seconds,
                   bool force_sensor, bool late_answers);

}  // namespace rci::ui::plots
