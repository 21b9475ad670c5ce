// SPDX-License-Identifier: Apache-2.0
// rci-cli's RSI commands as a user runs them (the program, as a process): `state --robot rsi:...`
// against a fake KRC on loopback (reads the answers, checks the printed values), and a smoke run of
// `bench rsi` (the output's shape, never its timings).
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <chrono>
#include <cmath>
#include <string>
#include <thread>

#include "net/udp_socket.h"

using namespace xmate;

namespace {

QString sampleConfig() { return qEnvironmentVariable("RCI_DATA_DIR") + "/resources/rsi/RSI_EthernetConfig.xml"; }

// rci-cli with the real-time setup off (a shared test machine), not yet waited for.
void startCli(QProcess& p, const QStringList& args) {
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  env.insert("RCI_NO_REALTIME", "1");
  p.setProcessEnvironment(env);
  p.start(RCI_CLI_PATH, args);
}

QString readLine(QProcess& p) {
  while (!p.canReadLine())
    if (!p.waitForReadyRead(20000)) return {};
  return QString::fromUtf8(p.readLine()).trimmed();
}

// Reads stdout up to the "waiting for the robot on 127.0.0.1:PORT" line; returns PORT (0 if none).
uint16_t waitingPort(QProcess& p, QStringList* before = nullptr) {
  const QRegularExpression waiting("^# waiting for the robot on 127\\.0\\.0\\.1:(\\d+) -- start the KRL program with RSI_ON");
  for (int i = 0; i < 10; ++i) {
    const QString line = readLine(p);
    const QRegularExpressionMatch m = waiting.match(line);
    if (m.hasMatch()) return uint16_t(m.captured(1).toUInt());
    if (before) before->append(line);
    if (line.isEmpty()) break;
  }
  return 0;
}

// The KRC's side: sends each <Rob> from its own port, as a KRC does, and reads the answer.
class FakeKrc {
 public:
  explicit FakeKrc(uint16_t port) : to_(net::makeEndpoint("127.0.0.1", port)) { socket_.bind("127.0.0.1", 0); }
  std::string exchange(const std::string& rob) {
    socket_.sendTo(to_, rob.data(), rob.size());
    char buffer[2048];
    const long n = socket_.receiveFrom(buffer, sizeof buffer, nullptr, 2'000'000);
    return n > 0 ? std::string(buffer, size_t(n)) : std::string();
  }

 private:
  net::UdpSocket socket_;
  net::Endpoint to_;
};

// A <Rob> of the sample config's layout, as a KRC writes it; cycle k moves A1 and X.
std::string rob(uint64_t ipoc, int k, bool with_currents = true) {
  const std::string a1 = std::to_string(10 + k) + ".000000";
  std::string s = "<Rob Type=\"ImFree\">\r\n"
                  "<RIst X=\"" + std::to_string(445 + k) + ".5\" Y=\"-12.25\" Z=\"900.125\" A=\"179.5\" B=\"-0.000000\" C=\"1e-05\" />\r\n"
                  "<RSol X=\"445.5\" Y=\"-12.25\" Z=\"900.125\" A=\"179.5\" B=\"0.0\" C=\"0.0\" />\r\n"
                  "<AIPos A1=\"" + a1 + "\" A2=\"-90.5\" A3=\"91.25\" A4=\"0.0\" A5=\"45.125\" A6=\"-180.0\" />\r\n"
                  "<ASPos A1=\"" + a1 + "\" A2=\"-90.5\" A3=\"91.25\" A4=\"0.0\" A5=\"45.125\" A6=\"-180.0\" />\r\n";
  if (with_currents) s += "<MACur A1=\"1.5\" A2=\"-2.25\" A3=\"0.125\" A4=\"0.0\" A5=\"3.0\" A6=\"-0.5\" />\r\n";
  s += "<Delay D=\"" + std::to_string(k % 3) + "\" />\r\n"
       "<GearTorque A1=\"1\" A2=\"2\" A3=\"3\" A4=\"4\" A5=\"5\" A6=\"6\" />\r\n"
       "<Status>3</Status>\r\n<Override>100</Override>\r\n"
       "<IPOC>" + std::to_string(ipoc) + "</IPOC>\r\n</Rob>";
  return s;
}

// The numbers of one printed cycle line (the cycle time "-" of a session's first line as NaN).
QList<double> numbers(const QString& line) {
  QList<double> out;
  for (const QString& word : line.split(' ', Qt::SkipEmptyParts)) out.append(word == "-" ? NAN : word.toDouble());
  return out;
}

}  // namespace

class TestRciCliRsi : public QObject {
  Q_OBJECT

 private slots:
  void stateAnswersEveryRobAndPrintsItsValues();
  void stateSaysWhatTheConfigDoesNotSend();
  void stateGivesUpWithoutARobot();
  void stateNamesTheConfigsFileAndLine();
  void benchRsiPrintsItsTable();
};

