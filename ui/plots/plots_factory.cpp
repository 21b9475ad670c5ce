// SPDX-License-Identifier: Apache-2.0
// createPlotsWidget (ui/window/parts.h): builds the live plot area and feeds it from a Session -- an
// xMate's state samples on samplesArrived (with its joint count and J^T model, with the tool), any
// other arm's samples on armSamplesArrived (with the signals its capabilities and sensor offer).
#include <exception>

#include "arm/arm.h"
#include "model/robot_spec.h"
#include "plots/plots_widget.h"
#include "session/session.h"
#include "window/parts.h"

namespace rci::ui {

namespace {

// The model for tau_ext = J^T F, with the robot's current tool; nullptr if it cannot be loaded.
std::unique_ptr<plots::ExternalTorqueMap> makeTorqueMap(Session& session) {
  xmate::Robot* robot = session.robot();
  if (robot == nullptr) return nullptr;
  try {
    auto map = std::make_unique<plots::ExternalTorqueMap>(robot->type());
    map->setTool(robot->toolFrame());
    return map;
  } catch (const std::exception&) {
    return nullptr;  // external torques then read 0; every other signal is unaffected
  }
}

// The signal set of the open session: the xMate's state samples when its client is there, else what
// the arm offers (its capabilities, the F/T sensor, RSI's late-answer count).
plots::PlotSetup setupOf(Session& session) {
  xmate::arm::Arm* arm = session.arm();
  if (session.robot() != nullptr || arm == nullptr) return plots::xmateSetup();
  return plots::armSetup(session.spec(), arm->capabilities(), arm->cycleSeconds(), session.live().has_force_sensor,
                         session.rsiArm() != nullptr);
}

void onOpened(Session& session, plots::PlotsWidget* plots) {
  plots->configure(setupOf(session));
  plots->clear();  // the session clock restarts at 0
  if (xmate::Robot* robot = session.robot()) plots->setJointCount(xmate::model::robotSpec(robot->type()).dof);
  plots->setExternalTorqueMap(makeTorqueMap(session));
}

// This display tick's values of what the session reports per tick, not per cycle.
plots::ArmExtras extrasOf(const LiveState& live) {
  plots::ArmExtras extras;
  extras.force_valid = live.has_force_sensor && live.force_reading;
  extras.force = live.force;
  extras.late_answers = live.rsi.delay;
  return extras;
}

// A command may have changed the tool (setCoor): the wrench then refers to the new TCP.
void refreshTool(Session& session, plots::PlotsWidget* plots) {
  xmate::Robot* robot = session.robot();
  plots::ExternalTorqueMap* map = plots->externalTorqueMap();
  if (robot == nullptr || map == nullptr) return;
  try {
    map->setTool(robot->toolFrame());
  } catch (const std::exception&) {
  }
}

}  // namespace

QWidget* createPlotsWidget(Session& session, QWidget* parent) {
  auto* plots = new plots::PlotsWidget(parent);
  plots->setObjectName(QStringLiteral("plots"));
  QObject::connect(&session, &Session::samplesArrived, plots,
                   [plots](const xmate::client::StateSample* samples, int count) { plots->addSamples(samples, count); },
                   Qt::DirectConnection);
  QObject::connect(&session, &Session::armSamplesArrived, plots,
                   [&session, plots](const xmate::arm::ArmSample* samples, int count) {
                     if (plots->recordsArmSamples()) plots->addArmSamples(samples, count, extrasOf(session.live()));
                   },
                   Qt::DirectConnection);
  QObject::connect(&session, &Session::opened, plots, [&session, plots] { onOpened(session, plots); });
  QObject::connect(&session, &Session::commandFinished, plots,
                   [&session, plots](const QString&, bool ok, const QString&) {
                     if (ok) refreshTool(session, plots);
                   });
  if (session.isOpen()) onOpened(session, plots);
  return plots;
}

}  // namespace rci::ui
