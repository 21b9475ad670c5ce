// SPDX-License-Identifier: Apache-2.0
// test_kuka_panels: the RSI and Force sensor panels on a Session with the built-in KUKA simulator
// (RSI running, the context's objects and limits, the simulated sensor's wrench and the display's
// zero), and that neither applies to an xMate session.
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <cmath>

#include "gui_test_support.h"
#include "panels/force_sensor_panel.h"
#include "panels/lamp.h"
#include "panels/rsi_panel.h"
#include "session/session.h"
#include "sim/krc_server.h"

using namespace rci::ui;

namespace {

constexpr int kWaitMs = 20000;  // a safety net for a loaded machine, not a timing claim

}  // namespace

class TestKukaPanels : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase();
  void cleanupTestCase();
  void rsiPanelShowsSessionAndContext();
  void forcePanelShowsWrenchAndZero();
  void neitherAppliesToXmate();

 private:
  template <class T>
  T* find(const QString& name) {
    return host_->findChild<T*>(name);
  }
  QString text(const QString& name) {
    auto* label = find<QLabel>(name);
    return label ? label->text() : QStringLiteral("<no %1>").arg(name);
  }
  double value(const QString& name) {
    auto* label = find<QLabel>(name);
    return label ? label->property("value").toDouble() : NAN;
  }
  bool open(const SessionTarget& target) {
    QSignalSpy failed(session_, &Session::openFailed);
    session_->open(target);
    if (!QTest::qWaitFor([&] { return session_->isOpen() || !failed.isEmpty(); }, kWaitMs)) return false;
    if (!failed.isEmpty()) qWarning("%s", qPrintable(failed.first().first().toString()));
    return session_->isOpen();
  }

  QTemporaryDir settings_dir_;
  Session* session_ = nullptr;
  QWidget* host_ = nullptr;
  RsiPanel* rsi_ = nullptr;
  ForceSensorPanel* force_ = nullptr;
};

void TestKukaPanels::initTestCase() {
  QVERIFY(settings_dir_.isValid());
  test::usePrivateSettings(settings_dir_.path());
  session_ = new Session;
  host_ = new QWidget;
  rsi_ = new RsiPanel(*session_, host_);
  force_ = new ForceSensorPanel(*session_, host_);
  auto* layout = new QVBoxLayout(host_);
  layout->addWidget(rsi_);
  layout->addWidget(force_);
  host_->resize(380, 1400);
  host_->show();
  QCOMPARE(rsi_->objectName(), QStringLiteral("panel.rsi"));
  QCOMPARE(force_->objectName(), QStringLiteral("panel.force"));
  QVERIFY(!rsi_->appliesTo(*session_));  // nothing open
  QVERIFY(!force_->appliesTo(*session_));
  QVERIFY(open(test::kukaSimulator()));
}

void TestKukaPanels::cleanupTestCase() {
  delete host_;
  delete session_;
}