void TestRciCliRsi::stateAnswersEveryRobAndPrintsItsValues() {
  QProcess cli;
  startCli(cli, {"state", "--robot", "rsi:" + sampleConfig(), "--model", "kr6_r900_sixx", "--bind", "127.0.0.1",
                 "--port", "0", "--count", "5"});
  QVERIFY(cli.waitForStarted());
  QStringList intro;
  const uint16_t port = waitingPort(cli, &intro);
  QVERIFY2(port != 0, qPrintable(intro.join('\n') + cli.readAllStandardError()));
  QVERIFY2(intro.join('\n').contains("over RSI, RSI_EthernetConfig.xml (Type ImFree); every <Rob> is answered with "
                                     "zero axis corrections (AK): the robot holds still"),
           qPrintable(intro.join('\n')));

  FakeKrc krc(port);
  const uint64_t first_ipoc = 4'294'967'290ull;  // crosses 2^32: a 64-bit IPOC, echoed verbatim
  for (int k = 0; k < 5; ++k) {
    const uint64_t ipoc = first_ipoc + 4 * uint64_t(k);
    const std::string sen = krc.exchange(rob(ipoc, k));
    QVERIFY2(!sen.empty(), "no answer from rci-cli");
    QCOMPARE(QString::fromStdString(sen),
             QString("<Sen Type=\"ImFree\"><EStr></EStr><AK A1=\"0.0000\" A2=\"0.0000\" A3=\"0.0000\" A4=\"0.0000\" "
                     "A5=\"0.0000\" A6=\"0.0000\" /><Stop>0</Stop><Digout o1=\"0\" o2=\"0\" o3=\"0\" o4=\"0\" o5=\"0\" o6=\"0\" o7=\"0\" o8=\"0\" /><IPOC>%1</IPOC></Sen>")
                 .arg(ipoc));
    std::this_thread::sleep_for(std::chrono::milliseconds(4));
  }
  QVERIFY(cli.waitForFinished(20000));
  QCOMPARE(cli.exitCode(), 0);

  QStringList lines;
  for (QString line = readLine(cli); !line.isEmpty(); line = readLine(cli)) lines.append(line);
  const QString all = lines.join('\n');
  QCOMPARE(lines.value(0), QString("# session 1: the robot sends (first IPOC %1)").arg(first_ipoc));
  QCOMPARE(lines.value(1), QString("# IPOC  cycle[ms]  A1 A2 A3 A4 A5 A6 [deg]  X Y Z [mm]  A B C [deg]  "
                                   "MACur A1..A6  Delay"));
  // The cycle lines (a loaded machine may pause the fake KRC past the link's silence, which adds a
  // "stopped sending" and a new session's lines in between: not what is checked here).
  QStringList data;
  for (const QString& line : lines)
    if (!line.startsWith('#')) data.append(line);
  QCOMPARE(data.size(), 5);
  for (int k = 0; k < 5; ++k) {
    const QList<double> v = numbers(data[k]);
    QCOMPARE(v.size(), 2 + 6 + 3 + 3 + 6 + 1);
    QCOMPARE(uint64_t(v[0]), first_ipoc + 4 * uint64_t(k));
    if (k == 0) QVERIFY(std::isnan(v[1]));  // the cycle time: "-" on a session's first line
    if (!std::isnan(v[1])) QVERIFY2(v[1] > 0, qPrintable(data[k]));
    const QList<double> axes{10.0 + k, -90.5, 91.25, 0, 45.125, -180};
    for (int i = 0; i < 6; ++i) QCOMPARE(v[2 + i], axes[i]);
    const QList<double> pose{445.5 + k, -12.25, 900.125, 179.5, 0, 0};
    for (int i = 0; i < 6; ++i) QCOMPARE(v[8 + i] + 1.0, pose[i] + 1.0);  // "-0.000000", "1e-05" print as 0
    const QList<double> currents{1.5, -2.25, 0.125, 0, 3, -0.5};
    for (int i = 0; i < 6; ++i) QCOMPARE(v[14 + i], currents[i]);
    QCOMPARE(v[20], double(k % 3));
  }
  QVERIFY2(lines.last().startsWith("# 5 received, 5 answered, 0 refused,"), qPrintable(all));
  QVERIFY2(!intro.join(QChar(10)).contains("not sent by this config"), qPrintable(intro.join(QChar(10))));
}

