// SPDX-License-Identifier: Apache-2.0
// test_window_layout: the main window's layout on two offscreen screens, 1920x1080 and 1366x768
// (the offscreen platform's screens come from a config file written at start): where the window
// opens, its geometry remembered per screen size, the default dock sizes, every panel's controls
// without horizontal scrolling, the key controls in view, and the scroll-wheel guard.
#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProgressBar>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSlider>
#include <QSpinBox>
#include <QTableView>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QWheelEvent>

#include <memory>

#include "session/session.h"
#include "gui_test_support.h"
#include "window/main_window.h"
#include "window/window_geometry.h"

using namespace rci::ui;

namespace {

struct ScreenSize {
  const char* name;
  int width, height;
};
constexpr ScreenSize kSmall{"small", 1366, 768};
constexpr ScreenSize kLarge{"large", 1920, 1080};  // the preferred 1600x1000 fits

// Writes the offscreen platform's configuration: the small screen at the origin, the large one beside it.
QString writeScreensConfig(const QString& dir) {
  QJsonArray screens;
  int x = 0;
  for (const ScreenSize& s : {kSmall, kLarge}) {
    screens.append(QJsonObject{{"name", s.name}, {"x", x}, {"y", 0}, {"width", s.width}, {"height", s.height},
                               {"logicalDpi", 96}, {"logicalBaseDpi", 96}, {"dpr", 1.0}});
    x += s.width;
  }
  const QString path = dir + QStringLiteral("/screens.json");
  QFile file(path);
  if (!file.open(QIODevice::WriteOnly)) qFatal("cannot write %s", qPrintable(path));
  file.write(QJsonDocument(QJsonObject{{"screens", screens}}).toJson());
  return path;
}

QScreen* screenNamed(const char* name) {
  for (QScreen* screen : QGuiApplication::screens())
    if (screen->name() == QLatin1String(name)) return screen;
  qFatal("no offscreen screen named %s", name);
}

// The widget's rectangle in ancestor's coordinates.
QRect rectIn(const QWidget* w, const QWidget* ancestor) { return QRect(w->mapTo(ancestor, QPoint(0, 0)), w->size()); }

QScrollArea* scrollAreaOf(QWidget* w) {
  for (QWidget* p = w->parentWidget(); p; p = p->parentWidget())
    if (auto* area = qobject_cast<QScrollArea*>(p)) return area;
  return nullptr;
}

QDockWidget* dockOf(QWidget* w) {
  for (QWidget* p = w; p; p = p->parentWidget())
    if (auto* dock = qobject_cast<QDockWidget*>(p)) return dock;
  return nullptr;
}

// The narrowest a resizable scroll area lays out its widget (the width beyond which it scrolls).
int minimumWidth(const QWidget* w) { return std::max(w->minimumSizeHint().width(), w->minimumWidth()); }

void settle() {
  for (int i = 0; i < 5; ++i) QCoreApplication::processEvents();
}

}  // namespace

class TestWindowLayout : public QObject {
  Q_OBJECT

 private:
  // A window (and its session) opened on the named screen, shown and laid out. On the screen at
  // the origin (the small one) the window places itself, as in the program; on the other it is placed there.
  struct Opened {
    std::unique_ptr<Session> session = std::make_unique<Session>();
    std::unique_ptr<MainWindow> window;
  };
  Opened openOn(const ScreenSize& size) {
    Opened o;
    o.window = std::make_unique<MainWindow>(*o.session);
    if (o.window->screen() != screenNamed(size.name)) o.window->placeOnScreen(screenNamed(size.name));
    o.window->show();
    if (!QTest::qWaitForWindowExposed(o.window.get())) qWarning("window not exposed");
    settle();
    return o;
  }
  template <class T>
  T* find(MainWindow& window, const char* name) {
    T* w = window.findChild<T*>(QLatin1String(name));
    if (!w) qWarning("no widget named %s", name);
    return w;
  }
  // Brings the dock holding w to the front of its tabs.
  void raiseDockOf(QWidget* w) {
    QDockWidget* dock = dockOf(w);
    QVERIFY(dock);
    dock->show();
    dock->raise();
    settle();
  }
  void checkPanelsFit(MainWindow& window);
  void checkInView(MainWindow& window, const char* name, bool unscrolled);
  void checkKeyControls(MainWindow& window);
  void clearSettings() { QSettings(QStringLiteral("RCI Studio"), QStringLiteral("rci-studio")).clear(); }

