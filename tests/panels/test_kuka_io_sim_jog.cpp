// SPDX-License-Identifier: Apache-2.0
// test_kuka_io_sim_jog: the IO, Simulator and Jog panels on a session with the built-in KUKA simulator
// (a KR 6 R900 sixx running the sample RSI context), driven with QTest: $OUT / $IN, the push at the
// flange, an RSITimeout and RSI's restart, and the joint jog within the correction limits.
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QSlider>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <functional>

#include "arm/rsi_arm.h"
#include "gui_test_support.h"
#include "jog/jog.h"
#include "panels/fields.h"
#include "panels/lamp.h"
#include "session/session.h"
#include "sim/krc_server.h"
#include "window/parts.h"
#include "window_driver.h"

using namespace rci::ui;

namespace {

constexpr int kWaitMs = 20000;  // a safety net for a loaded machine, not a timing claim
constexpr double kDeg = 3.14159265358979323846 / 180.0;

}  // namespace

class TestKukaIoSimJog : public QObject {
  Q_OBJECT

 private:
  template <class T>
  T* find(const QString& name) {
    return test::WindowDriver(host_).find<T>(name);
  }
  bool lampOn(const QString& name) {
    auto* lamp = find<Lamp>(name);
    return lamp && lamp->isOn();
  }
  void click(const QString& name) { QVERIFY2(test::WindowDriver(host_).click(name), qPrintable(name)); }
  QString statusText(const QString& panel) { return find<QLabel>(panel + QStringLiteral(".status"))->text(); }
  xmate::sim::Krc& krc() { return session_->kukaSimulator()->krc(); }
  void waitRunning() {
    QTRY_VERIFY_WITH_TIMEOUT(session_->live().rsi.phase == xmate::rsi::SessionPhase::kRunning, kWaitMs);
  }

  QTemporaryDir settings_dir_;
  Session* session_ = nullptr;
  QWidget* host_ = nullptr;
  std::vector<PanelSpec> panels_;
  void holdCartesian(const QString& button, int ms);

 private slots:
  void initTestCase();
  void cleanupTestCase();
  void panelsApply();
  void outputSwitchSetsKukaOutput();
  void simulatedInputLightsLamp();
  void pushSetsWrench();
  void jointJogStopsAtCorrectionLimit();
  void cartesianJogMovesTheFlange();
  void stopAnsweringStopsAndRestartsRsi();
};

void TestKukaIoSimJog::initTestCase() {
  QVERIFY(settings_dir_.isValid());
  test::usePrivateSettings(settings_dir_.path());
  session_ = new Session;
  host_ = new QWidget;
  panels_ = createPanels(*session_, host_);
  auto* layout = new QVBoxLayout(host_);
  for (const auto& p : panels_) layout->addWidget(p.widget);
  host_->show();

  QSignalSpy failed(session_, &Session::openFailed);
  session_->open(test::kukaSimulator());
  QTRY_VERIFY_WITH_TIMEOUT(session_->isOpen() || failed.count() > 0, kWaitMs);
  QVERIFY2(session_->isOpen(), failed.isEmpty() ? "" : qPrintable(failed.first().first().toString()));
  QVERIFY(session_->kukaSimulator() != nullptr);
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().has_arm_state, kWaitMs);
  waitRunning();
}

void TestKukaIoSimJog::cleanupTestCase() {
  delete host_;
  delete session_;
}

