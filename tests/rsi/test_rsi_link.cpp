// SPDX-License-Identifier: Apache-2.0
// rsi::Link against a fake robot on loopback (a UDP socket that sends <Rob> datagrams from its own
// port and waits for each answer): every <Rob> is answered to its source with the IPOC echoed and
// the callback's corrections (#ABSOLUTE as given, #RELATIVE as changes), a bad datagram is counted
// and not answered, silence ends the session and the next datagram starts a new one, a slow
// callback is counted late, and the newest values are published.
#include <QtTest>

#include <atomic>
#include <chrono>
#include <cmath>
#include <string>
#include <thread>

#include "rsi/link.h"
#include "rsi_test_support.h"

using namespace xmate;
using namespace xmate::rsi;
using namespace xmate::rsi::testing;


class TestRsiLink : public QObject {
  Q_OBJECT

 private slots:
  void answersEveryRobWithTheCorrections();
  void relativeModeSendsChangesAndRestartsWithTheSession();
  void badDatagramsAreCountedNotAnswered();
  void slowCallbackIsCountedLate();
  void bindFailureSaysWhatToDo();
};

void TestRsiLink::answersEveryRobWithTheCorrections() {
  Link link(sampleConfig(), loopback());
  std::atomic<int> calls{0};  // written by the link's thread
  const int a1 = link.slot("AIPos", "A1");
  std::atomic<double> seen_a1{0};
  link.setCallback([&](const RobDecoder& rob) {
    const int call = ++calls;
    seen_a1 = rob.value(a1);
    Correction c;
    c.kind = Correction::Kind::kAxis;
    c.values = {0.5 * call, -1, 0, 0, 0, 2};
    return c;
  });
  link.start();
  FakeRobot robot(link.port());
  for (uint64_t ipoc = 1000; ipoc < 1010; ++ipoc) {
    const std::string sen = robot.exchange(ipoc, 12.5);
    QVERIFY2(sen.find("<IPOC>" + std::to_string(ipoc) + "</IPOC>") != std::string::npos, sen.c_str());
    QCOMPARE(attribute(sen, "A1"), 0.5 * double(ipoc - 999));
    QCOMPARE(attribute(sen, "A2"), -1.0);
    QCOMPARE(attribute(sen, "A6"), 2.0);
  }
  QCOMPARE(seen_a1.load(), 12.5);
  RobSample sample;
  QVERIFY(link.latest(sample));
  QCOMPARE(sample.ipoc, uint64_t(1009));
  QCOMPARE(sample.values[size_t(a1)], 12.5);
  QCOMPARE(sample.session, 1u);
  QVERIFY(link.receiving());
  // The counters are published just after each answer has gone out.
  QTRY_COMPARE_WITH_TIMEOUT(link.counters().answered, uint64_t(10), 2000);
  QCOMPARE(link.counters().received, uint64_t(10));
  QCOMPARE(link.counters().sessions, uint64_t(1));
  // Every cycle is in the sample ring, in order, with its answer time.
  QTRY_COMPARE_WITH_TIMEOUT(link.samples().size(), size_t(10), 2000);
  for (uint64_t ipoc = 1000; ipoc < 1010; ++ipoc) {
    LinkSample s;
    QVERIFY(link.samples().pop(s));
    QCOMPARE(s.ipoc, ipoc);
    QCOMPARE(s.session, 1u);
    QCOMPARE(s.values[size_t(a1)], 12.5);
    QCOMPARE(s.count, 47u);  // the sample config's slots
    QVERIFY(s.answer_ns >= 0);
  }
  QCOMPARE(link.samples().dropped(), uint64_t(0));

  // A RECEIVE value set from another thread goes out in the next answer, and stays.
  link.setReceiveValue(link.receiveSlot("Digout", "o3"), 1);
  QCOMPARE(attribute(robot.exchange(1010), "o3"), 1.0);
  QCOMPARE(attribute(robot.exchange(1011), "o3"), 1.0);
  QCOMPARE(attribute(robot.exchange(1012), "o2"), 0.0);
  QVERIFY_THROWS_EXCEPTION(std::out_of_range, link.setReceiveValue(999, 1));
}

