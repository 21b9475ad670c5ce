// SPDX-License-Identifier: Apache-2.0
// Tests of rci-sim's control port: each command over a real TCP connection, its effect as a client
// sees it on the RCI wire, and the error messages for wrong input.
#include <QtTest>

#include "sim/server_control.h"
#include "test_support.h"

using namespace simtest;
using namespace xmate;
using protocol::Command;

namespace {

// One control-port connection: sends a line, returns the answer line.
class ControlClient {
 public:
  explicit ControlClient(uint16_t port)
      : conn_(net::TcpConnection::connect(net::makeEndpoint("127.0.0.1", port), 2000)) {}

  std::string ask(const std::string& line) {
    const std::string out = line + "\n";
    if (conn_.sendAll(out.data(), out.size(), 2000) != net::IoResult::kOk) throw std::runtime_error("cannot send");
    std::string answer;
    for (;;) {
      char ch = 0;
      const net::IoResult r = conn_.readExact(&ch, 1, 10000);
      if (r != net::IoResult::kOk) throw std::runtime_error(std::string("no answer: ") + net::toString(r));
      if (ch == '\n') return answer;
      answer += ch;
    }
  }

  net::TcpConnection& connection() { return conn_; }

 private:
  net::TcpConnection conn_;
};

// Value of key in a "k=v k=v" status line ("" if absent).
QString field(const std::string& status, const QString& key) {
  for (const QString& pair : QString::fromStdString(status).split(' ')) {
    if (pair.startsWith(key + "=")) return pair.mid(key.size() + 1);
  }
  return {};
}

}  // namespace

class TestSimControlPort : public QObject {
  Q_OBJECT

 private slots:
  void sceneCommandsReachTheWire() {
    auto server = startServer();
    sim::ControlPort port(*server, "127.0.0.1", 0);
    port.start();
    ControlClient control(port.port());
    auto client = connectedClient(*server);

    QCOMPARE(QString::fromStdString(control.ask("estop on")), QString("ok estop on"));
    QCOMPARE(int(client->requestByte(Command::kGetSafetyStopState)), 1);  // wire: 1 = ESTOP
    QCOMPARE(control.ask("estop off"), std::string("ok estop off"));
    QCOMPARE(control.ask("gstop on"), std::string("ok gstop on"));
    QCOMPARE(int(client->requestByte(Command::kGetSafetyStopState)), 2);  // wire: 2 = GSTOP
    QCOMPARE(control.ask("gstop off"), std::string("ok gstop off"));
    QCOMPARE(int(client->requestByte(Command::kGetSafetyStopState)), 0);

    QCOMPARE(control.ask("di 3 1"), std::string("ok di 3 = 1"));
    QVERIFY(client->digitalInput(3));
    QVERIFY(!client->digitalInput(2));
    QCOMPARE(control.ask("loopback on"), std::string("ok loopback on"));
    QCOMPARE(int(client->requestByte(protocol::SetDORequest{5, true})), 0);
    QVERIFY(client->digitalInput(5));

    QVERIFY(control.ask("wrench 0 0 -20 0 0.5 0").starts_with("ok wrench 0 0 -20 N, 0 0.5 0 Nm"));
    const std::array<double, 6> expected{0, 0, -20, 0, 0.5, 0};
    QCOMPARE(server->status().sim.external_wrench, expected);

    QCOMPARE(control.ask("payload 2.5 0 0 0.1"), std::string("ok payload 2.5 kg at 0 0 0.1 m (flange frame, point mass)"));
    QCOMPARE(server->status().sim.actual_payload_mass, 2.5);
    QVERIFY(!server->status().sim.actual_payload_follows_load);

    const std::string status = control.ask("status");
    QVERIFY(status.starts_with("ok running=1 "));
    QCOMPARE(field(status, "payload"), QString("2.5"));
    QCOMPARE(field(status, "payload_follows_load"), QString("0"));
    QCOMPARE(field(status, "session"), QString("1"));
    QCOMPARE(field(status, "streaming"), QString("1"));
    QCOMPARE(field(status, "client"), QString("127.0.0.1:%1").arg(client->udpPort()));
    QCOMPARE(field(status, "safety_stop"), QString("none"));
    QCOMPARE(field(status, "di"), QString("000001"));  // with loop-back on, each DI follows its DO
    QCOMPARE(field(status, "do"), QString("000001"));
    QCOMPARE(field(status, "wrench"), QString("0,0,-20,0,0.5,0"));
    QCOMPARE(control.ask("payload follow"), std::string("ok payload follows the configured load (setLoad)"));
    QVERIFY(server->status().sim.actual_payload_follows_load);
  }

