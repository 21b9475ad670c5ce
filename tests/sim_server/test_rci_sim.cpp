// SPDX-License-Identifier: Apache-2.0
// Tests of the rci-sim program: --print-port and a working session, the status line, the control
// port, option validation and its messages, the non-loopback warning, and clean shutdown; with --rsi
// the simulated KRC sends <Rob> datagrams to a PC played by the test and says RSITimeout when the
// PC falls silent.
#include <QProcess>
#include <QtTest>

#include <csignal>

#include "ft/netft.h"
#include "net/udp_socket.h"
#include "raw_client.h"
#include "rsi/codec.h"
#include "rsi/config.h"

using namespace simtest;
using namespace xmate;

namespace {

struct Finished {
  int exit_code = -1;
  QString out, err;
};

// Runs rci-sim to completion (for options that make it exit at once).
Finished runToEnd(const QStringList& args) {
  QProcess p;
  p.start(RCI_SIM_PATH, args);
  if (!p.waitForFinished(20000)) p.kill();
  return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, p.readAllStandardOutput(),
          p.readAllStandardError()};
}

// Reads one line of stdout (waiting for it).
QString readLine(QProcess& p) {
  while (!p.canReadLine())
    if (!p.waitForReadyRead(20000)) return {};
  return QString::fromUtf8(p.readLine()).trimmed();
}

// Sends SIGTERM and returns the exit code (-1 if it did not end by itself).
int terminate(QProcess& p) {
  ::kill(pid_t(p.processId()), SIGTERM);
  if (!p.waitForFinished(20000)) {
    p.kill();
    return -1;
  }
  return p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
}

}  // namespace

class TestRciSim : public QObject {
  Q_OBJECT

 private slots:
  void printPortThenServeASession() {
    QProcess sim;
    sim.start(RCI_SIM_PATH, {"--port", "0", "--print-port", "--lockstep", "--no-realtime", "--model", "xmate3"});
    QVERIFY(sim.waitForStarted());
    bool ok = false;
    const uint16_t port = uint16_t(readLine(sim).toUInt(&ok));
    QVERIFY(ok && port != 0);
    const QString status = readLine(sim);
    QCOMPARE(status, QString("rci-sim: xMate 3 on 127.0.0.1:%1, lock-step clock, normal priority (real-time "
                             "scheduling not requested)").arg(port));

    RawClient client(port);
    QCOMPARE(int(client.handshake()), 0);
    const std::optional<RCI::robot::RobotState> state = client.receiveState(5000);
    QVERIFY(state.has_value());
    QCOMPARE(state->q[6], 0.0);  // six-axis model: the seventh joint is unused

    QCOMPARE(terminate(sim), 0);
    QVERIFY(QString(sim.readAllStandardError()).contains("stopping (SIGTERM)"));
  }

  void controlPortIsAnnouncedAndAnswers() {
    QProcess sim;
    sim.start(RCI_SIM_PATH, {"--port", "0", "--print-port", "--control-port", "0", "--no-realtime"});
    QVERIFY(sim.waitForStarted());
    readLine(sim);
    QVERIFY(readLine(sim).startsWith("rci-sim: xMate Pro 7 on 127.0.0.1:"));
    const QString control_line = readLine(sim);
    const QRegularExpressionMatch m =
        QRegularExpression("^rci-sim: control port on 127\\.0\\.0\\.1:(\\d+) \\(type help\\)$").match(control_line);
    QVERIFY2(m.hasMatch(), qPrintable(control_line));

    net::TcpConnection control =
        net::TcpConnection::connect(net::makeEndpoint("127.0.0.1", uint16_t(m.captured(1).toUInt())), 2000);
    const std::string line = "estop on\n";
    QCOMPARE(control.sendAll(line.data(), line.size(), 2000), net::IoResult::kOk);
    char answer[12] = {};
    QCOMPARE(control.readExact(answer, 12, 10000), net::IoResult::kOk);
    QCOMPARE(QByteArray(answer, 12), QByteArray("ok estop on\n"));

    ::kill(pid_t(sim.processId()), SIGINT);
    QVERIFY(sim.waitForFinished(20000));
    QCOMPARE(sim.exitCode(), 0);
  }