void TestKukaIoSimJog::panelsApply() {
  for (const auto& p : panels_) {
    if (p.id == QLatin1String("panel.io") || p.id == QLatin1String("panel.simulator") ||
        p.id == QLatin1String("panel.jog"))
      QVERIFY2(p.applies && p.applies(), qPrintable(p.id));
  }
  // The signals the sample context wires: $OUT[1..8], $IN[1..8].
  QCOMPARE(find<QCheckBox>(QStringLiteral("io.do0"))->text(), QStringLiteral("$OUT[1]"));
  QCOMPARE(find<QCheckBox>(QStringLiteral("io.do7"))->text(), QStringLiteral("$OUT[8]"));
  QVERIFY(find<Lamp>(QStringLiteral("io.di7")) != nullptr);
  QVERIFY(find<QCheckBox>(QStringLiteral("io.do8")) == nullptr);
  QVERIFY(find<QCheckBox>(QStringLiteral("io.do0"))->isEnabled());
  // The KUKA simulator's controls, not the xMate simulator's.
  QVERIFY(find<QPushButton>(QStringLiteral("sim.fault.drop"))->isVisibleTo(host_));
  QVERIFY(find<QPushButton>(QStringLiteral("sim.fault.drop"))->isEnabled());
  QVERIFY(!find<QPushButton>(QStringLiteral("sim.estop"))->isVisibleTo(host_));
  QCOMPARE(find<QCheckBox>(QStringLiteral("sim.in1"))->text(), QStringLiteral("$IN[2]"));
  const QString help = find<QLabel>(QStringLiteral("sim.fault.help"))->text();
  QVERIFY2(help.contains(QStringLiteral("101 missing answers")), qPrintable(help));
  // Jog: six axes named A1..A6; the TCP jog moves the flange (its group says how).
  QVERIFY(find<QPushButton>(QStringLiteral("jog.joint6.plus"))->isVisibleTo(host_));
  QVERIFY(!find<QPushButton>(QStringLiteral("jog.joint7.plus"))->isVisibleTo(host_));
  QCOMPARE(find<QPushButton>(QStringLiteral("jog.joint1.plus"))->toolTip(), QStringLiteral("A1 +"));
  QVERIFY(find<QPushButton>(QStringLiteral("jog.cart.x.plus"))->isEnabled());
  QVERIFY(!find<QGroupBox>(QStringLiteral("jog.cart"))->toolTip().isEmpty());
}

void TestKukaIoSimJog::outputSwitchSetsKukaOutput() {
  QVERIFY((session_->live().outputs & 1u) == 0);
  click(QStringLiteral("io.do0"));
  // The simulated controller reports its $OUT[1] (DIGOUT) back: bit 0 of the arm's outputs.
  QTRY_VERIFY_WITH_TIMEOUT((session_->live().outputs & 1u) != 0, kWaitMs);
  QVERIFY(krc().status().digout & 1u);
  QVERIFY(find<QCheckBox>(QStringLiteral("io.do0"))->isChecked());
  QTRY_VERIFY_WITH_TIMEOUT(statusText(QStringLiteral("io")).contains(QStringLiteral("done")), kWaitMs);
  click(QStringLiteral("io.do0"));
  QTRY_VERIFY_WITH_TIMEOUT((session_->live().outputs & 1u) == 0, kWaitMs);
  QTRY_VERIFY_WITH_TIMEOUT(!find<QCheckBox>(QStringLiteral("io.do0"))->isChecked(), kWaitMs);
}

void TestKukaIoSimJog::simulatedInputLightsLamp() {
  QVERIFY(!lampOn(QStringLiteral("io.di1")));
  click(QStringLiteral("sim.in1"));  // $IN[2] high in the simulated controller
  QTRY_VERIFY_WITH_TIMEOUT(lampOn(QStringLiteral("io.di1")), kWaitMs);
  QVERIFY(!lampOn(QStringLiteral("io.di0")));
  QVERIFY((krc().status().digin >> 1) & 1u);
  click(QStringLiteral("sim.in1"));
  QTRY_VERIFY_WITH_TIMEOUT(!lampOn(QStringLiteral("io.di1")), kWaitMs);
}

void TestKukaIoSimJog::pushSetsWrench() {
  find<QDoubleSpinBox>(QStringLiteral("sim.fx"))->setValue(0);
  find<QDoubleSpinBox>(QStringLiteral("sim.fy"))->setValue(0);
  find<QDoubleSpinBox>(QStringLiteral("sim.fz"))->setValue(-40);
  for (const char* m : {"sim.mx", "sim.my", "sim.mz"}) find<QDoubleSpinBox>(QLatin1String(m))->setValue(0);
  click(QStringLiteral("sim.wrench.apply"));
  // The force at the flange, in the flange frame: 40 N whichever way the flange points.
  auto magnitude = [this] {
    const auto w = krc().flangeWrench();
    return std::hypot(w[0], w[1], w[2]);
  };
  QVERIFY2(std::abs(magnitude() - 40) < 1e-6, qPrintable(QString::number(magnitude())));
  // The simulated F/T sensor reads it.
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().force_reading &&
                               std::abs(std::hypot(session_->live().force[0], session_->live().force[1],
                                                   session_->live().force[2]) - 40) < 2,
                           kWaitMs);
  click(QStringLiteral("sim.wrench.release"));
  QVERIFY(magnitude() < 1e-9);
  QCOMPARE(find<QDoubleSpinBox>(QStringLiteral("sim.fz"))->value(), 0.0);
}

