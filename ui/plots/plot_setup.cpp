// SPDX-License-Identifier: Apache-2.0
// PlotSetup (plot_setup.h): the xMate's signal set and an arm's, from its capabilities.
#include "plots/plot_setup.h"

#include <algorithm>

namespace rci::ui::plots {

bool PlotSetup::offers(Signal signal) const {
  return std::find(offered.begin(), offered.end(), signal) != offered.end();
}

PlotSetup xmateSetup() {
  PlotSetup setup;
  setup.offered = {Signal::kPositionMeasured, Signal::kPositionCommanded, Signal::kVelocityMeasured,
                   Signal::kTorqueMeasured,   Signal::kTorqueCommanded,   Signal::kTorqueExternal};
  setup.ticked = {Signal::kPositionMeasured, Signal::kVelocityMeasured, Signal::kTorqueMeasured};
  return setup;
}

PlotSetup armSetup(const xmate::model::RobotSpec& spec, xmate::arm::Capabilities capabilities, double cycle_seconds,
                   bool force_sensor, bool late_answers) {
  using xmate::arm::Capability;
  PlotSetup setup;
  setup.source = PlotSetup::Source::kArmSamples;
  setup.offered = {Signal::kAxisActual, Signal::kAxisSetPoint, Signal::kAxisVelocity};
  setup.ticked = {Signal::kAxisActual, Signal::kAxisVelocity};
  if (xmate::arm::has(capabilities, Capability::kGearTorques)) {
    setup.offered.push_back(Signal::kGearTorque);
    setup.ticked.push_back(Signal::kGearTorque);
  }
  if (xmate::arm::has(capabilities, Capability::kMotorCurrents)) {
    setup.offered.push_back(Signal::kMotorCurrent);
    setup.ticked.push_back(Signal::kMotorCurrent);
  }
  if (force_sensor) {  // its chart appears when ticked: off at first, the dock stays compact
    setup.offered.push_back(Signal::kSensorForce);
    setup.offered.push_back(Signal::kSensorTorque);
  }
  if (late_answers) setup.offered.push_back(Signal::kLateAnswers);
  setup.offered.push_back(Signal::kTcpActual);  // its chart appears when ticked
  if (xmate::arm::has(capabilities, Capability::kTcpSetPoint)) setup.offered.push_back(Signal::kTcpSetPoint);
  setup.joints = std::clamp(spec.dof, 1, kJointCount);
  if (spec.family == xmate::model::RobotFamily::kKuka) {  // KUKA's own names for its axes
    setup.joint_prefix = QStringLiteral("A");
    setup.joints_caption = QStringLiteral("Axes");
    setup.joint_title = QStringLiteral("axis A%1");
  }
  setup.cycle_seconds = cycle_seconds > 0 ? cycle_seconds : 0.004;
  setup.sample_rate_hz = 1.0 / setup.cycle_seconds;
  return setup;
}

}  // namespace rci::ui::plots