void TestRciCliRsi::stateSaysWhatTheConfigDoesNotSend() {
  QFile sample(sampleConfig());
  QVERIFY(sample.open(QIODevice::ReadOnly));
  QString text = QString::fromUtf8(sample.readAll());
  text.remove(QRegularExpression("\\s*<ELEMENT TAG=\"DEF_MACur\"[^>]*>"));
  QTemporaryDir dir;
  QFile config(dir.filePath("NoCurrents.xml"));
  QVERIFY(config.open(QIODevice::WriteOnly));
  config.write(text.toUtf8());
  config.close();

  QProcess cli;
  startCli(cli, {"state", "--robot", "rsi:" + config.fileName(), "--model", "kr16_2", "--bind", "127.0.0.1", "--port",
                 "0", "--count", "2"});
  QVERIFY(cli.waitForStarted());
  QStringList intro;
  const uint16_t port = waitingPort(cli, &intro);
  QVERIFY2(port != 0, qPrintable(intro.join('\n') + cli.readAllStandardError()));
  QVERIFY2(intro.contains("# not sent by this config, so not shown: DEF_MACur (motor currents)"),
           qPrintable(intro.join('\n')));
  FakeKrc krc(port);
  QVERIFY(!krc.exchange(rob(7, 0, false)).empty());
  QVERIFY(!krc.exchange(rob(11, 1, false)).empty());
  QVERIFY(cli.waitForFinished(20000));
  QCOMPARE(cli.exitCode(), 0);
  readLine(cli);  // # session 1
  QCOMPARE(readLine(cli), QString("# IPOC  cycle[ms]  A1 A2 A3 A4 A5 A6 [deg]  X Y Z [mm]  A B C [deg]  Delay"));
  QCOMPARE(numbers(readLine(cli)).size(), 2 + 6 + 6 + 1);
}

void TestRciCliRsi::stateGivesUpWithoutARobot() {
  QProcess cli;
  startCli(cli, {"state", "--robot", "rsi:" + sampleConfig(), "--model", "kr6_r900_sixx", "--bind", "127.0.0.1",
                 "--port", "0", "--wait", "1"});
  QVERIFY(cli.waitForFinished(20000));
  QCOMPARE(cli.exitCode(), 1);
  const QString err = cli.readAllStandardError();
  QVERIFY2(QRegularExpression("^rci-cli: no <Rob> from the robot on 127\\.0\\.0\\.1:\\d+ for 1 s; check that the KRL "
                              "program runs RSI_ON").match(err).hasMatch(),
           qPrintable(err));
  QVERIFY2(err.contains("--wait S waits longer"), qPrintable(err));
}

void TestRciCliRsi::stateNamesTheConfigsFileAndLine() {
  QTemporaryDir dir;
  QFile config(dir.filePath("Broken.xml"));
  QVERIFY(config.open(QIODevice::WriteOnly));
  config.write("<ROOT>\n<CONFIG>\n<IP_NUMBER>127.0.0.1</IP_NUMBER>\n<PORT>70000</PORT>\n<SENTYPE>ImFree</SENTYPE>\n"
               "</CONFIG>\n</ROOT>\n");
  config.close();
  QProcess cli;
  startCli(cli, {"state", "--robot", "rsi:" + config.fileName(), "--model", "kr16_2"});
  QVERIFY(cli.waitForFinished(20000));
  QCOMPARE(cli.exitCode(), 1);
  const QString err = cli.readAllStandardError();
  QVERIFY2(err.startsWith("rci-cli: " + config.fileName() + ":4: "), qPrintable(err));
}

void TestRciCliRsi::benchRsiPrintsItsTable() {
  QProcess cli;
  startCli(cli, {"bench", "rsi", "--cycles", "200"});
  QVERIFY(cli.waitForFinished(60000));
  const QString out = cli.readAllStandardOutput();
  QVERIFY2(cli.exitCode() == 0, qPrintable(out + cli.readAllStandardError()));
  QVERIFY2(QRegularExpression("^rci-cli bench rsi: 200 cycles, one thread, loopback; 1000 generated <Rob> datagrams of "
                              "\\d+-\\d+ bytes \\(47 values\\) for the sample config, <Sen> of \\d+ bytes\n")
               .match(out)
               .hasMatch(),
           qPrintable(out));
  const QString number = "\\s+\\d+\\.\\d{3}";
  for (const QString row : {"ours: parse <Rob> \\+ publish \\+ callback \\+ compose <Sen>", "ours: the whole cycle, with the sendto",
                            "reference: tinyxml2 DOM parse \\+ callback \\+ compose", "reference: tinyxml2 DOM, with the sendto",
                            "reference: raw sendto of \\d+ bytes"})
    QVERIFY2(QRegularExpression("\n  " + row + number + number + number + "\n").match(out).hasMatch(),
             qPrintable(row + "\n" + out));
  QVERIFY2(QRegularExpression("\n  ours vs DOM \\(medians\\): \\d+\\.\\dx faster without the send, \\d+\\.\\dx with it \\(parse \\d+\\.\\dx, compose \\d+\\.\\dx\\)\n")
               .match(out)
               .hasMatch(),
           qPrintable(out));
  QVERIFY2(out.contains("agreement: both parsers read the same 47 values and IPOC from all 1000 datagrams; "),
           qPrintable(out));
}

QTEST_MAIN(TestRciCliRsi)
#include "test_rci_cli_rsi.moc"
