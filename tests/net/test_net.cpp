// SPDX-License-Identifier: Apache-2.0
// Tests of the net/ building blocks: SPSC ring order and overflow, seqlock consistency under a
// concurrent writer, cycle statistics, and loopback UDP/TCP with their timeouts.
#include <QtTest>

#include <atomic>
#include <thread>

#include <fstream>
#include <string>
#include <vector>
#include "net/cycle_stats.h"
#include "net/host_port.h"
#include "net/realtime.h"
#include "net/seqlock.h"
#include "net/spsc_ring.h"
#include "net/tcp_socket.h"
#include "net/udp_socket.h"

using namespace xmate::net;

namespace {

// VmLck of this process, kB (-1 if unreadable).
long lockedKb() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmLck:", 0) == 0) return std::stol(line.substr(6));
  return -1;
}

}  // namespace

class TestNet : public QObject {
  Q_OBJECT

 private slots:
  // The real-time thread locks its stack and the regions it names, not the whole process: memory
  // allocated afterwards by anyone (a window's scenes, plots) stays pageable.
  void realtimeLocksOnlyTheThreadsMemory() {
    const long before = lockedKb();
    std::vector<unsigned char> region(1 << 20, 1);
    RealtimeStatus status;
    std::thread([&] { status = enableRealtimeForThisThread(10, {{region.data(), region.size()}}); }).join();
    if (!status.memory_locked) QSKIP(qPrintable("memory locking not granted here: " + QString::fromStdString(status.reason)));
    const long locked = lockedKb() - before;
    QVERIFY2(locked >= 1024 && locked < 4096, qPrintable(QString::number(locked) + " kB locked"));
    std::vector<unsigned char> later(32 << 20, 1);  // touched: resident
    QVERIFY2(lockedKb() - before < 4096, qPrintable(QString::number(lockedKb() - before) + " kB locked after 32 MB"));
  }

  void ringKeepsOrderAndCountsDrops() {
    SpscRing<int, 4> ring;
    for (int i = 0; i < 4; ++i) QVERIFY(ring.push(i));
    QVERIFY(!ring.push(99));
    QCOMPARE(ring.dropped(), uint64_t(1));
    int out[8];
    QCOMPARE(ring.popBatch(out, 8), size_t(4));
    for (int i = 0; i < 4; ++i) QCOMPARE(out[i], i);
    QVERIFY(!ring.pop(out[0]));
  }

  void ringAcrossThreads() {
    SpscRing<uint64_t, 1024> ring;
    constexpr uint64_t kCount = 200000;
    std::thread producer([&] {
      for (uint64_t i = 0; i < kCount;)
        if (ring.push(i)) ++i;
    });
    uint64_t expected = 0, v = 0;
    while (expected < kCount)
      if (ring.pop(v)) QCOMPARE(v, expected++);
    producer.join();
  }

  void seqlockNeverTears() {
    struct Pair { uint64_t a, b; };
    Seqlock<Pair> lock;
    std::atomic<bool> stop{false};
    std::thread writer([&] {
      for (uint64_t i = 1; !stop; ++i) lock.store(Pair{i, ~i});
    });
    Pair p{};
    for (int i = 0; i < 200000; ++i)
      if (lock.load(p) > 0) QCOMPARE(p.b, ~p.a);
    stop = true;
    writer.join();
  }

  void cycleStatsPercentiles() {
    CycleStats stats(1000.0, 1500.0);
    for (int i = 0; i < 990; ++i) stats.record(1'000'000);
    for (int i = 0; i < 10; ++i) stats.record(2'000'000);
    stats.recordLost(3);
    const CycleSummary s = stats.summary();
    QCOMPARE(s.cycles, uint64_t(1000));
    QCOMPARE(s.min_us, 1000.0);
    QCOMPARE(s.max_us, 2000.0);
    QCOMPARE(s.p50_us, 1000.0);
    QCOMPARE(s.p99_us, 1000.0);   // exactly 99 % of the periods are 1000 us
    QCOMPARE(s.p999_us, 2000.0);
    QCOMPARE(s.late, uint64_t(10));
    QCOMPARE(s.lost, uint64_t(3));
    QVERIFY(qAbs(s.mean_us - 1010.0) < 1e-9);
  }

