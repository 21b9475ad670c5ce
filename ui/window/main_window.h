// SPDX-License-Identifier: Apache-2.0
// MainWindow: "RCI Studio" -- the 3D view in the centre, live plots and messages at the bottom,
// the panels in tabbed docks, the connection toolbar, the status bar. Opens within the screen's
// available area and persists its geometry per screen size, its dock layout and last target
// (QSettings "RCI Studio"/"rci-studio"). The Session is owned by the caller and outlives it.
#pragma once

#include <QIcon>
#include <QMainWindow>

#include <functional>
#include <set>
#include <utility>
#include <vector>

#include "session/session.h"

class QDockWidget;
class QScreen;

namespace rci::ui {

class Banner;
class ConnectionBar;
class MessageLog;
class StatusStrip;

// The RCI Studio icon (PNG sizes and the SVG), from the window's Qt resources.
QIcon applicationIcon();

// The application's look: Fusion style, the icon, a font of at least 9.5 pt (the program and the
// layout tests use the same, so the tests measure what the operator sees).
void applyStudioStyle();

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit MainWindow(Session& session, QWidget* parent = nullptr);

  // Shows target in the connection bar and connects to it (saves it as the last target).
  void connectTo(const SessionTarget& target);
  void disconnectFromTarget();

  // Opens on screen (before show): the geometry remembered for its available size if that still
  // fits, else the default placement (window_geometry.h); with it the dock layout saved there.
  // The constructor places the window on its default screen.
  void placeOnScreen(QScreen* screen);

  Session& session() { return session_; }
  QWidget* robotView() const { return view_; }
  MessageLog* messageLog() const { return log_; }
  Banner* banner() const { return banner_; }
  ConnectionBar* connectionBar() const { return bar_; }
  const std::vector<QDockWidget*>& docks() const { return docks_; }

 protected:
  void setVisible(bool visible) override;
  void closeEvent(QCloseEvent* event) override;
  void showEvent(QShowEvent* event) override;

 private:
  void buildCentre();
  QDockWidget* addDock(const QString& id, const QString& title, QWidget* widget, Qt::DockWidgetArea area);
  void buildDocks();
  void buildMenus();
  void connectSession();
  // Geometry remembered for the available area available (its settings group): true if restored.
  bool restoreGeometryFor(const QString& group, const QRect& available);
  void restoreDockLayout(const QString& group);
  void saveLayout();
  void resetLayout();
  // Gives the docks their default sizes (left panels, right panels, plots) for the current window size.
  void applyDefaultDockSizes();
  int sideDockWidth(QDockWidget* dock, int preferred) const;
  int chromeHeight() const;  // menu bar, toolbar and status bar
  int sideTabBarWidth(Qt::DockWidgetArea area) const;
  void updateTitle();
  void showFullTabNames();
  // After a session opened: hides the docks of panels that do not apply to its robot (and shows
  // again those hidden for an earlier one that apply now); their View menu entries follow.
  void showApplicablePanels();
  // Toolbar / Esc: asks the running motion to stop (Session::requestStop) and logs it.
  void stopMotion();

  Session& session_;
  QWidget* view_ = nullptr;
  Banner* banner_ = nullptr;
  ConnectionBar* bar_ = nullptr;
  MessageLog* log_ = nullptr;
  StatusStrip* strip_ = nullptr;
  QAction* stop_motion_ = nullptr;
  std::vector<QDockWidget*> docks_;
  std::vector<std::pair<QDockWidget*, std::function<bool()>>> gated_docks_;  // panels that may not apply
  std::set<QDockWidget*> hidden_for_robot_;  // hidden by showApplicablePanels, not by the operator
  QByteArray default_state_;
  bool layout_restored_ = false;  // a saved layout was restored: keep its dock sizes
  bool shown_once_ = false;
  bool maximize_on_show_ = false;  // placed maximized: applied when shown (it creates the native window)
};

}  // namespace rci::ui