  void ftSensorIsAnnouncedAndStreams() {
    QProcess sim;
    sim.start(RCI_SIM_PATH, {"--port", "0", "--print-port", "--ft-sensor", "0", "--no-realtime"});
    QVERIFY(sim.waitForStarted());
    readLine(sim);
    QVERIFY(readLine(sim).startsWith("rci-sim: xMate Pro 7 on 127.0.0.1:"));
    const QString ft_line = readLine(sim);
    const QRegularExpressionMatch m = QRegularExpression(
        "^rci-sim: F/T sensor \\(Net F/T, RDT\\) on 127\\.0\\.0\\.1:(\\d+), reading a zero wrench$").match(ft_line);
    QVERIFY2(m.hasMatch(), qPrintable(ft_line));
    ft::NetFtOptions options;
    options.host = "127.0.0.1";
    options.port = uint16_t(m.captured(1).toUInt());
    ft::NetFtClient client(options);
    client.start();
    QTRY_VERIFY_WITH_TIMEOUT(client.statistics().records > 10, 10000);
    ft::Wrench w;
    QVERIFY(client.latest(w));
    QVERIFY(w.values == (std::array<double, 6>{}));
    client.stop();
    QCOMPARE(terminate(sim), 0);
  }

  void unknownModelListsTheFour() {
    const Finished r = runToEnd({"--model", "xmate9"});
    QCOMPARE(r.exit_code, 2);
    QVERIFY2(r.err.contains("unknown model 'xmate9'; choose one of: xmate3_pro, xmate7_pro, xmate3, xmate7"),
             qPrintable(r.err));
    QVERIFY(r.err.contains("rci-sim --help"));
  }

  void badOptionsAreExplained() {
    Finished r = runToEnd({"--port", "70000"});
    QCOMPARE(r.exit_code, 2);
    QVERIFY2(r.err.contains("--port takes a whole number from 0 to 65535, got '70000'"), qPrintable(r.err));
    r = runToEnd({"--bind", "not-an-ip"});
    QCOMPARE(r.exit_code, 2);
    QVERIFY2(r.err.contains("--bind takes an IPv4 address"), qPrintable(r.err));
    r = runToEnd({"--frobnicate"});
    QCOMPARE(r.exit_code, 2);
    QVERIFY(r.err.contains("unknown option '--frobnicate'"));
    r = runToEnd({"--port"});
    QCOMPARE(r.exit_code, 2);
    QVERIFY(r.err.contains("--port needs a value"));
    r = runToEnd({"--idle-timeout", "-5"});
    QCOMPARE(r.exit_code, 2);
    QVERIFY2(r.err.contains("--idle-timeout takes a whole number from 0 to 3600000"), qPrintable(r.err));
  }

  // The command line is CLI11's: --opt=value as well as --opt value; every typed option range-checked;
  // a missing value or a stray argument is a usage error (2) that says so. The --rsi-* options need
  // --rsi (rsiOptionsAreChecked); no other options exclude each other.
  void optionSyntaxAndValueChecks() {
    Finished r = runToEnd({"--port=70000"});
    QCOMPARE(r.exit_code, 2);
    QVERIFY2(r.err.contains("--port takes a whole number from 0 to 65535, got '70000'"), qPrintable(r.err));
    QVERIFY2(r.err.contains("run rci-sim --help for the options"), qPrintable(r.err));
    r = runToEnd({"--lockstep-timeout", "0"});
    QCOMPARE(r.exit_code, 2);
    QVERIFY2(r.err.contains("--lockstep-timeout takes a whole number from 1 to 60000, got '0'"), qPrintable(r.err));
    r = runToEnd({"--control-port", "seven"});
    QCOMPARE(r.exit_code, 2);
    QVERIFY2(r.err.contains("--control-port takes a whole number from 0 to 65535, got 'seven'"), qPrintable(r.err));
    r = runToEnd({"--reboot-pause=600001"});
    QCOMPARE(r.exit_code, 2);
    QVERIFY2(r.err.contains("--reboot-pause takes a whole number from 0 to 600000, got '600001'"), qPrintable(r.err));
    r = runToEnd({"--control-bind", "1.2.3"});
    QCOMPARE(r.exit_code, 2);
    QVERIFY2(r.err.contains("--control-bind takes an IPv4 address such as 127.0.0.1, got '1.2.3'"), qPrintable(r.err));
    r = runToEnd({"--model=xmate9"});
    QCOMPARE(r.exit_code, 2);
    QVERIFY2(r.err.contains("unknown model 'xmate9'; choose one of:"), qPrintable(r.err));
    r = runToEnd({"--lockstep", "--connect-timeout"});
    QCOMPARE(r.exit_code, 2);
    QVERIFY2(r.err.contains("--connect-timeout needs a value"), qPrintable(r.err));
    r = runToEnd({"extra"});
    QCOMPARE(r.exit_code, 2);
    QVERIFY2(r.err.contains("unexpected argument 'extra' (rci-sim takes options only)"), qPrintable(r.err));
    r = runToEnd({"-h"});
    QCOMPARE(r.exit_code, 0);
    QVERIFY2(r.out.contains("--lockstep-timeout MS") && r.out.contains("--control-bind IP"), qPrintable(r.out));
  }

