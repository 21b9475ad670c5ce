// SPDX-License-Identifier: Apache-2.0
// The main window's assembly, connection flow and layout persistence (main_window.h).
#include "window/main_window.h"

#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QProxyStyle>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QStatusBar>
#include <QStyleFactory>
#include <QStyleOptionDockWidget>
#include <QTabBar>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <map>

#include "text/operator_text.h"
#include "window/banner.h"
#include "window/connection_bar.h"
#include "window/message_log.h"
#include "window/parts.h"
#include "window/status_strip.h"
#include "window/target_settings.h"
#include "window/wheel_guard.h"
#include "window/window_geometry.h"

// The window's resources live in the static rci_ui library: register them once, explicitly.
static void initWindowResources() {
  static const bool registered = [] {
    Q_INIT_RESOURCE(rci_window);
    return true;
  }();
  (void)registered;
}

namespace rci::ui {
namespace {

constexpr int kLayoutVersion = 1;
constexpr double kSideDockMaxShare = 0.4;  // a side dock widens for its panel up to this share of the width
constexpr double kMinimumFontPoints = 9.5;

QSettings windowSettings() { return QSettings(QStringLiteral("RCI Studio"), QStringLiteral("rci-studio")); }

// Dock titles carry "&&" for a '&' (dock tabs and the View menu read '&' as a mnemonic marker), but
// the dock's own title bar draws its title as plain text: draw "&&" there as the '&' it stands for.
class DockTitleStyle : public QProxyStyle {
 public:
  using QProxyStyle::QProxyStyle;
  void drawControl(ControlElement element, const QStyleOption* option, QPainter* painter,
                   const QWidget* widget) const override {
    const auto* dock = qstyleoption_cast<const QStyleOptionDockWidget*>(option);
    if (element != CE_DockWidgetTitle || !dock || !dock->title.contains(QLatin1String("&&"))) {
      QProxyStyle::drawControl(element, option, painter, widget);
      return;
    }
    QStyleOptionDockWidget plain(*dock);
    plain.title.replace(QLatin1String("&&"), QLatin1String("&"));
    QProxyStyle::drawControl(element, &plain, painter, widget);
  }
};

// Panels and plots scroll inside their dock, so a tall one never forces the window taller than the screen.
QWidget* scrollable(QWidget* panel) {
  auto* area = new QScrollArea;
  area->setObjectName(panel->objectName() + QStringLiteral(".scroll"));
  area->setWidget(panel);
  area->setWidgetResizable(true);
  area->setFrameShape(QFrame::NoFrame);
  area->setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded);
  return area;
}

}  // namespace

QIcon applicationIcon() {
  initWindowResources();
  QIcon icon;
  icon.addFile(QStringLiteral(":/icons/rci-studio-48.png"));
  icon.addFile(QStringLiteral(":/icons/rci-studio-256.png"));
  icon.addFile(QStringLiteral(":/icons/rci-studio.svg"));  // used where the SVG image plugin exists
  return icon;
}

void applyStudioStyle() {
  QApplication::setStyle(new DockTitleStyle(QStyleFactory::create(QStringLiteral("Fusion"))));
  QApplication::setWindowIcon(applicationIcon());
  QFont font = QApplication::font();
  if (font.pointSizeF() < kMinimumFontPoints) font.setPointSizeF(kMinimumFontPoints);
  QApplication::setFont(font);
}