 private slots:
  void init() { clearSettings(); }
  void opensAtPreferredSizeOnLargeScreen();
  void opensWithinSmallScreen();
  void defaultDockSizes_data();
  void defaultDockSizes();
  void panelsFitWithoutHorizontalScrolling_data();
  void panelsFitWithoutHorizontalScrolling();
  void kukaPanelsFitWithoutHorizontalScrolling_data();
  void kukaPanelsFitWithoutHorizontalScrolling();
  void keyControlsInView_data();
  void keyControlsInView();
  void programTypeColumnReadable();
  void wheelLeavesUnfocusedFieldsAlone();
  void geometryRememberedPerScreenSize();
  void geometryThatNoLongerFitsIsNotRestored();
};

void TestWindowLayout::opensAtPreferredSizeOnLargeScreen() {
  Opened o = openOn(kLarge);
  const QRect available = screenNamed(kLarge.name)->availableGeometry();
  QCOMPARE(o.window->size(), kPreferredWindowSize);
  QVERIFY(!o.window->isMaximized());
  QVERIFY2(available.contains(o.window->frameGeometry()), "the window lies outside the screen");
}

void TestWindowLayout::opensWithinSmallScreen() {
  Opened o = openOn(kSmall);
  const QRect available = screenNamed(kSmall.name)->availableGeometry();
  QCOMPARE(o.window->screen()->name(), QString(kSmall.name));
  QVERIFY2(available.contains(o.window->frameGeometry()),
           qPrintable(QStringLiteral("frame %1,%2 %3x%4")
                          .arg(o.window->frameGeometry().x())
                          .arg(o.window->frameGeometry().y())
                          .arg(o.window->frameGeometry().width())
                          .arg(o.window->frameGeometry().height())));
  // Nearly the whole screen: maximized.
  QVERIFY(o.window->isMaximized());
  QVERIFY(o.window->width() >= available.width() - 10 && o.window->height() >= available.height() - 10);
  // The status bar and the right-hand docks are on the screen.
  for (QDockWidget* dock : o.window->docks()) {
    if (dock->isHidden() || !o.window->rect().contains(dock->geometry().center())) continue;
    QVERIFY2(o.window->rect().contains(dock->geometry()), qPrintable(dock->objectName()));
  }
}

void TestWindowLayout::defaultDockSizes_data() {
  QTest::addColumn<int>("screen");
  QTest::newRow("1600x1000") << 0;
  QTest::newRow("1366x768") << 1;
}

// Side docks with room for their panels, the 3D view keeping about a third of the width, the plots
// 40 % of the height where the side panels keep room (less on the small screen).
void TestWindowLayout::defaultDockSizes() {
  QFETCH(int, screen);
  Opened o = openOn(screen == 0 ? kLarge : kSmall);
  MainWindow& w = *o.window;
  QDockWidget* left = nullptr;
  QDockWidget* right = nullptr;
  for (QDockWidget* dock : w.docks()) {
    if (dock->isHidden() || !w.rect().contains(dock->geometry().center())) continue;  // tabbed away
    if (w.dockWidgetArea(dock) == Qt::LeftDockWidgetArea) left = dock;
    if (w.dockWidgetArea(dock) == Qt::RightDockWidgetArea) right = dock;
  }
  QVERIFY(left && right);
  const QString sizes = QStringLiteral("left %1, right %2, view %3x%4, window %5x%6")
                            .arg(left->width())
                            .arg(right->width())
                            .arg(w.robotView()->width())
                            .arg(w.robotView()->height())
                            .arg(w.width())
                            .arg(w.height());
  QVERIFY2(left->width() >= defaultLeftDockWidth(w.width()) - 4, qPrintable(sizes));
  QVERIFY2(right->width() >= defaultRightDockWidth(w.width()) - 4, qPrintable(sizes));
  QVERIFY2(right->width() <= 0.4 * w.width() + 10, qPrintable(sizes));
  QVERIFY2(w.robotView()->width() >= w.width() / 3, qPrintable(sizes));
  QVERIFY2(w.robotView()->height() >= 240, qPrintable(sizes));
  const double plots_share = double(w.findChild<QDockWidget*>("dock.plots")->height()) / w.height();
  QVERIFY2(plots_share > (screen == 0 ? 0.36 : 0.25) && plots_share < 0.43, qPrintable(QString::number(plots_share)));
  // The side panels keep at least 400 px of height.
  QVERIFY2(left->height() >= 400 && right->height() >= 400, qPrintable(QString::number(left->height())));
}

