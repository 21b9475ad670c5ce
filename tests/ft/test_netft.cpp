// SPDX-License-Identifier: Apache-2.0
// ft::NetFtClient against the simulated Net F/T sensor on loopback: the request and record bytes are the
// RDT layout; the client asks the sensor to stream, converts counts to N and Nm, counts records lost
// on the way, biases on request, notices when the sensor falls silent and asks it again, and tells
// it to stop when stopped.
#include <QtTest>

#include <atomic>
#include <chrono>
#include <thread>

#include "ft/netft.h"
#include "net/udp_socket.h"
#include "sim/ft_sensor.h"

using namespace xmate;
using namespace xmate::ft;

namespace {

// The simulated sensor rci-sim serves, on a free loopback port, reading 2.5 N, -1 N, 0.25 Nm, -0.05 Nm.
struct FakeSensor : sim::SimulatedFtSensor {
  FakeSensor() : sim::SimulatedFtSensor(config()) {
    setWrench({2.5, -1.0, 0, 0.25, 0, -0.05});
    start();
  }
  static sim::FtSensorConfig config() {
    sim::FtSensorConfig c;
    c.port = 0;
    return c;
  }
};

NetFtOptions toSensor(uint16_t port) {
  NetFtOptions o;
  o.host = "127.0.0.1";
  o.port = port;
  return o;
}

}  // namespace

class TestNetFt : public QObject {
  Q_OBJECT

 private slots:
  void rdtBytes();
  void streamsConvertsAndCountsLosses();
  void biasAndSilence();
  void badAddressSaysWhatToGive();
};

void TestNetFt::rdtBytes() {
  uint8_t request[kRequestBytes];
  encodeRequest(kCommandStartStreaming, 0, request);
  const uint8_t expected[kRequestBytes] = {0x12, 0x34, 0x00, 0x02, 0, 0, 0, 0};
  QVERIFY(std::equal(request, request + kRequestBytes, expected));
  RdtRecord r;
  r.rdt_sequence = 0x01020304;
  r.status = 0x80000000u;
  r.counts = {-1, 2, -3, 4, -5, 2147483647};
  uint8_t bytes[kRecordBytes];
  encodeRecord(r, bytes);
  QCOMPARE(int(bytes[0]), 1);
  QCOMPARE(int(bytes[3]), 4);
  QCOMPARE(int(bytes[12]), 0xff);  // -1, big-endian
  RdtRecord back;
  QVERIFY(decodeRecord(bytes, sizeof bytes, back));
  QCOMPARE(back.rdt_sequence, r.rdt_sequence);
  QCOMPARE(back.status, r.status);
  QVERIFY(back.counts == r.counts);
  QVERIFY(!decodeRecord(bytes, sizeof bytes - 1, back));
}

void TestNetFt::streamsConvertsAndCountsLosses() {
  FakeSensor sensor;
  sensor.dropRecords(50, 3);  // three records lost on the way
  NetFtClient client(toSensor(sensor.port()));
  client.start();
  QTRY_VERIFY_WITH_TIMEOUT(client.streaming(), 5000);
  QTRY_VERIFY_WITH_TIMEOUT(client.statistics().records > 60, 10000);
  Wrench w;
  QVERIFY(client.latest(w));
  QCOMPARE(w.values[0], 2.5);
  QCOMPARE(w.values[1], -1.0);
  QCOMPARE(w.values[3], 0.25);
  QCOMPARE(w.values[5], -0.05);
  // Three were never sent; a machine too busy to read its socket in time could lose more.
  QVERIFY2(client.statistics().lost >= 3, qPrintable(QString::number(client.statistics().lost)));
  QCOMPARE(client.statistics().malformed, uint64_t(0));
  client.stop();
  QTRY_COMPARE_WITH_TIMEOUT(sensor.stopRequests(), 1, 5000);
  QVERIFY(!client.streaming());
}

void TestNetFt::biasAndSilence() {
  FakeSensor sensor;
  NetFtClient client(toSensor(sensor.port()));
  client.start();
  QTRY_VERIFY_WITH_TIMEOUT(client.streaming(), 5000);
  client.bias();
  Wrench w;
  QTRY_VERIFY_WITH_TIMEOUT(client.latest(w) && w.values[0] == 0 && w.values[1] == 0, 5000);
  sensor.setWrench({3.0, -1.0, 0, 0.25, 0, -0.05});  // someone pushes: +0.5 N over the bias
  QTRY_VERIFY_WITH_TIMEOUT(client.latest(w) && std::abs(w.values[0] - 0.5) < 1e-12, 5000);
  client.clearBias();
  QTRY_VERIFY_WITH_TIMEOUT(client.latest(w) && w.values[0] == 3.0, 5000);
  // The sensor falls silent: the client notices and asks it to stream again.
  sensor.setSilent(true);
  QTRY_VERIFY_WITH_TIMEOUT(!client.streaming(), 5000);
  QTRY_VERIFY_WITH_TIMEOUT(sensor.startRequests() >= 2, 5000);
  sensor.setSilent(false);
  QTRY_VERIFY_WITH_TIMEOUT(client.streaming(), 5000);
}

void TestNetFt::badAddressSaysWhatToGive() {
  NetFtOptions o;
  o.host = "sensor.local";
  NetFtClient client(o);
  try {
    client.start();
    QFAIL("started with a host name");
  } catch (const std::runtime_error& e) {
    QVERIFY2(QString::fromUtf8(e.what()).contains("\"sensor.local\" is not an IPv4 address"), e.what());
  }
}

QTEST_MAIN(TestNetFt)
#include "test_netft.moc"