  void packetFaultCommandsAreApplied() {
    auto server = startServer();
    sim::ControlPort port(*server, "127.0.0.1", 0);
    port.start();
    ControlClient control(port.port());
    auto client = connectedClient(*server);

    QCOMPARE(control.ask("drop states 3"), std::string("ok dropping the next 3 states"));
    QCOMPARE(control.ask("corrupt states 2"), std::string("ok corrupting the next 2 states"));
    // One after the other, so no datagram is both corrupted and shortened.
    QVERIFY(eventually([&] { return server->status().counters.states_corrupted == 2; }));
    QCOMPARE(control.ask("badlength states 1"), std::string("ok shortening the next 1 states"));
    QCOMPARE(control.ask("reorder states 2"), std::string("ok reordering the next 2 states"));
    QCOMPARE(control.ask("drop commands 4"), std::string("ok dropping the next 4 commands"));
    QCOMPARE(control.ask("delay commands 2 15"), std::string("ok delaying the next 2 commands by 15 ms"));
    QVERIFY(eventually([&] {
      const sim::ServerCounters c = server->status().counters;
      return c.states_dropped == 3 && c.states_corrupted == 2 && c.states_wrong_length == 1 &&
             c.states_reordered == 2;
    }));
    // Every faulty datagram was sent before the state that is newest now.
    const uint64_t first_clean = server->status().message_id;
    int bad_value = 0, wrong_length = 0;
    for (;;) {
      const std::optional<Datagram> d = client->receive(5000);
      QVERIFY(d.has_value());
      RCI::robot::RobotState s;
      const protocol::DecodeStatus st = d->decode(s);
      bad_value += st == protocol::DecodeStatus::kBadValue;
      wrong_length += st == protocol::DecodeStatus::kWrongLength;
      if (st == protocol::DecodeStatus::kOk && s.message_id >= first_clean) break;
    }
    QCOMPARE(bad_value, 2);
    QCOMPARE(wrong_length, 1);
    const std::string status = control.ask("status");
    QCOMPARE(field(status, "pending_drop_commands"), QString("4"));  // no command was sent yet
    QCOMPARE(field(status, "pending_delay_commands"), QString("2"));
    QCOMPARE(field(status, "pending_drop_states"), QString("0"));
  }