MainWindow::MainWindow(Session& session, QWidget* parent) : QMainWindow(parent), session_(session) {
  initWindowResources();
  installWheelGuard();
  setObjectName(QStringLiteral("mainWindow"));
  setWindowIcon(applicationIcon());
  setDockOptions(AnimatedDocks | AllowTabbedDocks | AllowNestedDocks);
  // Side panels get vertical tabs on the outer edge (full names, however many); the plots span
  // the whole width at the bottom.
  setTabPosition(Qt::LeftDockWidgetArea, QTabWidget::West);
  setTabPosition(Qt::RightDockWidgetArea, QTabWidget::East);
  setTabPosition(Qt::BottomDockWidgetArea, QTabWidget::North);
  setCorner(Qt::BottomLeftCorner, Qt::BottomDockWidgetArea);
  setCorner(Qt::BottomRightCorner, Qt::BottomDockWidgetArea);

  bar_ = new ConnectionBar(this);
  addToolBar(Qt::TopToolBarArea, bar_);
  buildCentre();
  buildDocks();
  strip_ = new StatusStrip(session_, statusBar());
  buildMenus();
  connectSession();

  default_state_ = saveState(kLayoutVersion);
  placeOnScreen(screen());
  if (std::optional<SessionTarget> last = lastTarget()) bar_->setTarget(*last);
  if (std::optional<QString> ini = robotFromIni()) {
    bar_->setRobotAddress(*ini);
    log_->addInfo(tr("Robot address %1 read from xmate.ini").arg(*ini));
  }
  updateTitle();
}

void MainWindow::buildCentre() {
  auto* centre = new QWidget(this);
  auto* layout = new QVBoxLayout(centre);
  layout->setContentsMargins(4, 4, 4, 0);
  layout->setSpacing(4);
  banner_ = new Banner(centre);
  view_ = createRobotView(session_, centre);
  view_->setMinimumSize(320, 240);
  layout->addWidget(banner_);
  layout->addWidget(view_, 1);
  setCentralWidget(centre);
}

QDockWidget* MainWindow::addDock(const QString& id, const QString& title, QWidget* widget, Qt::DockWidgetArea area) {
  // Dock tabs read '&' as a mnemonic marker: double it so "Tool & payload" shows as written.
  auto* dock = new QDockWidget(QString(title).replace(QLatin1Char('&'), QLatin1String("&&")), this);
  dock->setObjectName(id);
  dock->setWidget(widget);
  connect(dock, &QDockWidget::dockLocationChanged, this, [this] { QTimer::singleShot(0, this, [this] { showFullTabNames(); }); });
  dock->setFeatures(QDockWidget::DockWidgetClosable | QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable);
  addDockWidget(area, dock);
  docks_.push_back(dock);
  return dock;
}

void MainWindow::buildDocks() {
  QWidget* plots_widget = createPlotsWidget(session_, this);
  if (plots_widget->objectName().isEmpty()) plots_widget->setObjectName(QStringLiteral("plots"));
  QDockWidget* plots = addDock(QStringLiteral("dock.plots"), tr("Live plots"), scrollable(plots_widget),
                               Qt::BottomDockWidgetArea);
  log_ = new MessageLog(session_, this);
  QDockWidget* messages = addDock(QStringLiteral("dock.messages"), tr("Messages"), log_, Qt::BottomDockWidgetArea);
  tabifyDockWidget(plots, messages);

  // The first panel of each area; the others are tabbed with it.
  std::map<Qt::DockWidgetArea, QDockWidget*> first;
  first[Qt::BottomDockWidgetArea] = plots;
  for (const PanelSpec& spec : createPanels(session_, this)) {
    QWidget* content = spec.scrolls_itself ? spec.widget : scrollable(spec.widget);
    QDockWidget* dock = addDock(spec.id, spec.title, content, spec.area);
    if (spec.applies) gated_docks_.emplace_back(dock, spec.applies);
    auto [it, inserted] = first.emplace(spec.area, dock);
    if (!inserted) tabifyDockWidget(it->second, dock);
  }
  for (const auto& [area, dock] : first) dock->raise();
}

// The preferred width, or more when the dock's panel needs more to show without a horizontal scroll bar.
int MainWindow::sideDockWidth(QDockWidget* dock, int preferred) const {
  int needed = 0;
  if (auto* area = qobject_cast<QScrollArea*>(dock->widget()); area != nullptr && area->widget() != nullptr) {
    // The narrowest the scroll area lays the panel out: its size hint unless its policy lets it shrink.
    const QWidget* panel = area->widget();
    const bool shrinks = (panel->sizePolicy().horizontalPolicy() & QSizePolicy::ShrinkFlag) != 0;
    const int panel_width = std::max(panel->minimumWidth(), shrinks ? panel->minimumSizeHint().width() : panel->sizeHint().width());
    needed = panel_width + area->verticalScrollBar()->sizeHint().width() + 8;
  }
  const int limit = std::max(preferred, static_cast<int>(width() * kSideDockMaxShare));
  // The size given to resizeDocks also covers the area's vertical tab bar.
  return std::clamp(needed, preferred, limit) + sideTabBarWidth(dockWidgetArea(dock));
}