void TestWindowLayout::panelsFitWithoutHorizontalScrolling_data() { defaultDockSizes_data(); }

// Every panel, brought to the front of its tabs, fits its dock's width: its scroll area needs no
// horizontal scroll bar (and a panel that scrolls itself fits the dock as it is).
void TestWindowLayout::checkPanelsFit(MainWindow& window) {
  for (QDockWidget* dock : window.docks()) {
    if (dock->objectName() == QLatin1String("dock.messages")) continue;  // a list, no form
    dock->show();
    dock->raise();
    settle();
    if (!qobject_cast<QScrollArea*>(dock->widget())) {
      const int needed = minimumWidth(dock->widget());
      QVERIFY2(needed <= dock->widget()->width(), qPrintable(QStringLiteral("%1 needs %2 px, has %3")
                                                                 .arg(dock->objectName())
                                                                 .arg(needed)
                                                                 .arg(dock->widget()->width())));
    }
    for (QScrollArea* area : dock->findChildren<QScrollArea*>()) {
      if (!area->widget() || !area->widgetResizable()) continue;
      const int needed = minimumWidth(area->widget());
      const QString what = QStringLiteral("%1 (%2) needs %3 px, its viewport is %4 px")
                               .arg(dock->objectName(), area->objectName())
                               .arg(needed)
                               .arg(area->viewport()->width());
      QVERIFY2(needed <= area->viewport()->width(), qPrintable(what));
      QVERIFY2(area->horizontalScrollBar()->maximum() == 0, qPrintable(what));
    }
  }
}

void TestWindowLayout::panelsFitWithoutHorizontalScrolling() {
  QFETCH(int, screen);
  Opened o = openOn(screen == 0 ? kLarge : kSmall);
  checkPanelsFit(*o.window);
}

void TestWindowLayout::kukaPanelsFitWithoutHorizontalScrolling_data() { defaultDockSizes_data(); }

// The same with a KUKA connected: the panels show its signals, limits and simulator controls.
void TestWindowLayout::kukaPanelsFitWithoutHorizontalScrolling() {
  QFETCH(int, screen);
  Opened o = openOn(screen == 0 ? kLarge : kSmall);
  o.window->connectTo(rci::ui::test::kukaSimulator());
  QTRY_VERIFY_WITH_TIMEOUT(o.session->isOpen() && o.session->live().has_arm_state, 30000);
  settle();
  checkPanelsFit(*o.window);
}

void TestWindowLayout::keyControlsInView_data() { defaultDockSizes_data(); }

// w lies within its scroll area's viewport (scrolled to vertically only where unscrolled is false)
// and within the window.
void TestWindowLayout::checkInView(MainWindow& window, const char* name, bool unscrolled) {
  QWidget* w = find<QWidget>(window, name);
  QVERIFY2(w, name);
  raiseDockOf(w);
  QVERIFY2(w->isVisible(), name);
  if (QScrollArea* area = scrollAreaOf(w)) {
    area->horizontalScrollBar()->setValue(0);
    if (unscrolled)
      area->verticalScrollBar()->setValue(0);
    else
      area->ensureWidgetVisible(w, 0, 0);
    settle();
    QCOMPARE(area->horizontalScrollBar()->value(), 0);
    const QRect in_viewport = rectIn(w, area->viewport());
    QVERIFY2(area->viewport()->rect().contains(in_viewport),
             qPrintable(QStringLiteral("%1 at %2,%3 %4x%5 is outside its viewport %6x%7")
                            .arg(QLatin1String(name))
                            .arg(in_viewport.x())
                            .arg(in_viewport.y())
                            .arg(in_viewport.width())
                            .arg(in_viewport.height())
                            .arg(area->viewport()->width())
                            .arg(area->viewport()->height())));
  }
  QVERIFY2(window.rect().contains(rectIn(w, &window)), qPrintable(QLatin1String(name) + " is outside the window"));
}

