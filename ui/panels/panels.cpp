// SPDX-License-Identifier: Apache-2.0
// createPanels (window/parts.h): builds every dock panel for a session and says where it docks:
// operation (power, jog, drag or hand guiding by the force sensor, IO, safety, simulator, force
// sensor, RSI) on the right; the Program panel (teach and replay, the operator's main tool, which
// keeps its Run bar in view and scrolls the rest itself) first on the left, then the settings editors.
#include "window/parts.h"

#include "panels/collision_panel.h"
#include "panels/drag_panel.h"
#include "panels/filters_panel.h"
#include "panels/force_guide_panel.h"
#include "panels/force_sensor_panel.h"
#include "panels/impedance_panel.h"
#include "panels/io_panel.h"
#include "panels/jog_panel.h"
#include "panels/power_panel.h"
#include "panels/program_panel.h"
#include "panels/rsi_panel.h"
#include "panels/safety_box_panel.h"
#include "panels/safety_panel.h"
#include "panels/simulator_panel.h"
#include "panels/soft_limits_panel.h"
#include "panels/tool_panel.h"

namespace rci::ui {

std::vector<PanelSpec> createPanels(Session& session, QWidget* parent) {
  std::vector<PanelSpec> panels;
  auto add = [&panels, &session](PanelBase* panel, Qt::DockWidgetArea area, bool scrolls_itself = false) {
    panels.push_back({panel->objectName(), panel->title(), panel, area, scrolls_itself,
                      [panel, &session] { return panel->appliesTo(session); }});
  };
  add(new PowerPanel(session, parent), Qt::RightDockWidgetArea);
  add(new JogPanel(session, parent), Qt::RightDockWidgetArea);
  add(new DragPanel(session, parent), Qt::RightDockWidgetArea);
  add(new ForceGuidePanel(session, parent), Qt::RightDockWidgetArea);
  add(new IoPanel(session, parent), Qt::RightDockWidgetArea);
  add(new SafetyPanel(session, parent), Qt::RightDockWidgetArea);
  add(new SimulatorPanel(session, parent), Qt::RightDockWidgetArea);
  add(new ForceSensorPanel(session, parent), Qt::RightDockWidgetArea);
  add(new RsiPanel(session, parent), Qt::RightDockWidgetArea);
  add(new ProgramPanel(session, parent), Qt::LeftDockWidgetArea, true);
  add(new CollisionPanel(session, parent), Qt::LeftDockWidgetArea);
  add(new SafetyBoxPanel(session, parent), Qt::LeftDockWidgetArea);
  add(new SoftLimitsPanel(session, parent), Qt::LeftDockWidgetArea);
  add(new FiltersPanel(session, parent), Qt::LeftDockWidgetArea);
  add(new ImpedancePanel(session, parent), Qt::LeftDockWidgetArea);
  add(new ToolPanel(session, parent), Qt::LeftDockWidgetArea);
  return panels;
}

}  // namespace rci::ui