int MainWindow::sideTabBarWidth(Qt::DockWidgetArea area) const {
  const bool left = area == Qt::LeftDockWidgetArea;
  int width = 0;
  for (const QTabBar* tabs : findChildren<QTabBar*>(QString(), Qt::FindDirectChildrenOnly)) {
    const QTabBar::Shape shape = tabs->shape();
    const bool west = shape == QTabBar::RoundedWest || shape == QTabBar::TriangularWest;
    const bool east = shape == QTabBar::RoundedEast || shape == QTabBar::TriangularEast;
    if (tabs->isVisible() && (left ? west : east)) width = std::max(width, tabs->width());
  }
  return width;
}

int MainWindow::chromeHeight() const {
  return menuBar()->sizeHint().height() + bar_->sizeHint().height() + statusBar()->sizeHint().height();
}

void MainWindow::applyDefaultDockSizes() {
  // One dock per area is enough: tabbed docks share their area's size.
  QList<QDockWidget*> widths, heights;
  QList<int> width_sizes, height_sizes;
  bool left = false, right = false, bottom = false;
  for (QDockWidget* dock : docks_) {
    if (dock->isFloating() || dock->isHidden()) continue;
    const Qt::DockWidgetArea area = dockWidgetArea(dock);
    if (area == Qt::LeftDockWidgetArea && !left) {
      left = true;
      widths << dock;
      width_sizes << sideDockWidth(dock, defaultLeftDockWidth(width()));
    } else if (area == Qt::RightDockWidgetArea && !right) {
      right = true;
      widths << dock;
      width_sizes << sideDockWidth(dock, defaultRightDockWidth(width()));
    } else if (area == Qt::BottomDockWidgetArea && !bottom) {
      bottom = true;
      heights << dock;
      height_sizes << defaultPlotsHeight(height(), chromeHeight());
    }
  }
  if (!widths.isEmpty()) resizeDocks(widths, width_sizes, Qt::Horizontal);
  if (!heights.isEmpty()) resizeDocks(heights, height_sizes, Qt::Vertical);
}

void MainWindow::buildMenus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
  quit->setShortcut(QKeySequence::Quit);

  QMenu* connection = menuBar()->addMenu(tr("&Connection"));
  connection->addAction(tr("&Connect to the built-in simulator"), this, [this] {
    SessionTarget target;
    target.type = session_.target().type;
    target.loopback = true;
    connectTo(target);
  });
  connection->addAction(tr("&Disconnect"), this, [this] { disconnectFromTarget(); });

  // Stop motion: always within reach (toolbar, Connection menu, Esc anywhere in the window). It sets
  // the running motion's stop token at once: a program ramps down on its path, a jog ramps down.
  stop_motion_ = new QAction(tr("Stop motion"), this);
  stop_motion_->setObjectName(QStringLiteral("motion.stop"));
  stop_motion_->setShortcut(QKeySequence(Qt::Key_Escape));
  stop_motion_->setShortcutContext(Qt::ApplicationShortcut);
  stop_motion_->setToolTip(tr("Stop the running motion (program, go to or jog) smoothly on its path (Esc)"));
  connect(stop_motion_, &QAction::triggered, this, [this] { stopMotion(); });
  connection->addSeparator();
  connection->addAction(stop_motion_);
  bar_->addSeparator();
  bar_->addAction(stop_motion_);
  if (auto* button = bar_->widgetForAction(stop_motion_)) button->setObjectName(QStringLiteral("motion.stop.button"));

  QMenu* view = menuBar()->addMenu(tr("&View"));
  view->addAction(bar_->toggleViewAction());
  view->addSeparator();
  for (QDockWidget* dock : docks_) view->addAction(dock->toggleViewAction());
  view->addSeparator();
  view->addAction(tr("&Reset layout"), this, [this] { resetLayout(); });

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  help->addAction(tr("&About RCI Studio"), this, [this] {
    QMessageBox::about(this, tr("About RCI Studio"),
                       tr("<h3>RCI Studio %1</h3><p>Watch, teach and control ROKAE xMate robots over the RCI "
                          "real-time interface, or the built-in simulator.</p>")
                           .arg(QApplication::applicationVersion()));
  });
}

