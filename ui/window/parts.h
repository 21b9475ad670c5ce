// SPDX-License-Identifier: Apache-2.0
// The pieces the main window is assembled from. Each area of ui/ implements its own factory here,
// so the window (ui/window) depends on these declarations only, not on the areas' classes.
#pragma once

#include <QImage>
#include <QString>
#include <QWidget>

#include <functional>
#include <vector>

namespace rci::ui {

class Session;

// ui/plots: the live plot area (signals, joints, time window, freeze, CSV export).
QWidget* createPlotsWidget(Session& session, QWidget* parent);

// ui/view3d: the 3D robot view (a placeholder when no GL context can be made, e.g. under the
// offscreen platform). captureRobotView renders the view to an image and calls done on the GUI
// thread (with a null image if the view is a placeholder or the capture failed).
QWidget* createRobotView(Session& session, QWidget* parent);
void captureRobotView(QWidget* view, std::function<void(const QImage&)> done);

// ui/panels: the dock panels (power, IO, safety, ...). The window puts each in a QDockWidget named
// by id (dock layout persistence) titled title, in area, tabbed with the others of that area,
// inside a scroll area unless the panel scrolls its own parts (e.g. to keep a button bar in view).
struct PanelSpec {
  QString id;      // stable object name, e.g. "panel.power"
  QString title;   // "Power"
  QWidget* widget = nullptr;
  Qt::DockWidgetArea area = Qt::RightDockWidgetArea;
  bool scrolls_itself = false;
  // Whether the panel applies to the open session (its dock is hidden otherwise); empty: always.
  std::function<bool()> applies;
};
std::vector<PanelSpec> createPanels(Session& session, QWidget* parent);
// ui/panels: before the window closes, offers to save a modified program (the Program panel under
// root). False if the user cancelled or the save failed: the window then stays open.
bool maybeSaveProgram(QWidget* root);

}  // namespace rci::ui