void TestKukaIoSimJog::jointJogStopsAtCorrectionLimit() {
  waitRunning();
  QTRY_VERIFY_WITH_TIMEOUT(!session_->live().motion_running, kWaitMs);
  find<QSlider>(QStringLiteral("jog.speed"))->setValue(100);
  xmate::arm::StreamState s;
  QVERIFY(session_->rsiArm()->stream().state(s));
  const uint32_t rsi_session = s.session;
  const double q_on = s.q_on[0];
  const double limit = q_on + session_->rsiArm()->stream().limits().upper[0];  // +90 deg in the sample context
  const double a1_start = session_->live().arm.sample.q[0];
  QVERIFY(limit > a1_start + 10 * kDeg);
  auto* plus = find<QPushButton>(QStringLiteral("jog.joint1.plus"));
  auto commanded = [this] {
    xmate::arm::StreamState now;
    session_->rsiArm()->stream().state(now);
    return now.q_command[0];
  };
  // Hold A1 + until the jog has braked at the limit (the commanded A1 no longer changes). A jog the
  // dead-man ended (the window did not tick for 150 ms on a loaded machine) is pressed again.
  QElapsedTimer timer;
  timer.start();
  double max_commanded = -1e9, max_measured = -1e9;
  bool at_limit = false;
  while (!at_limit && timer.elapsed() < kWaitMs) {
    QSignalSpy finished(session_, &Session::motionFinished);
    QTest::mousePress(plus, Qt::LeftButton);
    double last = commanded();
    int still = 0;
    while (finished.isEmpty() && timer.elapsed() < kWaitMs) {
      QTest::qWait(20);
      const double c = commanded();
      max_commanded = std::max(max_commanded, c);
      max_measured = std::max(max_measured, session_->live().arm.sample.q[0]);
      still = (std::abs(c - last) < 1e-9 && c > a1_start + 10 * kDeg) ? still + 1 : 0;
      last = c;
      if (still >= 10) {
        at_limit = true;
        break;
      }
    }
    QTest::mouseRelease(plus, Qt::LeftButton);
    QVERIFY(QTest::qWaitFor([&] { return !finished.isEmpty(); }, kWaitMs));
    const bool ok = finished.first().at(1).toBool();
    const QString message = finished.first().at(2).toString();
    QVERIFY2(ok || message.contains(QStringLiteral("did not respond")), qPrintable(message));
    QTRY_VERIFY_WITH_TIMEOUT(!session_->live().motion_running, kWaitMs);
  }
  QVERIFY2(at_limit, "the jog did not come to rest at the correction limit");
  // It moved A1 the right way, up to 1 deg before the limit and not beyond, the other axes held.
  const double end = commanded();
  QVERIFY2(end > a1_start + 10 * kDeg, qPrintable(QString::number(end / kDeg)));
  QVERIFY2(max_commanded <= limit - xmate::jog::kJogLimitMargin + 1e-9, qPrintable(QString::number(max_commanded / kDeg)));
  QVERIFY2(end > limit - xmate::jog::kJogLimitMargin - 2 * kDeg, qPrintable(QString::number(end / kDeg)));
  QVERIFY2(max_measured <= limit, qPrintable(QString::number(max_measured / kDeg)));
  QVERIFY(session_->rsiArm()->stream().state(s));
  for (int i = 1; i < 6; ++i) QVERIFY(std::abs(s.q_command[size_t(i)] - s.q_on[size_t(i)]) < 1e-9);
  // RSI kept running in the same session: no correction monitor stopped it.
  QCOMPARE(s.session, rsi_session);
  QCOMPARE(int(krc().status().last_stop), int(xmate::sim::KrcStop::kNone));
  QTRY_VERIFY_WITH_TIMEOUT(statusText(QStringLiteral("jog")).contains(QStringLiteral("done")), kWaitMs);
}