void MainWindow::showApplicablePanels() {
  for (const auto& [dock, applies] : gated_docks_) {
    const bool applicable = applies();
    dock->toggleViewAction()->setVisible(applicable);
    if (!applicable && !dock->isHidden()) {
      dock->hide();
      hidden_for_robot_.insert(dock);
    } else if (applicable && hidden_for_robot_.erase(dock) > 0) {
      dock->show();
    }
  }
}

void MainWindow::connectSession() {
  connect(bar_, &ConnectionBar::connectRequested, this, [this](const SessionTarget& target) { connectTo(target); });
  connect(bar_, &ConnectionBar::disconnectRequested, this, [this] { disconnectFromTarget(); });
  connect(bar_, &ConnectionBar::inputRefused, this, [this](const QString& reason) {
    banner_->showError(reason);
    log_->addError(reason);
  });
  connect(&session_, &Session::opened, this, [this] {
    showApplicablePanels();
    bar_->setState(ConnectionBar::State::kConnected);
    banner_->hide();
    strip_->refresh();
    updateTitle();
  });
  connect(&session_, &Session::openFailed, this, [this](const QString& reason) {
    bar_->setState(ConnectionBar::State::kDisconnected);
    banner_->showError(text::connectFailure(session_.target().describe(), reason));
    strip_->refresh();
    updateTitle();
  });
  connect(&session_, &Session::closed, this, [this](const QString& reason) {
    bar_->setState(ConnectionBar::State::kDisconnected);
    if (!reason.isEmpty()) banner_->showError(reason);
    strip_->refresh();
    updateTitle();
  });
  connect(&session_, &Session::tick, strip_, &StatusStrip::refresh);
}

void MainWindow::connectTo(const SessionTarget& target) {
  bar_->setTarget(target);
  if (target.kind == SessionTarget::Kind::kRobot) {
    rememberRobot(QStringLiteral("%1:%2").arg(target.host).arg(target.port));
    bar_->refreshRecent();
  }
  saveLastTarget(target);
  banner_->hide();
  session_.open(target);
  bar_->setState(ConnectionBar::State::kConnecting);
  strip_->showConnecting();
  log_->addInfo(tr("Connecting to %1 …").arg(target.describe()));
  updateTitle();
}

void MainWindow::disconnectFromTarget() {
  const bool was_opening = session_.isOpening();
  session_.close();
  if (was_opening) log_->addInfo(tr("Connection cancelled"));
  bar_->setState(ConnectionBar::State::kDisconnected);
  strip_->refresh();
  updateTitle();
}

void MainWindow::stopMotion() {
  if (!session_.isOpen()) return;
  if (!session_.live().motion_running) {
    log_->addInfo(tr("Stop motion: nothing is moving"));
    return;
  }
  session_.requestStop();
  log_->addWarning(tr("Stop motion pressed: the running motion ramps down and ends"));
}

void MainWindow::updateTitle() {
  QString title = QStringLiteral("RCI Studio");
  if (session_.isOpen()) title += QStringLiteral(" — ") + session_.target().describe();
  setWindowTitle(title);
}

void MainWindow::placeOnScreen(QScreen* screen) {
  if (!screen) screen = QGuiApplication::primaryScreen();
  setScreen(screen);
  const QRect available = screen->availableGeometry();
  const QString group = screenSizeGroup(available.size());
  if (!restoreGeometryFor(group, available)) {
    const WindowPlacement placement = defaultPlacement(available);
    setGeometry(placement.geometry);
    maximize_on_show_ = placement.maximized;
  }
  restoreDockLayout(group);
}