  void wrongInputGetsAnErrorWithTheUsage() {
    auto server = startServer();
    sim::ControlPort port(*server, "127.0.0.1", 0);
    port.start();
    ControlClient control(port.port());
    const std::pair<const char*, const char*> cases[] = {
        {"frobnicate", "error unknown command 'frobnicate'; type help for the list"},
        {"", "error empty line; type help"},
        {"estop maybe", "error estop: expected on or off, got 'maybe'; usage: estop on|off"},
        {"wrench 1 2 3",
         "error wrench: expected 6 arguments, got 3; usage: wrench FX FY FZ TX TY TZ (N, Nm; base frame, at the TCP)"},
        {"wrench 1 2 3 4 5 nan",
         "error wrench: tz must be a finite number, got 'nan'; usage: wrench FX FY FZ TX TY TZ (N, Nm; base frame, "
         "at the TCP)"},
        {"di 7 1", "error di: the input index must be a whole number from 0 to 5, got '7'; usage: di INDEX(0-5) "
                   "LEVEL(0|1)"},
        {"di 1 2", "error di: the level must be a whole number from 0 to 1, got '2'; usage: di INDEX(0-5) LEVEL(0|1)"},
        {"drop states x", "error drop: N must be a whole number from 1 to 1000000, got 'x'; usage: drop states N | "
                          "drop commands N"},
        {"drop packets 3", "error drop: expected 'states' or 'commands', got 'packets'; usage: drop states N | drop "
                           "commands N"},
        {"delay states 1 5", "error delay: only commands can be delayed, got 'states'; usage: delay commands N MS"},
        {"delay commands 1 -5", "error delay: MS must be a whole number from 0 to 60000, got '-5'; usage: delay "
                                "commands N MS"},
        {"corrupt commands 2", "error corrupt: this fault applies to states only, got 'commands'; usage: corrupt "
                               "states N"},
        {"status now", "error status: expected 0 arguments, got 1; usage: status"},
        {"payload -1", "error payload: setActualPayload: the mass must be a finite number >= 0 kg, got -1"},
        {"payload 1 2", "error payload: expected 1 or 4 arguments, got 2; usage: payload KG [CX CY CZ] (what really "
                        "hangs on the flange) | payload follow"},
    };
    for (const auto& [line, expected] : cases) QCOMPARE(QString::fromStdString(control.ask(line)), QString(expected));
    const std::string help = control.ask("help");
    QVERIFY(help.starts_with("ok commands: | wrench FX FY FZ TX TY TZ"));
    for (const char* name : {"estop", "gstop", "di ", "loopback", "payload", "drop", "delay", "reorder", "corrupt",
                             "badlength", "status", "kill", "restart", "quit"})
      QVERIFY2(help.find(name) != std::string::npos, name);
    // Nothing above changed the simulator.
    QCOMPARE(server->status().pending.drop_states, 0);
    QCOMPARE(server->status().sim.safety_stop, 1);
  }

  // "loss ..." starts a random loss that keeps running; "loss off" ends it, and the stream is whole again.
  void stateLossRunsUntilSwitchedOff() {
    auto server = startServer();
    sim::ControlPort port(*server, "127.0.0.1", 0);
    port.start();
    ControlClient control(port.port());
    auto client = connectedClient(*server);

    QCOMPARE(control.ask("loss states 20% pairs 50% seed 3"),
             std::string("ok losing 20 % of the states at random, 50 % of the losses in pairs; seed 3"));
    QCOMPARE(field(control.ask("status"), "loss"), QString("20%,pairs=50%,seed=3"));
    QVERIFY(eventually([&] { return server->status().counters.loss_pairs >= 10; }));
    const std::string off = control.ask("loss off");
    QVERIFY2(off.starts_with("ok state loss off (") && off.ends_with(" states lost so far)"), off.c_str());
    const std::string status = control.ask("status");
    QCOMPARE(field(status, "loss"), QString("off"));
    const uint64_t lost = server->status().counters.states_lost;
    QCOMPARE(field(status, "states_lost"), QString::number(lost));
    QVERIFY(field(status, "loss_singles").toInt() > 0);

    const uint64_t first_clean = server->status().message_id;
    std::optional<RCI::robot::RobotState> s;
    do {
      s = client->receiveState(5000);
      QVERIFY(s.has_value());
    } while (s->message_id < first_clean);
    for (int i = 0; i < 500; ++i) {
      const uint64_t before = s->message_id;
      s = client->receiveState(5000);
      QVERIFY(s.has_value());
      QCOMPARE(s->message_id, before + 1);
    }
    QCOMPARE(server->status().counters.states_lost, lost);

    QCOMPARE(control.ask("loss burst 5 every 10000"), std::string("ok losing 5 states in a row every 10000 ms; seed 1"));
    QCOMPARE(control.ask("loss states 2% pairs 30% burst 5 every 10000 seed 7"),
             std::string("ok losing 2 % of the states at random, 30 % of the losses in pairs, and 5 states in a "
                         "row every 10000 ms; seed 7"));
    QCOMPARE(field(control.ask("status"), "loss"), QString("2%,pairs=30%,burst=5/10000ms,seed=7"));
  }

