// SPDX-License-Identifier: Apache-2.0
// test_safety_dock: the Safety panel in its dock of the whole window (offscreen, embedded lock-step
// simulator) -- after an injected collision the active error comes first in plain words with what
// to do, the Recover button lies inside the visible part of the dock at the default width and at
// 340 px, the status bar names the error plainly; a joint beyond the window's soft limit is shown
// with the joint, the amount and the way back.
#include <QAbstractButton>
#include <QAction>
#include <QDockWidget>
#include <QLabel>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include "gui_test_support.h"
#include "window_driver.h"
#include "panels/lamp.h"
#include "session/session.h"
#include "window/main_window.h"

using namespace rci::ui;
using rci::ui::test::lockstepSimulator;
using rci::ui::test::WindowDriver;

namespace {

constexpr int kWaitMs = 20000;  // a safety net for a loaded machine, not a timing claim
constexpr double kDegPerRad = 57.29577951308232;

}  // namespace

class TestSafetyDock : public QObject {
  Q_OBJECT

 private:
  template <class T>
  T* find(const QString& name) {
    return WindowDriver(window_).find<T>(name);
  }
  QString label(const QString& name) { return find<QLabel>(name)->text(); }
  bool lampOn(const QString& name) { return find<Lamp>(name)->isOn(); }
  QDockWidget* safetyDock() { return find<QDockWidget>(QStringLiteral("panel.safety")); }
  void raiseSafety() {
    safetyDock()->show();
    safetyDock()->raise();
    QTest::qWait(50);  // let the dock lay out its tab
  }
  // True when the whole Recover button lies inside what the dock's scroll area shows.
  bool recoverVisible(QString& why) {
    auto* area = find<QScrollArea>(QStringLiteral("panel.safety.scroll"));
    auto* recover = find<QAbstractButton>(QStringLiteral("safety.recover"));
    if (!area || !recover) return false;
    const QRect shown = area->viewport()->rect();
    const QRect button(recover->mapTo(area->viewport(), QPoint(0, 0)), recover->size());
    why = QStringLiteral("button %1,%2 %3x%4 in viewport %5x%6, dock width %7")
              .arg(button.x()).arg(button.y()).arg(button.width()).arg(button.height())
              .arg(shown.width()).arg(shown.height()).arg(safetyDock()->width());
    return recover->isVisible() && shown.contains(button);
  }

  QTemporaryDir dir_;
  Session* session_ = nullptr;
  MainWindow* window_ = nullptr;

 private slots:
  void initTestCase();
  void cleanupTestCase();
  void panelFitsANarrowDock();
  void collisionFirstAndRecoverVisible();
  void jointBeyondSoftLimitShown();
};

void TestSafetyDock::initTestCase() {
  QStandardPaths::setTestModeEnabled(true);
  QVERIFY(dir_.isValid());
  QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, dir_.path());
  qputenv("XDG_STATE_HOME", dir_.path().toUtf8());
  QSettings(QStringLiteral("RCI Studio"), QStringLiteral("rci-studio")).clear();
  session_ = new Session;
  window_ = new MainWindow(*session_);
  window_->show();
  QVERIFY(QTest::qWaitForWindowExposed(window_));
  // A 1600 x 1000 window whatever the (offscreen) screen's size, with the default dock sizes for it.
  window_->resize(1600, 1000);
  QTest::qWait(100);
  for (QAction* action : window_->findChildren<QAction*>())
    if (action->text() == QStringLiteral("&Reset layout")) action->trigger();
  QTest::qWait(100);
  QSignalSpy failed(session_, &Session::openFailed);
  window_->connectTo(lockstepSimulator());
  QTRY_VERIFY_WITH_TIMEOUT(session_->isOpen() || failed.count() > 0, kWaitMs);
  QVERIFY(session_->isOpen());
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().has_state, kWaitMs);
}

void TestSafetyDock::cleanupTestCase() {
  delete window_;
  delete session_;
}

void TestSafetyDock::panelFitsANarrowDock() {
  QWidget* panel = find<QWidget>(QStringLiteral("panel.safety"))->findChild<QScrollArea*>()->widget();
  QVERIFY(panel);
  QVERIFY2(panel->minimumSizeHint().width() <= 340, qPrintable(QString::number(panel->minimumSizeHint().width())));
  // The controller's names are no label text, only tooltips.
  QCOMPARE(label(QStringLiteral("safety.bitname15")), QStringLiteral("Collision detected"));
  QVERIFY(find<QLabel>(QStringLiteral("safety.bitname15"))->toolTip().contains(QStringLiteral("kCollision")));
}

