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

#include "net/udp_socket.h"
#include "rsi/config.h"
#include "rsi/link.h"

using namespace xmate;
using namespace xmate::rsi;

namespace {

EthernetConfig sampleConfig() {
  return readEthernetConfig(qEnvironmentVariable("RCI_DATA_DIR").toStdString() + "/resources/rsi/RSI_EthernetConfig.xml");
}

LinkOptions loopback(CorrectionMode mode = CorrectionMode::kAbsolute) {
  LinkOptions o;
  o.bind_ip = "127.0.0.1";
  o.port = 0;  // a free port
  o.mode = mode;
  o.realtime = false;
  o.silence_ms = 1000;  // a loaded machine may pause between two exchanges; only the test's own pause is silence
  return o;
}

// The robot's side: sends from its own (ephemeral) port, as a KRC does.
class FakeRobot {
 public:
  explicit FakeRobot(uint16_t link_port) : to_(net::makeEndpoint("127.0.0.1", link_port)) { socket_.bind("127.0.0.1", 0); }
  // Sends a <Rob> with this IPOC and A1 actual; returns the answer ("" if none within 2 s).
  std::string exchange(uint64_t ipoc, double a1 = 0, const std::string& raw = {}) {
    const std::string rob = !raw.empty() ? raw
                                         : "<Rob Type=\"ImFree\"><AIPos A1=\"" + std::to_string(a1) +
                                               "\" A2=\"-90\" A3=\"90\" A4=\"0\" A5=\"90\" A6=\"0\" /><Delay D=\"0\" /><IPOC>" +
                                               std::to_string(ipoc) + "</IPOC></Rob>";
    socket_.sendTo(to_, rob.data(), rob.size());
    char buffer[2048];
    net::Endpoint from;
    const long n = socket_.receiveFrom(buffer, sizeof buffer, &from, 2'000'000);
    return n > 0 ? std::string(buffer, size_t(n)) : std::string();
  }

 private:
  net::UdpSocket socket_;
  net::Endpoint to_;
};

// The attribute's value in an answer.
double attribute(const std::string& sen, const std::string& name) {
  const size_t at = sen.find(" " + name + "=\"");
  return at == std::string::npos ? NAN : std::stod(sen.substr(at + name.size() + 3));
}

}  // namespace

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
