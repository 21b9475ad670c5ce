// SPDX-License-Identifier: Apache-2.0
// createPlotsWidget (ui/window/parts.h): builds the live plot area and feeds it from a Session --
// samples on samplesArrived, the arm's joint count and J^T model (with the tool) when it opens.
#include <exception>

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

void onOpened(Session& session, plots::PlotsWidget* plots) {
  plots->clear();  // the session clock restarts at 0
  if (xmate::Robot* robot = session.robot()) plots->setJointCount(xmate::model::robotSpec(robot->type()).dof);
  plots->setExternalTorqueMap(makeTorqueMap(session));
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
  QObject::connect(&session, &Session::opened, plots, [&session, plots] { onOpened(session, plots); });
  QObject::connect(&session, &Session::commandFinished, plots,
                   [&session, plots](const QString&, bool ok, const QString&) {
                     if (ok) refreshTool(session, plots);
                   });
  if (session.isOpen()) onOpened(session, plots);
  return plots;
}

}  // namespace rci::ui
