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
#include "rsi/session_monitor.h"
#include "sim/krc_server.h"

using namespace xmate;
using namespace xmate::rsi;

namespace {

std::string dataPath(const std::string& relative) {
  return qEnvironmentVariable("RCI_DATA_DIR").toStdString() + "/" + relative;
}

}  // namespace

class TestSessionMonitor : public QObject {
  Q_OBJECT

 private slots:
  void followsTheSessionAndTellsWhyItStopped();
};

void TestSessionMonitor::followsTheSessionAndTellsWhyItStopped() {
  arm::RsiArmConfig config;
  config.context_path = dataPath("resources/rsi/rci_replay.rsi.xml");
  config.model = "kr6_r900_sixx";
  config.link.bind_ip = "127.0.0.1";
  config.link.port = 0;
  config.link.realtime = false;
  arm::RsiArm arm(config);
  SessionMonitor monitor(arm.link(), arm.context());
  // The window's tick: take what the link recorded, then ask.
  auto status = [&] {
    LinkSample s;
    while (arm.link().samples().pop(s)) monitor.add(s);
    return monitor.status(arm.link().receiving());
  };
  auto waitFor = [&](const std::function<bool(const SessionStatus&)>& condition) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(15);
    while (!condition(status())) {
      if (std::chrono::steady_clock::now() > end) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return true;
  };
  QCOMPARE(status().phase, SessionPhase::kWaiting);
  QVERIFY(QString::fromStdString(describe(status())).startsWith("Waiting for the robot"));
  QCOMPARE(status().timeout, 100);  // rci_replay.rsi.xml's ETHERNET1 Timeout

  arm.start();
  sim::KrcServerConfig k;
  k.krc.context_path = config.context_path;
  k.krc.model = config.model;
  k.krc.restart_pause_ms = 300;
  k.target_ip = "127.0.0.1";
  k.target_port = arm.link().port();
  sim::KrcServer krc(k);
  krc.start();
  QVERIFY(waitFor([](const SessionStatus& s) { return s.phase == SessionPhase::kRunning && s.cycle_ms == 4; }));
  QVERIFY(waitFor([](const SessionStatus& s) { return s.answer_p99_ms > 0; }));
  QCOMPARE(status().session, 1u);
  QVERIFY(QString::fromStdString(describe(status())).startsWith("RSI running, 4 ms cycle"));

  krc.krc().dropAnswers(150);  // every answer counts late: RSITimeout after 100
  QVERIFY(waitFor([](const SessionStatus& s) { return s.phase == SessionPhase::kStopped; }));
  SessionStatus stopped = status();
  QCOMPARE(stopped.cause, StopCause::kTimeout);
  QVERIFY2(stopped.delay >= 100, qPrintable(QString::number(stopped.delay)));
  QVERIFY2(QString::fromStdString(describe(stopped)).contains("until its limit of 100 (RSITimeout)"),
           describe(stopped).c_str());
  // The KRL program starts RSI again: a new session, running.
  QVERIFY(waitFor([](const SessionStatus& s) { return s.phase == SessionPhase::kRunning && s.session == 2; }));
  QCOMPARE(status().cause, StopCause::kNone);

  krc.krc().suspendSending(1000);  // RSI_OFF without late answers
  QVERIFY(waitFor([](const SessionStatus& s) { return s.phase == SessionPhase::kStopped; }));
  stopped = status();
  QCOMPARE(stopped.cause, StopCause::kByController);
  QVERIFY(QString::fromStdString(describe(stopped)).startsWith("RSI stopped by the controller"));
  krc.stop();
  arm.stop();
}

QTEST_GUILESS_MAIN(TestSessionMonitor)
#include "test_session_monitor.moc"