  void udpLoopback() {
    UdpSocket a, b;
    a.bind("127.0.0.1", 0);
    b.bind("127.0.0.1", 0);
    QVERIFY(a.localPort() != 0);
    const char msg[] = "state";
    QCOMPARE(a.sendTo(makeEndpoint("127.0.0.1", b.localPort()), msg, sizeof msg), long(sizeof msg));
    char buf[64] = {};
    Endpoint from;
    QCOMPARE(b.receiveFrom(buf, sizeof buf, &from, 1'000'000), long(sizeof msg));
    QCOMPARE(QString(buf), QString("state"));
    QCOMPARE(ntohs(from.addr.sin_port), a.localPort());
    // Nothing more: a short timeout returns 0.
    QCOMPARE(b.receiveFrom(buf, sizeof buf, nullptr, 2000), 0L);
    // An oversize datagram reports its full length.
    char big[100] = {};
    a.sendTo(makeEndpoint("127.0.0.1", b.localPort()), big, sizeof big);
    QCOMPARE(b.receiveFrom(buf, 10, nullptr, 1'000'000), 100L);
  }

  void badAddressIsRejectedClearly() {
    try {
      makeEndpoint("192.168.0.300", 1337);
      QFAIL("expected std::invalid_argument");
    } catch (const std::invalid_argument& e) {
      QVERIFY(QString(e.what()).contains("192.168.0.300"));
    }
  }

  void tcpExchangeAndTimeouts() {
    TcpListener listener;
    listener.listen("127.0.0.1", 0);
    TcpConnection client = TcpConnection::connect(makeEndpoint("127.0.0.1", listener.localPort()), 1000);
    auto server = listener.accept(1000);
    QVERIFY(server.has_value());
    const char msg[] = "hello";
    QCOMPARE(client.sendAll(msg, sizeof msg, 100), IoResult::kOk);
    char buf[sizeof msg] = {};
    QCOMPARE(server->readExact(buf, sizeof buf, 1000), IoResult::kOk);
    QCOMPARE(QString(buf), QString("hello"));
    QCOMPARE(server->readExact(buf, 1, 20), IoResult::kTimeout);
    client.close();
    QCOMPARE(server->readExact(buf, 1, 1000), IoResult::kClosed);
  }

  void tcpConnectRefusedSaysWhere() {
    TcpListener listener;
    listener.listen("127.0.0.1", 0);
    const uint16_t port = listener.localPort();
    listener.close();
    try {
      TcpConnection::connect(makeEndpoint("127.0.0.1", port), 500);
      QFAIL("expected a connection error");
    } catch (const std::runtime_error& e) {
      QVERIFY2(QString(e.what()).contains(QString::number(port)), e.what());
    }
  }

  // HOST:PORT as every program here reads it: the port after the last colon, or the default.
  void hostPortIsSplitAtTheLastColon() {
    HostPort a;
    QCOMPARE(splitHostPort("192.168.0.160:1337", 0, a), HostPortProblem::kNone);
    QCOMPARE(a.host, std::string("192.168.0.160"));
    QCOMPARE(a.port, uint16_t(1337));
    QCOMPARE(splitHostPort("sensor", 49152, a), HostPortProblem::kNone);
    QCOMPARE(a.port, uint16_t(49152));
    QCOMPARE(splitHostPort("sensor", 0, a), HostPortProblem::kNoPort);
    QCOMPARE(splitHostPort(":1337", 0, a), HostPortProblem::kNoHost);
    QCOMPARE(splitHostPort("", 1337, a), HostPortProblem::kNoHost);
    QCOMPARE(splitHostPort("host:", 1337, a), HostPortProblem::kBadPort);
    QCOMPARE(a.port_text, std::string());
    QCOMPARE(splitHostPort("host:70000", 0, a), HostPortProblem::kBadPort);
    QCOMPARE(a.port_text, std::string("70000"));
    QCOMPARE(splitHostPort("host:12ab", 0, a), HostPortProblem::kBadPort);
    QCOMPARE(splitHostPort("host:0", 0, a), HostPortProblem::kBadPort);
  }
};

QTEST_APPLESS_MAIN(TestNet)
#include "test_net.moc"
