// SPDX-License-Identifier: Apache-2.0
// test_main_window: the whole RCI Studio window (offscreen) against the embedded lock-step
// simulator: connect, power on through the Power panel, status bar, DO->DI loop-back, an injected
// collision in the Safety panel, drag changing the robot mode, refused input, disconnect, a
// controller that stops answering, and the layout and last target persisting.
#include <QAbstractButton>
#include <QComboBox>
#include <QDockWidget>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>

#include "gui_test_support.h"
#include "window_driver.h"
#include "session/session.h"
#include "window/banner.h"
#include "window/connection_bar.h"
#include "window/main_window.h"
#include "window/message_log.h"

using namespace rci::ui;

using rci::ui::test::lockstepSimulator;
using rci::ui::test::WindowDriver;
using rci::ui::test::unusedPort;

namespace {

constexpr int kWaitMs = 20000;  // a safety net for a loaded machine, not a timing claim

}  // namespace

class TestMainWindow : public QObject {
  Q_OBJECT

 private:
  template <class T>
  T* find(const QString& name) {
    return WindowDriver(window_).find<T>(name);
  }
  QString label(const QString& name) { return find<QLabel>(name)->text(); }
  bool lampOn(const QString& name) { return find<QWidget>(name)->property("on").toBool(); }
  // Brings the dock holding the button to the front (docks are tabbed), then clicks it.
  void click(const QString& name) { QVERIFY2(WindowDriver(window_).click(name), qPrintable(name)); }
  void connectSimulator();

  QTemporaryDir state_dir_;
  Session* session_ = nullptr;
  MainWindow* window_ = nullptr;

 private slots:
  void initTestCase();
  void cleanupTestCase();
  void startsAndConnects();
  void powerOnShowsInStatusBar();
  void digitalOutputLoopsBack();
  void collisionShowsInSafetyPanel();
  void dragChangesRobotMode();
  void invalidInputRefused();
  void refusedConnectionShowsReason();
  void disconnectAndReconnect();
  void silentControllerReported();
  void layoutAndTargetPersist();
  void readsRobotAddressFromXmateIni();
};

void TestMainWindow::initTestCase() {
  QStandardPaths::setTestModeEnabled(true);
  QVERIFY(state_dir_.isValid());
  qputenv("XDG_STATE_HOME", state_dir_.path().toUtf8());  // the event log file goes there
  QSettings(QStringLiteral("RCI Studio"), QStringLiteral("rci-studio")).clear();
  session_ = new Session;
  window_ = new MainWindow(*session_);
  window_->show();
  QVERIFY(QTest::qWaitForWindowExposed(window_));
}

void TestMainWindow::cleanupTestCase() {
  delete window_;
  delete session_;
}

void TestMainWindow::connectSimulator() {
  QSignalSpy failed(session_, &Session::openFailed);
  window_->connectTo(lockstepSimulator());
  QCOMPARE(find<QAbstractButton>("connection.connect")->text(), QString("Cancel"));
  QTRY_VERIFY_WITH_TIMEOUT(session_->isOpen() || failed.count() > 0, kWaitMs);
  QVERIFY2(session_->isOpen(), failed.isEmpty() ? "" : qPrintable(failed.first().first().toString()));
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().has_state, kWaitMs);
}

void TestMainWindow::startsAndConnects() {
  QCOMPARE(window_->windowTitle(), QString("RCI Studio"));
  QVERIFY(!applicationIcon().pixmap(48).isNull());
  QVERIFY(!window_->windowIcon().isNull());
  QVERIFY(window_->robotView() != nullptr);
  QVERIFY(find<QDockWidget>("dock.plots"));
  QVERIFY(find<QDockWidget>("dock.messages"));
  QVERIFY(find<QDockWidget>("panel.power"));
  QVERIFY(window_->docks().size() >= 3);
  QCOMPARE(label("status.target"), QString("Not connected"));
  connectSimulator();
  QCOMPARE(find<QAbstractButton>("connection.connect")->text(), QString("Disconnect"));
  QCOMPARE(window_->windowTitle(), QString("RCI Studio — Simulator (xMate7 Pro)"));
  QTRY_COMPARE_WITH_TIMEOUT(label("status.target"), QString("Simulator (xMate7 Pro)"), kWaitMs);
  QTRY_COMPARE_WITH_TIMEOUT(label("status.mode"), QString("Mode: Idle"), kWaitMs);
  QTRY_COMPARE_WITH_TIMEOUT(label("status.motors"), QString("Motors off"), kWaitMs);
  QTRY_VERIFY_WITH_TIMEOUT(label("status.rate").endsWith(" Hz") && label("status.rate") != "0 Hz", kWaitMs);
  QVERIFY(label("status.realtime").startsWith("RT: "));
  QVERIFY(!find<QLabel>("status.realtime")->toolTip().isEmpty());
  QVERIFY(label("status.jitter").startsWith("Jitter p99 "));
  QVERIFY(window_->messageLog()->find("Connected to Simulator") >= 0);
}