void TestWindowLayout::checkKeyControls(MainWindow& window) {
  // In view as the window opens: the Program panel's Run bar, power and hand guiding.
  for (const char* name : {"program.run", "program.step", "program.pause", "program.resume", "program.stop",
                           "program.speed", "program.progress", "power.on", "power.off", "drag.start", "drag.stop"}) {
    checkInView(window, name, true);
    if (QTest::currentTestFailed()) return;
  }
  // Reachable by scrolling down, never sideways: every jog button, error recovery.
  for (int j = 1; j <= 7; ++j)
    for (const char* sign : {"minus", "plus"}) {
      checkInView(window, qPrintable(QStringLiteral("jog.joint%1.%2").arg(j).arg(QLatin1String(sign))), false);
      if (QTest::currentTestFailed()) return;
    }
  for (const char* axis : {"x", "y", "z", "rx", "ry", "rz"})
    for (const char* sign : {"minus", "plus"}) {
      checkInView(window, qPrintable(QStringLiteral("jog.cart.%1.%2").arg(QLatin1String(axis), QLatin1String(sign))),
                  false);
      if (QTest::currentTestFailed()) return;
    }
  checkInView(window, "safety.recover", false);
}

void TestWindowLayout::keyControlsInView() {
  QFETCH(int, screen);
  Opened o = openOn(screen == 0 ? kLarge : kSmall);
  checkKeyControls(*o.window);
}

// The instruction list's Type column shows its longest type in full.
void TestWindowLayout::programTypeColumnReadable() {
  Opened o = openOn(kSmall);
  auto* table = o.window->findChild<QTableView*>("program.list");
  QVERIFY(table);
  raiseDockOf(table);
  const int type_column = 1;
  QCOMPARE(table->model()->headerData(type_column, Qt::Horizontal).toString(), QString("Type"));
  const int needed = table->fontMetrics().horizontalAdvance(QStringLiteral("WAIT_DI")) +
                     2 * table->style()->pixelMetric(QStyle::PM_FocusFrameHMargin) + 2;
  QVERIFY2(table->columnWidth(type_column) >= needed,
           qPrintable(QStringLiteral("%1 < %2").arg(table->columnWidth(type_column)).arg(needed)));
}

// A wheel turn over a spin box, slider or combo box without the focus leaves its value and
// scrolls the panel; once clicked into, the wheel changes the field.
void TestWindowLayout::wheelLeavesUnfocusedFieldsAlone() {
  Opened o = openOn(kSmall);
  MainWindow& w = *o.window;
  auto wheel = [](QWidget* target, int delta) {
    const QPoint local = target->rect().center();
    QWheelEvent event(local, target->mapToGlobal(local), QPoint(), QPoint(0, delta), Qt::NoButton, Qt::NoModifier,
                      Qt::NoScrollPhase, false);
    QApplication::sendEvent(target, &event);
  };

  auto* ms = find<QSpinBox>(w, "program.logicMs");
  QVERIFY(ms);
  raiseDockOf(ms);
  QScrollArea* area = scrollAreaOf(ms);
  QVERIFY(area);
  area->verticalScrollBar()->setValue(0);
  QVERIFY2(area->verticalScrollBar()->maximum() > 0, "the Program panel's editor area does not scroll at 1366x768");
  QCOMPARE(ms->focusPolicy(), Qt::StrongFocus);
  ms->setValue(500);
  w.activateWindow();
  find<QWidget>(w, "program.run")->setFocus();
  wheel(ms, -120);
  QCOMPARE(ms->value(), 500);
  QVERIFY2(area->verticalScrollBar()->value() > 0, "the wheel did not scroll the panel");

  for (const char* name : {"collision.threshold1", "jog.speed", "drag.space"}) {
    QWidget* field = find<QWidget>(w, name);
    QVERIFY2(field, name);
    raiseDockOf(field);
    QVERIFY2(!(field->focusPolicy() & Qt::WheelFocus & ~Qt::StrongFocus), name);
    auto value = [field] {
      if (auto* spin = qobject_cast<QDoubleSpinBox*>(field)) return spin->value();
      if (auto* slider = qobject_cast<QSlider*>(field)) return double(slider->value());
      return double(qobject_cast<QComboBox*>(field)->currentIndex());
    };
    if (auto* slider = qobject_cast<QSlider*>(field)) slider->setValue(50);
    if (auto* combo = qobject_cast<QComboBox*>(field)) combo->setCurrentIndex(0);
    if (auto* spin = qobject_cast<QDoubleSpinBox*>(field)) spin->setValue(spin->maximum() / 2);
    const double before = value();
    wheel(field, -120);
    QCOMPARE(value(), before);
  }

  // Clicked into, the spin box takes the wheel.
  raiseDockOf(ms);
  area->ensureWidgetVisible(ms);
  QTest::mouseClick(ms, Qt::LeftButton, {}, QPoint(8, ms->height() / 2));
  QVERIFY(ms->hasFocus());
  wheel(ms, -120);
  QVERIFY2(ms->value() < 500, qPrintable(QString::number(ms->value())));
}