// Holds a TCP jog button for `ms`, releases it and waits until the jog has braked and ended.
void TestKukaIoSimJog::holdCartesian(const QString& button, int ms) {
  auto* b = find<QPushButton>(button);
  QVERIFY(b && b->isEnabled());
  QSignalSpy finished(session_, &Session::motionFinished);
  QTest::mousePress(b, Qt::LeftButton);
  QTest::qWait(ms);
  QTest::mouseRelease(b, Qt::LeftButton);
  QVERIFY(QTest::qWaitFor([&] { return !finished.isEmpty(); }, kWaitMs));
  QVERIFY2(finished.first().at(1).toBool(), qPrintable(finished.first().at(2).toString()));
  QTRY_VERIFY_WITH_TIMEOUT(!session_->live().motion_running, kWaitMs);
  QTest::qWait(100);  // the newest state after the last command
}

// On a KUKA the TCP buttons move the flange along / about a base axis through the joints: +z lifts
// it and keeps its orientation; rz+ turns it and keeps its position.
void TestKukaIoSimJog::cartesianJogMovesTheFlange() {
  waitRunning();
  QTRY_VERIFY_WITH_TIMEOUT(!session_->live().motion_running, kWaitMs);
  find<QSlider>(QStringLiteral("jog.speed"))->setValue(40);
  auto pose = [this] { return session_->live().arm.tcp; };
  auto angle = [](const std::array<double, 16>& a, const std::array<double, 16>& b) {
    double trace = 0;
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) trace += a[size_t(4 * k + i)] * b[size_t(4 * k + i)];
    return std::acos(std::clamp((trace - 1) / 2, -1.0, 1.0));
  };
  std::array<double, 16> start = pose();
  holdCartesian(QStringLiteral("jog.cart.z.plus"), 600);
  std::array<double, 16> end = pose();
  QVERIFY2(end[11] - start[11] > 0.01, qPrintable(QString::number(end[11] - start[11])));
  QVERIFY2(std::hypot(end[3] - start[3], end[7] - start[7]) < 0.003,
           qPrintable(QString::number(std::hypot(end[3] - start[3], end[7] - start[7]))));
  QVERIFY2(angle(start, end) < 0.01, qPrintable(QString::number(angle(start, end))));
  start = end;
  holdCartesian(QStringLiteral("jog.cart.rz.plus"), 600);
  end = pose();
  QVERIFY2(angle(start, end) > 0.03, qPrintable(QString::number(angle(start, end))));
  QVERIFY2(std::hypot(end[3] - start[3], end[7] - start[7], end[11] - start[11]) < 0.003,
           qPrintable(QString::number(std::hypot(end[3] - start[3], end[7] - start[7], end[11] - start[11]))));
}

void TestKukaIoSimJog::stopAnsweringStopsAndRestartsRsi() {
  waitRunning();
  const uint32_t before = session_->live().rsi.session;
  // Every tick's phase, so a short stopped phase is not missed between two polls of the test.
  bool saw_timeout_stop = false;
  const auto watch = connect(session_, &Session::tick, this, [&] {
    const auto& rsi = session_->live().rsi;
    if (rsi.phase == xmate::rsi::SessionPhase::kStopped && rsi.cause == xmate::rsi::StopCause::kTimeout)
      saw_timeout_stop = true;
  });
  click(QStringLiteral("sim.fault.drop"));
  QTRY_VERIFY_WITH_TIMEOUT(saw_timeout_stop, kWaitMs);
  QTRY_VERIFY_WITH_TIMEOUT(krc().status().last_stop == xmate::sim::KrcStop::kTimeout, kWaitMs);
  // The simulated controller switches RSI on again; the window carries on with the new session.
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().rsi.phase == xmate::rsi::SessionPhase::kRunning &&
                               session_->live().rsi.session > before,
                           kWaitMs);
  disconnect(watch);
  QVERIFY(session_->isOpen());
  auto* label = find<QLabel>(QStringLiteral("sim.krc.state"));
  QTRY_VERIFY_WITH_TIMEOUT(label->text().contains(QStringLiteral("RSI is on")), kWaitMs);
  const QString state = label->text();
  QVERIFY2(state.contains(QStringLiteral("RSITimeout")), qPrintable(state));
  QVERIFY2(!state.contains(QStringLiteral("kTimeout")) && !state.contains(QStringLiteral("kRunning")), qPrintable(state));
}

QTEST_MAIN(TestKukaIoSimJog)
#include "test_kuka_io_sim_jog.moc"