void TestMainWindow::powerOnShowsInStatusBar() {
  click("power.on");
  QTRY_VERIFY_WITH_TIMEOUT(lampOn("power.lamp"), kWaitMs);
  QTRY_COMPARE_WITH_TIMEOUT(label("status.motors"), QString("Motors on"), kWaitMs);
}

void TestMainWindow::digitalOutputLoopsBack() {
  QVERIFY(!lampOn("io.di1"));
  click("io.do1");
  QTRY_VERIFY_WITH_TIMEOUT(lampOn("io.di1"), kWaitMs);
  click("io.do1");
  QTRY_VERIFY_WITH_TIMEOUT(!lampOn("io.di1"), kWaitMs);
}

void TestMainWindow::collisionShowsInSafetyPanel() {
  QVERIFY(!lampOn("safety.bit15"));
  find<QDoubleSpinBox>("sim.fx")->setValue(250);  // a hard push on the held arm trips the detection
  click("sim.wrench.apply");
  QTRY_VERIFY_WITH_TIMEOUT(lampOn("safety.bit15"), kWaitMs);
  QVERIFY(label("safety.details").contains("Collision detected"));
  QTRY_VERIFY_WITH_TIMEOUT(label("status.errors").contains("Collision detected"), kWaitMs);
  QVERIFY(find<QLabel>("status.errors")->isVisible());
  QTRY_COMPARE_WITH_TIMEOUT(label("status.motors"), QString("Motors off"), kWaitMs);

  click("sim.wrench.release");
  click("safety.recover");
  QTRY_VERIFY_WITH_TIMEOUT(!lampOn("safety.bit15"), kWaitMs);
  QTRY_VERIFY_WITH_TIMEOUT(!find<QLabel>("status.errors")->isVisible(), kWaitMs);
  click("power.on");
  QTRY_COMPARE_WITH_TIMEOUT(label("status.motors"), QString("Motors on"), kWaitMs);
}

void TestMainWindow::dragChangesRobotMode() {
  auto* space = find<QComboBox>("drag.space");
  space->setCurrentIndex(space->findData(1));  // joint space, free
  click("drag.start");
  QTRY_COMPARE_WITH_TIMEOUT(label("status.mode"), QString("Mode: Hand guiding"), kWaitMs);
  QTRY_VERIFY_WITH_TIMEOUT(lampOn("drag.lamp"), kWaitMs);
  click("drag.stop");
  QTRY_COMPARE_WITH_TIMEOUT(label("status.mode"), QString("Mode: Idle"), kWaitMs);
}

void TestMainWindow::invalidInputRefused() {
  // A collision threshold above the joint's maximum: refused in the panel, nothing sent.
  QSignalSpy sent(session_, &Session::commandFinished);
  find<QDoubleSpinBox>("collision.threshold3")->setValue(90);  // J3 allows at most 60 Nm
  click("collision.apply");
  QVERIFY(find<QLabel>("collision.message")->text().contains("60"));
  QTest::qWait(300);
  QCOMPARE(sent.count(), 0);
  find<QDoubleSpinBox>("collision.threshold3")->setValue(60);

  // A robot address that is not HOST:PORT: the banner says why, nothing connects.
  window_->disconnectFromTarget();
  QVERIFY(!session_->isOpen());
  find<QComboBox>("connection.kind")->setCurrentIndex(1);
  find<QComboBox>("connection.robot")->setEditText("192.168.0.160");
  click("connection.connect");
  QVERIFY(!session_->isOpening());
  QVERIFY(window_->banner()->isVisible());
  QVERIFY2(window_->banner()->text().contains("HOST:PORT"), qPrintable(window_->banner()->text()));
  find<QComboBox>("connection.robot")->setEditText("192.168.0.160:99999");
  click("connection.connect");
  QVERIFY(!session_->isOpening());
  QVERIFY2(window_->banner()->text().contains("65535"), qPrintable(window_->banner()->text()));
}