void TestSafetyDock::collisionFirstAndRecoverVisible() {
  QSignalSpy done(session_, &Session::commandFinished);
  session_->run(QStringLiteral("Test: power on"), [](xmate::Robot& r) { r.setMotorPower(1); });
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().motor_state == 1, kWaitMs);
  session_->simulator()->setExternalWrench({250, 0, 0, 0, 0, 0});  // a hard push on the held arm
  QTRY_VERIFY_WITH_TIMEOUT(lampOn(QStringLiteral("safety.bit15")), kWaitMs);
  session_->simulator()->setExternalWrench({0, 0, 0, 0, 0, 0});
  raiseSafety();

  // Active errors first: the collision in words, with what to do, above the stop lamps.
  const QString details = label(QStringLiteral("safety.details"));
  QVERIFY2(details.contains(QStringLiteral("Collision detected")), qPrintable(details));
  QVERIFY2(details.contains(QStringLiteral("Power on in the Power panel")), qPrintable(details));
  QVERIFY2(!details.contains(QStringLiteral("kCollision")), qPrintable(details));
  auto* panel = find<QWidget>(QStringLiteral("panel.safety.scroll"))->findChild<QWidget*>(QStringLiteral("panel.safety"));
  const int details_y = find<QLabel>(QStringLiteral("safety.details"))->mapTo(panel, QPoint(0, 0)).y();
  const int recover_y = find<QWidget>(QStringLiteral("safety.recover"))->mapTo(panel, QPoint(0, 0)).y();
  const int estop_y = find<QWidget>(QStringLiteral("safety.estop"))->mapTo(panel, QPoint(0, 0)).y();
  QVERIFY(details_y < recover_y && recover_y < estop_y);

  QString why;
  QVERIFY2(recoverVisible(why), qPrintable(why));
  QVERIFY2(safetyDock()->width() >= 300, qPrintable(QString::number(safetyDock()->width())));  // the default
  window_->resizeDocks({safetyDock()}, {340}, Qt::Horizontal);
  QTest::qWait(50);
  QTRY_VERIFY2_WITH_TIMEOUT(recoverVisible(why), qPrintable(why), kWaitMs);
  QCOMPARE(find<QScrollArea>(QStringLiteral("panel.safety.scroll"))->horizontalScrollBar()->maximum(), 0);

  QTRY_VERIFY_WITH_TIMEOUT(label(QStringLiteral("status.errors")).contains(QStringLiteral("Collision detected")), kWaitMs);
  QVERIFY(!label(QStringLiteral("status.errors")).contains(QStringLiteral("kCollision")));

  QTest::mouseClick(find<QAbstractButton>(QStringLiteral("safety.recover")), Qt::LeftButton);
  QTRY_VERIFY_WITH_TIMEOUT(!lampOn(QStringLiteral("safety.bit15")), kWaitMs);
  QTRY_COMPARE_WITH_TIMEOUT(label(QStringLiteral("safety.details")), QStringLiteral("No errors."), kWaitMs);
}

void TestSafetyDock::jointBeyondSoftLimitShown() {
  // Soft limits the window recorded (not sent): J1 is 3° past its upper one.
  const double q1 = session_->live().state.q[0] * kDegPerRad;
  OperatorSettings settings = session_->operatorSettings();
  const OperatorSettings before = settings;
  settings.soft_limits_enabled = true;
  for (size_t j = 0; j < 7; ++j) {
    settings.soft_lower_deg[j] = -170;
    settings.soft_upper_deg[j] = 170;
  }
  settings.soft_upper_deg[0] = q1 - 3;
  session_->setOperatorSettings(settings);
  raiseSafety();
  QTRY_VERIFY_WITH_TIMEOUT(label(QStringLiteral("safety.details")).contains(QStringLiteral("J1 reached its upper soft limit")),
                           kWaitMs);
  const QString details = label(QStringLiteral("safety.details"));
  QVERIFY2(details.contains(QStringLiteral("J1 is 3.0° beyond its upper soft limit: Jog J1 \u2212")), qPrintable(details));
  session_->setOperatorSettings(before);
  QTRY_COMPARE_WITH_TIMEOUT(label(QStringLiteral("safety.details")), QStringLiteral("No errors."), kWaitMs);
}

QTEST_MAIN(TestSafetyDock)
#include "test_safety_dock.moc"