// The saved frame must lie within the available area; a maximized window keeps its normal
// geometry only if that fits too.
bool MainWindow::restoreGeometryFor(const QString& group, const QRect& available) {
  QSettings s = windowSettings();
  s.beginGroup(group);
  const QRect normal = s.value(QStringLiteral("geometry")).toRect();
  const QRect frame = s.value(QStringLiteral("frame")).toRect();
  const bool maximized = s.value(QStringLiteral("maximized"), false).toBool();
  if (!maximized && !(fitsAvailable(frame, available) && fitsAvailable(normal, available))) return false;
  setGeometry(fitsAvailable(normal, available) ? normal : available);
  maximize_on_show_ = maximized;
  return true;
}

// The layout saved on a screen of this size, sizes and all; else the last one saved anywhere for
// which docks are shown and tabbed, with default sizes for this screen.
void MainWindow::restoreDockLayout(const QString& group) {
  QSettings s = windowSettings();
  // Docks hidden only because the last robot lacked what they need come back for one that has it.
  const QStringList hidden_for_robot = s.value(QStringLiteral("window/hiddenForRobot")).toStringList();
  for (QDockWidget* dock : docks_)
    if (hidden_for_robot.contains(dock->objectName())) hidden_for_robot_.insert(dock);
  const QByteArray sized = s.value(group + QStringLiteral("/state")).toByteArray();
  layout_restored_ = !sized.isEmpty() && restoreState(sized, kLayoutVersion);
  if (layout_restored_) return;
  const QByteArray last = s.value(QStringLiteral("window/state")).toByteArray();
  restoreState(last.isEmpty() ? default_state_ : last, kLayoutVersion);
}

void MainWindow::saveLayout() {
  QSettings s = windowSettings();
  const QByteArray state = saveState(kLayoutVersion);
  s.setValue(QStringLiteral("window/state"), state);
  QStringList hidden_for_robot;
  for (const QDockWidget* dock : hidden_for_robot_) hidden_for_robot << dock->objectName();
  s.setValue(QStringLiteral("window/hiddenForRobot"), hidden_for_robot);
  s.beginGroup(screenSizeGroup(screen()->availableGeometry().size()));
  s.setValue(QStringLiteral("geometry"), normalGeometry());
  s.setValue(QStringLiteral("frame"), frameGeometry());
  s.setValue(QStringLiteral("maximized"), isMaximized());
  s.setValue(QStringLiteral("state"), state);
}

void MainWindow::resetLayout() {
  restoreState(default_state_, kLayoutVersion);
  hidden_for_robot_.clear();
  if (session_.isOpen()) showApplicablePanels();
  for (QDockWidget* dock : docks_) dock->setFloating(false);
  applyDefaultDockSizes();
  showFullTabNames();
}

// The dock tab bars are made by the main window's layout; let them scroll instead of eliding names.
void MainWindow::showFullTabNames() {
  for (QTabBar* tabs : findChildren<QTabBar*>(QString(), Qt::FindDirectChildrenOnly)) {
    tabs->setElideMode(Qt::ElideNone);
    tabs->setUsesScrollButtons(true);
  }
}

void MainWindow::setVisible(bool visible) {
  if (visible && maximize_on_show_) {
    maximize_on_show_ = false;
    setWindowState(windowState() | Qt::WindowMaximized);
  }
  QMainWindow::setVisible(visible);
}

void MainWindow::showEvent(QShowEvent* event) {
  QMainWindow::showEvent(event);
  showFullTabNames();
  if (shown_once_) return;
  shown_once_ = true;
  // Dock sizes need the window's real geometry: set them once it is laid out, unless restored.
  if (!layout_restored_) QTimer::singleShot(0, this, [this] { applyDefaultDockSizes(); });
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (!maybeSaveProgram(this)) {  // unsaved program: the user cancelled, or saving failed
    event->ignore();
    return;
  }
  saveLayout();
  session_.close();
  event->accept();
}

}  // namespace rci::ui