void TestMainWindow::refusedConnectionShowsReason() {
  const uint16_t port = unusedPort();
  find<QComboBox>("connection.kind")->setCurrentIndex(1);
  find<QComboBox>("connection.robot")->setEditText(QString("127.0.0.1:%1").arg(port));
  QSignalSpy failed(session_, &Session::openFailed);
  click("connection.connect");
  QTRY_VERIFY_WITH_TIMEOUT(failed.count() == 1, kWaitMs);
  QVERIFY(window_->banner()->isVisible());
  QVERIFY2(window_->banner()->text().contains(QString("127.0.0.1:%1").arg(port)), qPrintable(window_->banner()->text()));
  QCOMPARE(find<QAbstractButton>("connection.connect")->text(), QString("Connect"));
  QCOMPARE(label("status.target"), QString("Not connected"));
  QVERIFY(find<QComboBox>("connection.robot")->findText(QString("127.0.0.1:%1").arg(port)) >= 0);  // recent list
}

void TestMainWindow::disconnectAndReconnect() {
  find<QComboBox>("connection.kind")->setCurrentIndex(0);
  connectSimulator();
  QVERIFY(!window_->banner()->isVisible());
  click("connection.connect");  // "Disconnect"
  QVERIFY(!session_->isOpen());
  QCOMPARE(find<QAbstractButton>("connection.connect")->text(), QString("Connect"));
  QCOMPARE(label("status.target"), QString("Not connected"));
  QCOMPARE(window_->windowTitle(), QString("RCI Studio"));
  connectSimulator();
}

void TestMainWindow::silentControllerReported() {
  QVERIFY(session_->isOpen());
  session_->simulator()->kill();
  QTRY_VERIFY_WITH_TIMEOUT(!session_->isOpen(), kWaitMs);
  QVERIFY(window_->banner()->isVisible());
  QVERIFY2(window_->banner()->text().contains("stopped"), qPrintable(window_->banner()->text()));
  QCOMPARE(find<QAbstractButton>("connection.connect")->text(), QString("Connect"));
  const MessageLog* log = window_->messageLog();
  QVERIFY(log->text(log->count() - 1).contains("stopped"));
}

void TestMainWindow::layoutAndTargetPersist() {
  find<QDockWidget>("dock.messages")->hide();
  window_->close();  // saves geometry, dock layout
  Session other_session;
  MainWindow other(other_session);
  QVERIFY(other.findChild<QDockWidget*>("dock.messages")->isHidden());
  QVERIFY(!other.findChild<QDockWidget*>("dock.plots")->isHidden());
  // The last target was the simulator (reconnected above) with the robot address still listed.
  QCOMPARE(other.findChild<QComboBox*>("connection.kind")->currentIndex(), 0);
  QVERIFY(other.findChild<QComboBox*>("connection.robot")->count() >= 1);
}

void TestMainWindow::readsRobotAddressFromXmateIni() {
  QTemporaryDir dir;
  QVERIFY(dir.isValid());
  QFile ini(dir.filePath("xmate.ini"));
  QVERIFY(ini.open(QIODevice::WriteOnly));
  ini.write("[network]\nip = 10.1.2.3\nport = 1338\n");
  ini.close();
  const QString before = QDir::currentPath();
  QDir::setCurrent(dir.path());
  Session other_session;
  MainWindow other(other_session);
  QDir::setCurrent(before);
  QCOMPARE(other.findChild<QComboBox*>("connection.robot")->currentText(), QString("10.1.2.3:1338"));
  QVERIFY(other.messageLog()->text(other.messageLog()->count() - 1).contains("xmate.ini"));
}

QTEST_MAIN(TestMainWindow)
#include "test_main_window.moc"