void TestRsiLink::relativeModeSendsChangesAndRestartsWithTheSession() {
  Link link(sampleConfig(), loopback(CorrectionMode::kRelative));
  std::atomic<double> total{0};  // the test sets it between exchanges; the link's thread reads it
  link.setCallback([&](const RobDecoder&) {
    total = total + 0.25;  // the total correction grows by 0.25 deg a cycle
    Correction c;
    c.kind = Correction::Kind::kAxis;
    c.values = {total.load(), 0, 0, 0, 0, 0};
    return c;
  });
  link.start();
  FakeRobot robot(link.port());
  for (uint64_t ipoc = 1; ipoc <= 5; ++ipoc) QCOMPARE(attribute(robot.exchange(ipoc), "A1"), 0.25);  // the change
  // The robot stops sending (RSI off): the session ends; it starts again with IPOC from 0.
  QTRY_VERIFY_WITH_TIMEOUT(!link.receiving(), 5000);
  total = 10;  // a new session's corrections start from nothing: the first change is the whole total
  QCOMPARE(attribute(robot.exchange(0), "A1"), 10.25);
  QCOMPARE(attribute(robot.exchange(1), "A1"), 0.25);
  RobSample sample;
  QVERIFY(link.latest(sample));
  QCOMPARE(sample.session, 2u);
  QTRY_COMPARE_WITH_TIMEOUT(link.counters().sessions, uint64_t(2), 2000);
}

void TestRsiLink::badDatagramsAreCountedNotAnswered() {
  Link link(sampleConfig(), loopback());
  link.start();
  FakeRobot robot(link.port());
  QVERIFY(!robot.exchange(1).empty());
  // No answer to a datagram the link cannot read (the robot will count it late, as it should).
  QCOMPARE(robot.exchange(0, 0, "<Rob Type=\"ImFree\"><IPOC>12</IPO"), std::string());
  QTRY_COMPARE_WITH_TIMEOUT(link.counters().rejected, uint64_t(1), 2000);
  QVERIFY(std::string(link.lastReason()).size() > 0);
  QVERIFY(!robot.exchange(2).empty());
  QTRY_COMPARE_WITH_TIMEOUT(link.counters().answered, uint64_t(2), 2000);
}

void TestRsiLink::slowCallbackIsCountedLate() {
  LinkOptions options = loopback();
  options.cycle_ms = 4;
  Link link(sampleConfig(), options);
  link.setCallback([](const RobDecoder&) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));  // longer than the 4 ms cycle
    return Correction{};
  });
  link.start();
  FakeRobot robot(link.port());
  for (uint64_t ipoc = 1; ipoc <= 3; ++ipoc) QVERIFY(!robot.exchange(ipoc).empty());
  QTRY_COMPARE_WITH_TIMEOUT(link.counters().late, uint64_t(3), 2000);
  QTRY_COMPARE_WITH_TIMEOUT(link.samples().size(), size_t(3), 2000);
  LinkSample s;
  while (link.samples().pop(s)) QVERIFY2(s.late && s.answer_ns >= 10'000'000, qPrintable(QString::number(s.answer_ns)));
}

void TestRsiLink::bindFailureSaysWhatToDo() {
  Link first(sampleConfig(), loopback());
  first.start();
  LinkOptions same = loopback();
  same.port = first.port();
  Link second(sampleConfig(), same);
  try {
    second.start();
    QFAIL("a second link bound the same port");
  } catch (const std::runtime_error& e) {
    const QString message = QString::fromUtf8(e.what());
    QVERIFY2(message.contains(QStringLiteral("cannot listen on 127.0.0.1:%1").arg(first.port())) &&
                 message.contains(QStringLiteral("no other program may use the port")),
             qPrintable(message));
  }
}

QTEST_MAIN(TestRsiLink)
#include "test_rsi_link.moc"