  void badLossArgumentsAreRefusedNamingTheProblem() {
    auto server = startServer();
    sim::ControlPort port(*server, "127.0.0.1", 0);
    port.start();
    ControlClient control(port.port());
    const std::string usage =
        "; usage: loss states P% [pairs S%] [burst B every MS] [seed N] (until loss off) | loss off";
    const std::pair<const char*, std::string> cases[] = {
        {"loss", "error loss: expected 'off' or what to lose" + usage},
        {"loss sometimes", "error loss: expected states, pairs, burst or seed, got 'sometimes'" + usage},
        {"loss states 70%", "error loss: P must be a percentage from 0 to 50, got '70%'" + usage},
        {"loss states two", "error loss: P must be a percentage from 0 to 50, got 'two'" + usage},
        {"loss states", "error loss: 'states' needs P%" + usage},
        {"loss states 2% pairs x", "error loss: S must be a percentage from 0 to 100, got 'x'" + usage},
        {"loss states 2% states 3%", "error loss: 'states' is given twice" + usage},
        {"loss pairs 30%", "error loss: say which states to lose: 'states P%', 'burst B every MS' or both" + usage},
        {"loss states 2% burst 5", "error loss: 'burst' needs B every MS" + usage},
        {"loss states 2% burst 5 each 100", "error loss: expected 'every' after the burst's length, got 'each'" + usage},
        {"loss burst 0 every 100", "error loss: B must be a whole number from 1 to 10000, got '0'" + usage},
        {"loss states 2% seed -1", "error loss: N must be a whole number from 0 to 2147483647, got '-1'" + usage},
        {"loss burst 5 every 5", "error loss: setStateLoss: a burst of 5 states needs a period of 6..3600000 ms, got 5"},
    };
    for (const auto& [line, expected] : cases) QCOMPARE(QString::fromStdString(control.ask(line)), QString::fromStdString(expected));
    QVERIFY(control.ask("help").find("| loss states P% [pairs S%] [burst B every MS] [seed N]") != std::string::npos);
    QCOMPARE(field(control.ask("status"), "loss"), QString("off"));  // nothing above started a loss
  }

  void killAndRestartThroughTheControlPort() {
    auto server = startServer();
    sim::ControlPort port(*server, "127.0.0.1", 0);
    port.start();
    ControlClient control(port.port());
    auto client = connectedClient(*server);
    QVERIFY(control.ask("kill").starts_with("ok killed"));
    uint8_t byte = 0;
    QCOMPARE(client->tcp().readExact(&byte, 1, 10000), net::IoResult::kClosed);
    QCOMPARE(field(control.ask("status"), "killed"), QString("1"));
    QVERIFY_THROWS_EXCEPTION(std::runtime_error, RawClient{server->port()});
    QCOMPARE(control.ask("restart"),
             "ok restarted: a fresh controller listens on port " + std::to_string(server->port()));
    auto again = connectedClient(*server);
    QCOMPARE(field(control.ask("status"), "killed"), QString("0"));
  }

  void quitEndsTheConnectionAndTheNextOneIsServed() {
    auto server = startServer();
    sim::ControlPort port(*server, "127.0.0.1", 0);
    port.start();
    {
      ControlClient first(port.port());
      const std::string out = "quit\n";
      QCOMPARE(first.connection().sendAll(out.data(), out.size(), 2000), net::IoResult::kOk);
      char ch = 0;
      QCOMPARE(first.connection().readExact(&ch, 1, 10000), net::IoResult::kClosed);
    }
    ControlClient second(port.port());
    QVERIFY(second.ask("status").starts_with("ok running=1"));
  }
};

QTEST_APPLESS_MAIN(TestSimControlPort)
#include "test_sim_control_port.moc"
