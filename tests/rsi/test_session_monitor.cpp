// SPDX-License-Identifier: Apache-2.0
// rsi::SessionMonitor on the link's samples from the simulated KRC (timed, loopback): waiting, then
// running with its 4 ms cycle and answer times; dropped answers end the session with RSITimeout
// (said so in operator words) and a new session runs after the restart pause; RSI switched off
// without late answers is told apart.
#include <QtTest>

#include <chrono>
#include <functional>
#include <thread>

#include "arm/rsi_arm.h"
#include "rsi_test_support.h"
#include "rsi/session_monitor.h"
#include "sim/krc_server.h"

using namespace xmate;
using namespace xmate::rsi;
using namespace xmate::rsi::testing;


class TestSessionMonitor : public QObject {
  Q_OBJECT

 private slots:
  void followsTheSessionAndTellsWhyItStopped();
};

void TestSessionMonitor::followsTheSessionAndTellsWhyItStopped() {
  const arm::RsiArmConfig config = loopbackArm("resources/rsi/rci_replay.rsi.xml", 100);
  arm::RsiArm arm(config);
  SessionMonitor monitor(arm.link(), arm.context());
  // The window's tick: take what the link recorded, then ask.
  auto status = [&] {
    LinkSample s;
    while (arm.link().samples().pop(s)) monitor.add(s);
    return monitor.status(arm.link().receiving());
  };
  auto waitUntil = [&](const std::function<bool(const SessionStatus&)>& condition) {
    return waitFor([&] { return condition(status()); });
  };
  QCOMPARE(status().phase, SessionPhase::kWaiting);
  QVERIFY(QString::fromStdString(describe(status())).startsWith("Waiting for the robot"));
  QCOMPARE(status().timeout, 100);  // rci_replay.rsi.xml's ETHERNET1 Timeout

  arm.start();
  sim::KrcServerConfig k = krcFor(config, arm.link().port(), false);  // timed: late answers are late
  k.krc.restart_pause_ms = 300;
  sim::KrcServer krc(k);
  krc.start();
  QVERIFY(waitUntil([](const SessionStatus& s) { return s.phase == SessionPhase::kRunning && s.cycle_ms == 4; }));
  QVERIFY(waitUntil([](const SessionStatus& s) { return s.answer_p99_ms > 0; }));
  QCOMPARE(status().session, 1u);
  QVERIFY(QString::fromStdString(describe(status())).startsWith("RSI running, 4 ms cycle"));

  krc.krc().dropAnswers(150);  // every answer counts late: RSITimeout after 100
  QVERIFY(waitUntil([](const SessionStatus& s) { return s.phase == SessionPhase::kStopped; }));
  SessionStatus stopped = status();
  QCOMPARE(stopped.cause, StopCause::kTimeout);
  QVERIFY2(stopped.delay >= 100, qPrintable(QString::number(stopped.delay)));
  QVERIFY2(QString::fromStdString(describe(stopped)).contains("until its limit of 100 (RSITimeout)"),
           describe(stopped).c_str());
  // The KRL program starts RSI again: a new session, running.
  QVERIFY(waitUntil([](const SessionStatus& s) { return s.phase == SessionPhase::kRunning && s.session == 2; }));
  QCOMPARE(status().cause, StopCause::kNone);

  // RSI_OFF without late answers (on a loaded machine wait for a cycle answered in time first).
  QVERIFY(waitUntil([](const SessionStatus& s) { return s.late_in_a_row == 0; }));
  krc.krc().suspendSending(1000);
  QVERIFY(waitUntil([](const SessionStatus& s) { return s.phase == SessionPhase::kStopped; }));
  stopped = status();
  QCOMPARE(stopped.cause, StopCause::kByController);
  QVERIFY(QString::fromStdString(describe(stopped)).startsWith("RSI stopped by the controller"));
  krc.stop();
  arm.stop();
}

QTEST_GUILESS_MAIN(TestSessionMonitor)
#include "test_session_monitor.moc"