  // rci-sim --rsi: the simulated KRC sends a <Rob> every cycle from its own port to the target, takes
  // the answers, and when the PC falls silent stops RSI with RSITimeout, then starts a new session.
  void rsiSendsRobsAndSaysRsiTimeoutWhenNobodyAnswers() {
    const std::string data = qEnvironmentVariable("RCI_DATA_DIR").toStdString();
    const rsi::EthernetConfig config = rsi::readEthernetConfig(data + "/resources/rsi/RSI_EthernetConfig.xml");
    rsi::RobDecoder rob(config);
    rsi::SenEncoder sen(config);
    net::UdpSocket pc;
    pc.bind("127.0.0.1", 0);
    QProcess sim;
    sim.start(RCI_SIM_PATH, {"--rsi", QString::fromStdString(data + "/resources/rsi/rci_axis_corr.rsi.xml"),
                             "--rsi-target", QString("127.0.0.1:%1").arg(pc.localPort()), "--no-realtime",
                             "--print-port", "--rsi-restart-pause", "100"});
    QVERIFY(sim.waitForStarted());
    const uint16_t krc_port = uint16_t(readLine(sim).toUInt());
    QVERIFY(krc_port != 0);
    const QString status = readLine(sim);
    QVERIFY2(status.startsWith(QString("rci-sim: KR 6 R900 sixx (KUKA RSI) on 127.0.0.1:%1, sending <Rob> to "
                                       "127.0.0.1:%2 every 4 ms, #ABSOLUTE, Timeout 100").arg(krc_port).arg(pc.localPort())),
             qPrintable(status));

    // Answer 20 <Rob> like a PC (to their source), then fall silent.
    char buffer[rsi::kMaxDatagramBytes];
    for (int i = 0; i < 20; ++i) {
      net::Endpoint from;
      const long n = pc.receiveFrom(buffer, sizeof buffer, &from, 10'000'000);
      QVERIFY(n > 0);
      QCOMPARE(ntohs(from.addr.sin_port), krc_port);  // one socket sends and receives
      const std::string datagram(buffer, size_t(n));
      QVERIFY2(datagram.rfind("<Rob Type=\"ImFree\">", 0) == 0, datagram.c_str());
      QVERIFY2(rob.decode(datagram), rob.reason());
      char answer[rsi::kMaxSenBytes];
      const size_t m = sen.encode(rob.ipocText(), answer, sizeof answer);
      QCOMPARE(pc.sendTo(from, answer, m), long(m));
    }
    QCOMPARE(rob.value(rob.slot("AIPos", "A2")), -90.0);
    sim.setReadChannel(QProcess::StandardError);
    QString err;
    while (!err.contains("session 2") && sim.waitForReadyRead(20000)) err += sim.readAllStandardError();
    QVERIFY2(err.contains("Signal flow (running): Object ETHERNET1 returns error RSITimeout (101 late answers in a row, "
                          "Timeout 100); RSI stopped, the arm holds"),
             qPrintable(err));
    QVERIFY2(err.contains("RSI_ON(#ABSOLUTE): session 2"), qPrintable(err));
    QCOMPARE(terminate(sim), 0);
  }

  // rci-sim --rsi --ft-sensor: the sensor reads the wrench pushed on the simulated arm, in the flange
  // frame (the KR 6's flange at the start pose is turned 180 deg about y of the base: z points down).
  void rsiFtSensorReadsTheArmsWrench() {
    const std::string data = qEnvironmentVariable("RCI_DATA_DIR").toStdString();
    QProcess sim;
    sim.start(RCI_SIM_PATH, {"--rsi", QString::fromStdString(data + "/resources/rsi/rci_axis_corr.rsi.xml"),
                             "--rsi-target", "127.0.0.1:9", "--no-realtime", "--ft-sensor", "0", "--external-wrench",
                             "0,0,-20,0,0,0"});
    QVERIFY(sim.waitForStarted());
    QVERIFY(readLine(sim).startsWith("rci-sim: KR 6 R900 sixx (KUKA RSI)"));
    const QRegularExpressionMatch m =
        QRegularExpression("^rci-sim: F/T sensor \\(Net F/T, RDT\\) on 127\\.0\\.0\\.1:(\\d+), reading the arm's external wrench$")
            .match(readLine(sim));
    QVERIFY(m.hasMatch());
    ft::NetFtOptions options;
    options.host = "127.0.0.1";
    options.port = uint16_t(m.captured(1).toUInt());
    ft::NetFtClient client(options);
    client.start();
    ft::Wrench w;
    QTRY_VERIFY_WITH_TIMEOUT(client.latest(w) && std::abs(w.values[2] - 20) < 1e-3, 10000);
    QVERIFY(std::abs(w.values[0]) < 1e-3 && std::abs(w.values[1]) < 1e-3);
    client.stop();
    QCOMPARE(terminate(sim), 0);
  }