// Each screen size keeps its own window geometry: a window moved and resized on the small screen
// opens there again, while the large screen keeps its default until changed there.
void TestWindowLayout::geometryRememberedPerScreenSize() {
  const QRect small = screenNamed(kSmall.name)->availableGeometry();
  const QRect large = screenNamed(kLarge.name)->availableGeometry();
  const QRect small_choice(small.topLeft() + QPoint(40, 30), QSize(1100, 650));
  const QRect large_choice(large.topLeft() + QPoint(60, 40), QSize(1500, 900));
  {
    Opened o = openOn(kSmall);
    o.window->showNormal();
    o.window->setGeometry(small_choice);
    settle();
    QVERIFY(o.window->close());
  }
  {
    Opened o = openOn(kLarge);
    QCOMPARE(o.window->size(), kPreferredWindowSize);  // not the small screen's choice
    o.window->setGeometry(large_choice);
    settle();
    QVERIFY(o.window->close());
  }
  {
    Opened o = openOn(kSmall);
    QVERIFY(!o.window->isMaximized());
    QCOMPARE(o.window->geometry(), small_choice);
  }
  {
    Opened o = openOn(kLarge);
    QCOMPARE(o.window->geometry(), large_choice);
  }
}

// A saved geometry larger than the screen now is (e.g. saved before a resolution change) is not
// restored: the window opens at the default for the screen.
void TestWindowLayout::geometryThatNoLongerFitsIsNotRestored() {
  const QRect small = screenNamed(kSmall.name)->availableGeometry();
  {
    QSettings s(QStringLiteral("RCI Studio"), QStringLiteral("rci-studio"));
    s.beginGroup(screenSizeGroup(small.size()));
    s.setValue("geometry", QRect(small.topLeft(), QSize(1600, 1000)));
    s.setValue("frame", QRect(small.topLeft(), QSize(1604, 1030)));
    s.setValue("maximized", false);
  }
  Opened o = openOn(kSmall);
  QVERIFY(small.contains(o.window->frameGeometry()));
  QVERIFY(o.window->isMaximized());
}

int main(int argc, char** argv) {
  // Settings and the screens of the offscreen platform in a throw-away folder.
  QTemporaryDir dir;
  if (!dir.isValid()) qFatal("no temporary folder");
  qputenv("QT_QPA_PLATFORM", ("offscreen:configfile=" + writeScreensConfig(dir.path())).toLocal8Bit());
  qputenv("XDG_STATE_HOME", dir.path().toLocal8Bit());
  QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, dir.path());
  QApplication app(argc, argv);
  applyStudioStyle();  // the program's style and font: the sizes measured are the operator's
  TestWindowLayout test;
  QTEST_SET_MAIN_SOURCE_PATH
  return QTest::qExec(&test, argc, argv);
}

#include "test_window_layout.moc"