void TestKukaPanels::rsiPanelShowsSessionAndContext() {
  QVERIFY(rsi_->appliesTo(*session_));
  QTRY_VERIFY2_WITH_TIMEOUT(text(QStringLiteral("rsi.state")).contains(QStringLiteral("running")),
                            qPrintable(text(QStringLiteral("rsi.state"))), kWaitMs);
  QVERIFY(find<Lamp>(QStringLiteral("rsi.lamp"))->isOn());
  QTRY_COMPARE_WITH_TIMEOUT(text(QStringLiteral("rsi.cycle")), QStringLiteral("4 ms"), kWaitMs);
  QCOMPARE(text(QStringLiteral("rsi.contextFile")), QStringLiteral("rci_replay.rsi.xml"));
  QCOMPARE(text(QStringLiteral("rsi.configFile")), QStringLiteral("RSI_EthernetConfig.xml"));
  QVERIFY2(text(QStringLiteral("rsi.listen")).startsWith(QStringLiteral("127.0.0.1, port ")),
           qPrintable(text(QStringLiteral("rsi.listen"))));

  // The context's objects, by ID and type, with their settings.
  auto* objects = find<QTreeWidget>(QStringLiteral("rsi.objects"));
  QVERIFY(objects);
  QCOMPARE(objects->topLevelItemCount(), 8);
  const QList<QTreeWidgetItem*> axiscorr = objects->findItems(QStringLiteral("AXISCORR1"), Qt::MatchExactly, 0);
  QCOMPARE(axiscorr.size(), 1);
  QCOMPARE(axiscorr.first()->text(1), QStringLiteral("AXISCORR"));
  QVERIFY2(axiscorr.first()->text(2).contains(QStringLiteral("LowerLimA1-6 = -90")),
           qPrintable(axiscorr.first()->text(2)));
  const QList<QTreeWidgetItem*> ethernet = objects->findItems(QStringLiteral("ETHERNET1"), Qt::MatchExactly, 0);
  QCOMPARE(ethernet.size(), 1);
  QVERIFY(ethernet.first()->text(2).contains(QStringLiteral("Timeout = 100")));

  // The correction limits as set in the context (+-90 deg), the Timeout and the start pose.
  for (int axis = 1; axis <= 6; ++axis) {
    QCOMPARE(text(QStringLiteral("rsi.lower%1").arg(axis)), QStringLiteral("-90") + QChar(0x00B0));
    QCOMPARE(text(QStringLiteral("rsi.upper%1").arg(axis)), QStringLiteral("90") + QChar(0x00B0));
  }
  QVERIFY2(text(QStringLiteral("rsi.timeout")).contains(QStringLiteral("100 late answers")),
           qPrintable(text(QStringLiteral("rsi.timeout"))));
  // The simulated KRC switches RSI on at A1..A6 = 0, -90, 90, 0, 90, 0.
  QTRY_COMPARE_WITH_TIMEOUT(text(QStringLiteral("rsi.start2")), QStringLiteral("-90.0") + QChar(0x00B0), kWaitMs);
  QCOMPARE(text(QStringLiteral("rsi.start3")), QStringLiteral("90.0") + QChar(0x00B0));

  // The values exchanged: what comes from the robot and what goes to it.
  auto* channels = find<QTreeWidget>(QStringLiteral("rsi.channels"));
  QVERIFY(channels);
  QCOMPARE(channels->topLevelItemCount(), 2);
  QCOMPARE(channels->topLevelItem(0)->childCount(), 22);  // SEND
  QCOMPARE(channels->topLevelItem(1)->childCount(), 16);  // RECEIVE
  QCOMPARE(channels->topLevelItem(1)->child(1)->text(0), QStringLiteral("AK.A1"));
  QCOMPARE(channels->topLevelItem(1)->child(1)->text(2), QStringLiteral("1"));
  QCOMPARE(channels->topLevelItem(1)->child(0)->text(2), QStringLiteral("built in"));
  // No technology values in this config, and the smartPAD message channel is named.
  QVERIFY(text(QStringLiteral("rsi.tech")).contains(QStringLiteral("no technology values")));
  QVERIFY(text(QStringLiteral("rsi.messages")).contains(QStringLiteral("smartPAD")));
}

void TestKukaPanels::forcePanelShowsWrenchAndZero() {
  QVERIFY(force_->appliesTo(*session_));
  QVERIFY(text(QStringLiteral("force.address")).contains(QStringLiteral("simulator")));
  // The simulated sensor reads the arm's external wrench in the flange frame.
  session_->kukaSimulator()->krc().setExternalWrench({0, 0, -20, 0, 0, 0});
  auto magnitude = [this] {
    return std::hypot(value(QStringLiteral("force.fx")), value(QStringLiteral("force.fy")),
                      value(QStringLiteral("force.fz")));
  };
  QTRY_VERIFY2_WITH_TIMEOUT(std::abs(magnitude() - 20) < 1, qPrintable(text(QStringLiteral("force.state"))), kWaitMs);
  QVERIFY(find<Lamp>(QStringLiteral("force.lamp"))->isOn());
  QCOMPARE(text(QStringLiteral("force.state")), QStringLiteral("Readings arrive."));

  // The display's zero: the push now reads ~0, and a further push shows as the change only.
  auto* bias = find<QPushButton>(QStringLiteral("force.bias"));
  QVERIFY(bias && bias->isEnabled());
  QTest::mouseClick(bias, Qt::LeftButton);
  QTRY_VERIFY_WITH_TIMEOUT(magnitude() < 0.5, kWaitMs);
  session_->kukaSimulator()->krc().setExternalWrench({0, 0, -30, 0, 0, 0});
  QTRY_VERIFY_WITH_TIMEOUT(std::abs(magnitude() - 10) < 1, kWaitMs);
  // Clearing the zero shows the sensor's reading again.
  auto* clear = find<QPushButton>(QStringLiteral("force.clearBias"));
  QVERIFY(clear && clear->isEnabled());
  QTest::mouseClick(clear, Qt::LeftButton);
  QTRY_VERIFY_WITH_TIMEOUT(std::abs(magnitude() - 30) < 1, kWaitMs);
  session_->kukaSimulator()->krc().setExternalWrench({0, 0, 0, 0, 0, 0});
}

void TestKukaPanels::neitherAppliesToXmate() {
  QVERIFY(open(test::lockstepSimulator()));
  QVERIFY(!rsi_->appliesTo(*session_));
  QVERIFY(!force_->appliesTo(*session_));
  // Opening the xMate closed the KUKA session: the panels no longer show it.
  QCOMPARE(find<QTreeWidget>(QStringLiteral("rsi.objects"))->topLevelItemCount(), 0);
  QVERIFY(!find<Lamp>(QStringLiteral("force.lamp"))->isOn());
  session_->close();
}

QTEST_MAIN(TestKukaPanels)
#include "test_kuka_panels.moc"