  void rsiOptionsAreChecked() {
    Finished r = runToEnd({"--rsi-target", "127.0.0.1:49152"});
    QCOMPARE(r.exit_code, 2);
    QVERIFY2(r.err.contains("--rsi-target needs --rsi CONTEXT.rsi.xml"), qPrintable(r.err));
    r = runToEnd({"--model", "kr16_2"});
    QCOMPARE(r.exit_code, 2);
    QVERIFY2(r.err.contains("--model kr16_2 is a KUKA arm: it runs over RSI; give --rsi CONTEXT.rsi.xml"), qPrintable(r.err));
    r = runToEnd({"--rsi", "x.rsi.xml", "--cycle-ms", "5"});
    QCOMPARE(r.exit_code, 2);
    QVERIFY2(r.err.contains("--cycle-ms takes 4 (#IPO_FAST) or 12, got '5'"), qPrintable(r.err));
    r = runToEnd({"--rsi", "x.rsi.xml", "--rsi-mode", "sideways"});
    QCOMPARE(r.exit_code, 2);
    QVERIFY2(r.err.contains("--rsi-mode takes absolute or relative, got 'sideways'"), qPrintable(r.err));
    r = runToEnd({"--rsi", "x.rsi.xml", "--rsi-target", "127.0.0.1"});
    QCOMPARE(r.exit_code, 2);
    QVERIFY2(r.err.contains("--rsi-target takes HOST:PORT"), qPrintable(r.err));
    r = runToEnd({"--rsi", "x.rsi.xml", "--start-joints-deg", "0,-90,90"});
    QCOMPARE(r.exit_code, 2);
    QVERIFY2(r.err.contains("--start-joints-deg takes 6 numbers separated by commas"), qPrintable(r.err));
    r = runToEnd({"--rsi", "/nonexistent/x.rsi.xml", "--no-realtime"});
    QCOMPARE(r.exit_code, 1);
    QVERIFY2(r.err.contains("/nonexistent/x.rsi.xml"), qPrintable(r.err));
    const std::string data = qEnvironmentVariable("RCI_DATA_DIR").toStdString();
    r = runToEnd({"--rsi", QString::fromStdString(data + "/resources/rsi/rci_axis_corr.rsi.xml"), "--no-realtime",
                  "--start-joints-deg", "0,-90,90,0,170,0"});
    QCOMPARE(r.exit_code, 1);
    QVERIFY2(r.err.contains("A5 = 170") && r.err.contains("outside its range"), qPrintable(r.err));
  }

  void helpListsTheOptions() {
    const Finished r = runToEnd({"--help"});
    QCOMPARE(r.exit_code, 0);
    for (const char* option : {"--model", "--bind", "--port", "--print-port", "--lockstep", "--control-port",
                               "--loopback-io", "--no-realtime", "--connect-timeout", "--idle-timeout", "--rsi",
                               "--rsi-target", "--rsi-mode", "--cycle-ms", "--start-joints-deg", "--rsi-restart-pause"})
      QVERIFY2(r.out.contains(option), option);
  }

  void versionPrintsTheVersion() {
    const Finished r = runToEnd({"--version"});
    QCOMPARE(r.exit_code, 0);
    QVERIFY2(r.out.startsWith("rci-sim 0."), qPrintable(r.out));
  }

  void nonLoopbackBindWarns() {
    QProcess sim;
    sim.start(RCI_SIM_PATH, {"--bind", "0.0.0.0", "--port", "0", "--print-port", "--no-realtime"});
    QVERIFY(sim.waitForStarted());
    QVERIFY(readLine(sim).toUInt() != 0);
    QCOMPARE(terminate(sim), 0);
    QVERIFY(QString(sim.readAllStandardError())
                .contains("warning: listening on 0.0.0.0: anyone on that network can move the simulated robot"));
  }

  void portInUseIsReported() {
    QProcess first;
    first.start(RCI_SIM_PATH, {"--port", "0", "--print-port", "--no-realtime"});
    QVERIFY(first.waitForStarted());
    const QString port = readLine(first);
    const Finished second = runToEnd({"--port", port, "--no-realtime"});
    QCOMPARE(second.exit_code, 1);
    QVERIFY2(second.err.contains("already in use"), qPrintable(second.err));
    QCOMPARE(terminate(first), 0);
  }
};

QTEST_APPLESS_MAIN(TestRciSim)
#include "test_rci_sim.moc"
