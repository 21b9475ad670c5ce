// SPDX-License-Identifier: Apache-2.0
// Tests of the rci-sim program: --print-port and a working session, the status line, the control
// port, option validation and its messages, the non-loopback warning, and clean shutdown.
#include <QProcess>
#include <QtTest>

#include <csignal>

#include "ft/netft.h"
#include "raw_client.h"

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
  // a missing value or a stray argument is a usage error (2) that says so. rci-sim has no options
  // that exclude each other.
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

  void helpListsTheOptions() {
    const Finished r = runToEnd({"--help"});
    QCOMPARE(r.exit_code, 0);
    for (const char* option : {"--model", "--bind", "--port", "--print-port", "--lockstep", "--control-port",
                               "--loopback-io", "--no-realtime", "--connect-timeout", "--idle-timeout"})
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
