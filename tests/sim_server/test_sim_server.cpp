// SPDX-License-Identifier: Apache-2.0
// Tests of sim::Server over real loopback sockets with a raw client: the Connect handshake, the
// 1 kHz stream, lock-step stepping and lost answers, every packet fault as seen on the wire (the
// random state loss too), session rules (one at a time, the busy answer naming the holder, idle
// connections and silent sessions giving way), reboot, kill, and the bind failure message.
#include <QtTest>

#include <arpa/inet.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <map>
#include <stdexcept>
#include <thread>
#include <vector>

#include <xmate/exception.h>
#include <xmate/robot.h>

#include "sim/server_faults.h"
#include "test_support.h"

using namespace simtest;
using namespace xmate;
using protocol::Command;
using protocol::DecodeStatus;
using RCI::robot::RobotState;

namespace {

// message_id sits in the first 8 bytes (big-endian) of every state, even a corrupted one.
uint64_t rawMessageId(const Datagram& d) {
  uint64_t id = 0;
  for (int i = 0; i < 8; ++i) id = id << 8 | d.bytes[size_t(i)];
  return id;
}

std::vector<Datagram> collect(RawClient& client, int count) {
  std::vector<Datagram> out;
  while (int(out.size()) < count) {
    std::optional<Datagram> d = client.receive(5000);
    if (!d) throw std::runtime_error("the stream stopped after " + std::to_string(out.size()) + " datagrams");
    out.push_back(*d);
  }
  return out;
}

// Waits until the server has applied a whole packet fault (done() on its pending faults), then
// returns every datagram received up to the first one sent after that: all the faulty ones.
std::vector<Datagram> collectFault(RawClient& client, const sim::Server& server,
                                   const std::function<bool(const sim::PendingFaults&)>& done) {
  if (!eventually([&] { return done(server.status().pending); }))
    throw std::runtime_error("the fault was never applied");
  const uint64_t first_clean = server.status().message_id;
  std::vector<Datagram> out;
  for (;;) {
    std::optional<Datagram> d = client.receive(5000);
    if (!d) throw std::runtime_error("the stream stopped after " + std::to_string(out.size()) + " datagrams");
    out.push_back(*d);
    if (rawMessageId(*d) >= first_clean) return out;
  }
}

std::vector<uint64_t> idsOf(const std::vector<Datagram>& datagrams) {
  std::vector<uint64_t> ids;
  for (const Datagram& d : datagrams) ids.push_back(rawMessageId(d));
  return ids;
}

// The state the lock-step server is waiting on (it cannot move on without our answer).
RobotState awaitWantedState(RawClient& client, const sim::Server& server) {
  for (int i = 0; i < 20000; ++i) {
    const std::optional<RobotState> s = client.receiveState(5000);
    if (!s) throw std::runtime_error("no state while waiting for the one that needs an answer");
    if (server.status().awaiting_answer_to == s->message_id) return *s;
  }
  throw std::runtime_error("no state needing an answer arrived");
}

uint8_t wireSafetyStop(RawClient& client) { return client.requestByte(Command::kGetSafetyStopState); }

// The gaps in a stream of message_ids, by the number of states missing in a row.
std::map<uint64_t, int> gapsByLength(const std::vector<uint64_t>& ids) {
  std::map<uint64_t, int> gaps;
  for (size_t i = 1; i < ids.size(); ++i)
    if (ids[i] > ids[i - 1] + 1) ++gaps[ids[i] - ids[i - 1] - 1];
  return gaps;
}

// Answers every state (holding the arm) until `until` says stop; returns the message_ids seen.
std::vector<uint64_t> answerEveryState(RawClient& client, const std::function<bool(uint64_t id)>& until) {
  std::vector<uint64_t> ids;
  for (;;) {
    const std::optional<RobotState> s = client.receiveState(5000);
    if (!s) throw std::runtime_error("the stream stopped after " + std::to_string(ids.size()) + " states");
    client.answer(*s);
    ids.push_back(s->message_id);
    if (until(s->message_id)) return ids;
  }
}

}  // namespace

class TestSimServer : public QObject {
  Q_OBJECT

 private slots:
  void connectHandshakeStartsTheStream() {
    auto server = startServer();
    RawClient client(server->port());
    QVERIFY(!client.receive(100));  // nothing before Connect
    QCOMPARE(int(client.handshake()), int(protocol::ConnectStatus::kSuccess));
    const std::optional<RobotState> state = client.receiveState(5000);
    QVERIFY(state.has_value());
    const sim::ServerStatus st = server->status();
    QVERIFY(st.session);
    QVERIFY(st.streaming);
    QCOMPARE(QString::fromStdString(st.client), QString("127.0.0.1:%1").arg(client.udpPort()));
    QCOMPARE(st.counters.sessions, uint64_t(1));
  }

  void incompatibleConnectGetsNoStream() {
    sim::ServerConfig config;
    config.sim.reject_connect_as_incompatible = true;
    auto server = startServer(config);
    RawClient client(server->port());
    QCOMPARE(int(client.handshake()), int(protocol::ConnectStatus::kIncompatibleLibraryVersion));
    QVERIFY(!client.receive(300));
    QVERIFY(!server->status().streaming);
  }

  void statesStreamWithIncreasingMessageIds() {
    auto server = startServer();
    auto client = connectedClient(*server);
    const std::vector<Datagram> datagrams = collect(*client, 300);
    for (size_t i = 0; i < datagrams.size(); ++i) {
      QCOMPARE(datagrams[i].size, long(protocol::kRobotStateSize));
      RobotState s;
      QCOMPARE(datagrams[i].decode(s), DecodeStatus::kOk);
      if (i > 0) QCOMPARE(rawMessageId(datagrams[i]), rawMessageId(datagrams[i - 1]) + 1);
    }
    QVERIFY(server->status().counters.cycles >= 300);
  }

  void lockStepAdvancesOneCyclePerAnswer() {
    auto server = startServer(lockStepConfig(20000));
    auto client = connectedClient(*server);
    startJointMotion(*client);
    RobotState state = awaitWantedState(*client, *server);
    for (int i = 0; i < 30; ++i) {
      const uint64_t cycles = server->status().counters.cycles;
      if (i % 10 == 0) QVERIFY(!client->receive(100));  // without an answer the simulator waits
      QCOMPARE(server->status().counters.cycles, cycles);
      client->answer(state);
      const std::optional<RobotState> next = client->receiveState(5000);
      QVERIFY(next.has_value());
      QCOMPARE(next->message_id, state.message_id + 1);
      QCOMPARE(server->status().counters.cycles, cycles + 1);
      state = *next;
    }
    const sim::ServerStatus st = server->status();
    QCOMPARE(st.counters.commands_used, uint64_t(30));
    QCOMPARE(st.counters.commands_lost, uint64_t(0));
    client->answer(state, /*finished=*/true);
    QVERIFY(eventually([&] { return !server->status().sim.motion_active; }));
  }

  void lostAnswerIsCountedAfterTheTimeout() {
    auto server = startServer(lockStepConfig(200));
    auto client = connectedClient(*server);
    startJointMotion(*client);
    const RobotState unanswered = awaitWantedState(*client, *server);
    const std::optional<RobotState> next = client->receiveState(10000);  // after the 200 ms timeout
    QVERIFY(next.has_value());
    QCOMPARE(next->message_id, unanswered.message_id + 1);
    sim::ServerStatus st = server->status();
    QCOMPARE(st.counters.commands_lost, uint64_t(1));
    QVERIFY(st.sim.lost_commands >= 1);  // the controller saw the loss, too
    client->answer(*next);
    const std::optional<RobotState> after = client->receiveState(10000);
    QVERIFY(after.has_value());
    QCOMPARE(after->message_id, next->message_id + 1);
    QCOMPARE(server->status().counters.commands_lost, uint64_t(1));
  }

  void droppedStatesLeaveAGapOfExactlyN() {
    auto server = startServer();
    auto client = connectedClient(*server);
    const std::optional<RobotState> before = client->receiveState(5000);
    QVERIFY(before.has_value());
    server->dropStates(5);
    std::vector<uint64_t> ids =
        idsOf(collectFault(*client, *server, [](const sim::PendingFaults& p) { return p.drop_states == 0; }));
    ids.insert(ids.begin(), before->message_id);
    int gaps_of_five = 0;
    for (size_t i = 1; i < ids.size(); ++i) {
      QVERIFY(ids[i] > ids[i - 1]);
      if (ids[i] - ids[i - 1] == 6) ++gaps_of_five;
    }
    QCOMPARE(gaps_of_five, 1);
    QCOMPARE(server->status().counters.states_dropped, uint64_t(5));
    QCOMPARE(server->status().pending.drop_states, 0);
  }

  // 2 % of the states lost at random, 30 % of the losses pairs, a burst of 5 every 5000 states, over
  // 20000 states of a motion on the lock-step clock: the wire shows exactly the losses the counters
  // report, singles, pairs and bursts only (a sent state after each), at about the rates asked.
  void randomStateLossFollowsItsSetting() {
    auto server = startServer(lockStepConfig(5));  // a lost state's cycle waits 5 ms for its answer
    auto client = connectedClient(*server);
    startJointMotion(*client);
    client->answer(awaitWantedState(*client, *server));
    server->setStateLoss({0.02, 0.3, 5, 5000, 7});
    QCOMPARE(server->status().state_loss.seed, uint32_t(7));
    const uint64_t first = server->status().message_id;
    std::vector<uint64_t> ids = answerEveryState(*client, [&](uint64_t id) { return id >= first + 20000; });
    server->setStateLoss({});
    const uint64_t off = server->status().message_id;
    const std::vector<uint64_t> tail = answerEveryState(*client, [&](uint64_t id) { return id > off + 100; });
    ids.insert(ids.end(), tail.begin(), tail.end());

    const sim::ServerCounters c = server->status().counters;
    std::map<uint64_t, int> gaps = gapsByLength(ids);
    QCOMPARE(uint64_t(gaps[1]), c.loss_singles);
    QCOMPARE(uint64_t(gaps[2]), c.loss_pairs);
    QCOMPARE(uint64_t(gaps[5]), c.loss_bursts);
    QCOMPARE(gaps.size(), size_t(3));  // no other lengths: losses never merge
    QCOMPARE(c.states_lost, c.loss_singles + 2 * c.loss_pairs + 5 * c.loss_bursts);
    QCOMPARE(c.states_dropped, c.states_lost);
    QVERIFY2(c.loss_bursts == 3 || c.loss_bursts == 4, qPrintable(QString::number(c.loss_bursts)));
    const double states = double(off - first);
    const double random_share = double(c.loss_singles + 2 * c.loss_pairs) / states;
    QVERIFY2(random_share > 0.015 && random_share < 0.025, qPrintable(QString::number(random_share)));
    const double pair_share = double(c.loss_pairs) / double(c.loss_singles + c.loss_pairs);
    QVERIFY2(pair_share > 0.22 && pair_share < 0.38, qPrintable(QString::number(pair_share)));
    QVERIFY(!server->status().state_loss.active());
  }

  // The pattern depends on the seed alone: the same seed gives the same losses, another seed others.
  void stateLossIsTheSameForTheSameSeed() {
    const auto pattern = [](uint32_t seed) {
      sim::LossRun run;
      sim::ServerCounters counters;
      sim::startStateLoss(run, {0.02, 0.3, 5, 1000, seed});
      std::vector<bool> lost(20000);
      for (size_t i = 0; i < lost.size(); ++i) lost[i] = sim::nextStateLost(run, counters);
      return lost;
    };
    QVERIFY(pattern(7) == pattern(7));
    QVERIFY(pattern(7) != pattern(8));
  }

  void badStateLossIsRefusedNamingTheValue() {
    auto server = startServer();
    const std::pair<sim::StateLoss, const char*> cases[] = {
        {{0.7, 0, 0, 0, 1}, "setStateLoss: the loss probability must be 0..0.5 (0..50 %), got 0.7"},
        {{std::nan(""), 0, 0, 0, 1}, "setStateLoss: the loss probability must be 0..0.5 (0..50 %), got nan"},
        {{0.02, 1.5, 0, 0, 1}, "setStateLoss: the share of pairs must be 0..1 (0..100 %), got 1.5"},
        {{0, 0, 5, 0, 1}, "setStateLoss: a burst needs both its length and its period (or neither), got 5 states "
                          "every 0 ms"},
        {{0, 0, 5, 5, 1}, "setStateLoss: a burst of 5 states needs a period of 6..3600000 ms, got 5"},
        {{0, 0, 20000, 100000, 1}, "setStateLoss: a burst must be 0..10000 states, got 20000"},
    };
    for (const auto& [loss, expected] : cases) {
      try {
        server->setStateLoss(loss);
        QFAIL(expected);
      } catch (const std::invalid_argument& e) {
        QCOMPARE(QString(e.what()), QString(expected));
      }
    }
    QVERIFY(!server->status().state_loss.active());
  }

  void reorderedStatesArriveWithPairsSwapped() {
    auto server = startServer();
    auto client = connectedClient(*server);
    server->reorderStates(4);
    const std::vector<uint64_t> ids =
        idsOf(collectFault(*client, *server, [](const sim::PendingFaults& p) { return p.reorder_states == 0; }));
    std::vector<size_t> swaps;
    for (size_t i = 1; i < ids.size(); ++i)
      if (ids[i] + 1 == ids[i - 1]) swaps.push_back(i);
    QCOMPARE(swaps.size(), size_t(2));
    QCOMPARE(swaps[1], swaps[0] + 2);  // two neighbouring pairs: b a d c
    QCOMPARE(ids[swaps[1] - 1], ids[swaps[0]] + 3);
    QCOMPARE(server->status().counters.states_reordered, uint64_t(4));
  }

  void corruptedStatesFailToDecode() {
    auto server = startServer();
    auto client = connectedClient(*server);
    server->corruptStates(3);
    const std::vector<Datagram> datagrams =
        collectFault(*client, *server, [](const sim::PendingFaults& p) { return p.corrupt_states == 0; });
    int bad = 0;
    for (const Datagram& d : datagrams) {
      QCOMPARE(d.size, long(protocol::kRobotStateSize));
      RobotState s;
      const DecodeStatus status = d.decode(s);
      QVERIFY(status == DecodeStatus::kOk || status == DecodeStatus::kBadValue);
      if (status == DecodeStatus::kBadValue) ++bad;
    }
    QCOMPARE(bad, 3);
    const std::vector<uint64_t> ids = idsOf(datagrams);
    for (size_t i = 1; i < ids.size(); ++i) QCOMPARE(ids[i], ids[i - 1] + 1);  // corrupted, not lost
  }

  void wrongLengthStatesLookLikeAnotherVersion() {
    auto server = startServer();
    auto client = connectedClient(*server);
    server->sendWrongLengthStates(2);
    int wrong = 0;
    for (const Datagram& d :
         collectFault(*client, *server, [](const sim::PendingFaults& p) { return p.wrong_length_states == 0; })) {
      RobotState s;
      if (d.size == long(protocol::kRobotStateSize)) {
        QCOMPARE(d.decode(s), DecodeStatus::kOk);
      } else {
        QCOMPARE(d.size, long(protocol::kRobotStateSize - sim::kWrongLengthDelta));
        QCOMPARE(d.decode(s), DecodeStatus::kWrongLength);
        ++wrong;
      }
    }
    QCOMPARE(wrong, 2);
  }

  void commandFaultsAndBadCommandsAreCounted() {
    auto server = startServer(lockStepConfig(500));
    auto client = connectedClient(*server);
    startJointMotion(*client);
    RobotState state = awaitWantedState(*client, *server);

    // Malformed and stale datagrams are dropped and counted; the right answer still counts.
    const uint8_t junk[10] = {1, 2, 3};
    client->sendRaw(junk, sizeof junk);
    RobotState old = state;
    old.message_id -= 3;
    client->answer(old);
    client->answer(state);
    std::optional<RobotState> next = client->receiveState(10000);
    QVERIFY(next && next->message_id == state.message_id + 1);
    sim::ServerStatus st = server->status();
    QCOMPARE(st.counters.commands_malformed, uint64_t(1));
    QCOMPARE(st.counters.commands_stale, uint64_t(1));
    QCOMPARE(st.counters.commands_lost, uint64_t(0));
    state = *next;

    // A dropped answer is lost after the timeout.
    server->dropCommands(1);
    client->answer(state);
    next = client->receiveState(10000);
    QVERIFY(next && next->message_id == state.message_id + 1);
    st = server->status();
    QCOMPARE(st.counters.commands_dropped, uint64_t(1));
    QCOMPARE(st.counters.commands_lost, uint64_t(1));
    state = *next;

    // A short delay is waited out in lock-step: the answer still counts.
    server->delayCommands(1, 30);
    client->answer(state);
    next = client->receiveState(10000);
    QVERIFY(next && next->message_id == state.message_id + 1);
    st = server->status();
    QCOMPARE(st.counters.commands_delayed, uint64_t(1));
    QCOMPARE(st.counters.commands_lost, uint64_t(1));
    const uint64_t used = st.counters.commands_used;
    state = *next;

    // A delay longer than the timeout: lost, and stale when it finally arrives.
    server->delayCommands(1, 900);
    client->answer(state);
    next = client->receiveState(10000);
    QVERIFY(next && next->message_id == state.message_id + 1);
    QCOMPARE(server->status().counters.commands_lost, uint64_t(2));
    QCOMPARE(server->status().counters.commands_used, used);
    state = *next;
    QVERIFY(eventually([&] {  // keep the motion going until the late answer turns up
      client->answer(state);
      next = client->receiveState(10000);
      if (next) state = *next;
      return server->status().counters.commands_stale == 2;
    }));
    QCOMPARE(server->status().counters.commands_lost, uint64_t(2));
  }

  void secondClientIsToldWhoHoldsTheSession() {
    auto server = startServer();
    auto client = connectedClient(*server);
    RawClient second(server->port());
    const protocol::ConnectResponse r = second.handshakeResponse();
    QCOMPARE(int(r.status), int(protocol::ConnectStatus::kBusy));
    QVERIFY(r.has_holder);
    const sockaddr_in holder = client->tcp().local().addr;
    QCOMPARE(std::memcmp(r.holder_ip.data(), &holder.sin_addr.s_addr, 4), 0);
    QCOMPARE(r.holder_port, ntohs(holder.sin_port));
    uint8_t byte = 0;
    QCOMPARE(second.tcp().readExact(&byte, 1, 10000), net::IoResult::kClosed);  // then closed
    QCOMPARE(int(client->requestByte(Command::kGetMotorState)), 0);            // the first session goes on
    QCOMPARE(server->status().counters.clients_refused, uint64_t(1));
  }

  // The client library turns the busy answer into a TcpException naming the holder.
  void libraryClientSaysWhoHoldsTheSession() {
    auto server = startServer();
    auto client = connectedClient(*server);
    xmate::Robot robot("127.0.0.1", server->port(), xmate::XMATE7_PRO);
    try {
      robot.connect();
      QFAIL("connect must fail while another client holds the session");
    } catch (const xmate::TcpException& e) {
      const QString holder = QString::fromStdString(client->tcp().local().toString());
      QVERIFY2(QString(e.what()).contains("the controller's session is held by " + holder +
                                          " (another program is connected); close that program or wait until its "
                                          "session ends"),
               e.what());
    }
    QCOMPARE(int(client->requestByte(Command::kGetMotorState)), 0);
  }

  // A connection that never sends Connect is closed after connect_timeout_ms; then a real client
  // connects.
  void idleConnectionIsDroppedAfterTheTimeout() {
    sim::ServerConfig config;
    config.connect_timeout_ms = 300;
    auto server = startServer(config);
    net::TcpConnection idle = net::TcpConnection::connect(net::makeEndpoint("127.0.0.1", server->port()), 2000);
    QVERIFY(eventually([&] { return server->status().session; }));
    uint8_t byte = 0;
    QCOMPARE(idle.readExact(&byte, 1, 10000), net::IoResult::kClosed);
    QVERIFY(eventually([&] { return !server->status().session; }));
    QCOMPARE(server->status().counters.sessions_dropped, uint64_t(1));
    xmate::Robot robot("127.0.0.1", server->port(), xmate::XMATE7_PRO);
    robot.connect();
    QCOMPARE(robot.getMotorState(), 0);
  }

  // A client's Connect takes the controller from a connection that has not sent Connect yet.
  void connectTakesOverAConnectionWithoutConnect() {
    sim::ServerConfig config;
    config.connect_timeout_ms = 600'000;  // only the takeover can end the idle connection
    auto server = startServer(config);
    net::TcpConnection idle = net::TcpConnection::connect(net::makeEndpoint("127.0.0.1", server->port()), 2000);
    QVERIFY(eventually([&] { return server->status().session; }));
    auto client = connectedClient(*server);
    uint8_t byte = 0;
    QCOMPARE(idle.readExact(&byte, 1, 10000), net::IoResult::kClosed);
    QCOMPARE(int(client->requestByte(Command::kGetMotorState)), 0);
  }

  // A silent session keeps the controller while nobody else asks; a new client's Connect then takes
  // it over. A session that is guiding (or moving) is not silent.
  void silentSessionGivesWayToANewClient() {
    sim::ServerConfig config;
    config.idle_timeout_ms = 200;
    auto server = startServer(config);
    auto first = connectedClient(*server);
    std::this_thread::sleep_for(std::chrono::milliseconds(400));  // silent beyond the timeout ...
    QCOMPARE(int(first->requestByte(Command::kGetMotorState)), 0);  // ... nobody else wants it: still served
    QCOMPARE(int(first->requestByte(protocol::SetMotorPowerRequest{1})), 0);
    QCOMPARE(int(first->requestByte(protocol::StartDragRequest{0, 2})), 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(400));  // guiding: not silent
    {
      RawClient refused(server->port());
      QCOMPARE(int(refused.handshakeResponse().status), int(protocol::ConnectStatus::kBusy));
    }
    QCOMPARE(int(first->requestByte(Command::kStopDrag)), 0);
    QVERIFY(eventually([&] { return !server->status().sim.dragging; }));
    std::this_thread::sleep_for(std::chrono::milliseconds(400));  // silent again
    auto second = connectedClient(*server);
    uint8_t byte = 0;
    QCOMPARE(first->tcp().readExact(&byte, 1, 10000), net::IoResult::kClosed);
    QCOMPARE(int(second->requestByte(Command::kGetMotorState)), 1);  // the motors stayed on
    QCOMPARE(server->status().counters.sessions_dropped, uint64_t(1));
  }

  // The client's message when the controller closes the connection without answering does not
  // blame the address (something did answer there).
  void closedWithoutAnswerDoesNotBlameTheAddress() {
    net::TcpListener listener;
    listener.listen("127.0.0.1", 0);
    std::thread closer([&] {
      auto conn = listener.accept(10000);  // accepts, then closes at once
    });
    xmate::Robot robot("127.0.0.1", listener.localPort(), xmate::XMATE7_PRO);
    try {
      robot.connect();
      QFAIL("connect must fail");
    } catch (const xmate::TcpException& e) {
      QVERIFY2(QString(e.what()).contains("closed the connection without answering"), e.what());
      QVERIFY2(!QString(e.what()).contains("check the IP"), e.what());
    }
    closer.join();
  }

  void closingTheSessionStopsStreamAndMotion() {
    auto server = startServer(lockStepConfig(500));
    {
      auto client = connectedClient(*server);
      startJointMotion(*client);
      client->answer(awaitWantedState(*client, *server));
    }
    QVERIFY(eventually([&] {
      const sim::ServerStatus st = server->status();
      return !st.session && !st.streaming && !st.sim.motion_active;
    }));
  }

  void sceneCallsReachTheController() {
    auto server = startServer();
    auto client = connectedClient(*server);
    const std::array<double, 6> wrench{1, -2, 3, 0.1, -0.2, 0.3};
    server->setExternalWrench(wrench);
    QCOMPARE(server->status().sim.external_wrench, wrench);
    server->setEmergencyStop(true);
    QCOMPARE(server->status().sim.safety_stop, 2);
    QCOMPARE(int(wireSafetyStop(*client)), 1);  // wire: 0 none, 1 ESTOP, 2 GSTOP
    server->setEmergencyStop(false);
    server->setGuardStop(true);
    QCOMPARE(int(wireSafetyStop(*client)), 2);
    server->setGuardStop(false);
    QCOMPARE(int(wireSafetyStop(*client)), 0);
    server->setDigitalInput(4, true);
    QVERIFY(client->digitalInput(4));
    QVERIFY(!client->digitalInput(3));
    server->setDoToDiLoopback(true);
    QCOMPARE(int(client->requestByte(protocol::SetDORequest{2, true})), 0);
    QVERIFY(client->digitalInput(2));
  }

  void refusalsAreReportedWithTheControllersReason() {
    auto server = startServer();
    auto client = connectedClient(*server);
    QCOMPARE(QString::fromStdString(server->status().last_refusal), QString());
    using Req = RCI::robot::StartMoveRequest;
    const uint8_t status = client->requestByte(protocol::StartMoveRequestMsg{
        uint8_t(Req::ControllerMode::kJointPosition), uint8_t(Req::MotionGeneratorMode::kJointPosition)});
    QCOMPARE(int(status), int(protocol::StartMoveStatus::kNotPossible));  // the motors are off
    const QString reason = QString::fromStdString(server->status().last_refusal);
    QVERIFY2(reason.startsWith("startMove") && reason.contains("motors"), qPrintable(reason));
  }

  void badArgumentsAreRefused() {
    auto server = startServer();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, server->setDigitalInput(6, true));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, server->dropStates(0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, server->delayCommands(1, -5));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, server->setExternalWrench({0, 0, std::nan(""), 0, 0, 0}));
  }

  void rebootClosesTheSessionAndRestoresDefaults() {
    sim::ServerConfig config;
    config.reboot_pause_ms = 200;
    auto server = startServer(config);
    auto client = connectedClient(*server);
    QCOMPARE(int(client->requestByte(protocol::SetMotorPowerRequest{1})), 0);
    QCOMPARE(int(client->requestByte(Command::kGetMotorState)), 1);
    server->setEmergencyStop(true);  // the world: survives the reboot
    server->setEmergencyStop(false);
    server->setDigitalInput(1, true);
    QCOMPARE(int(client->requestByte(Command::kRebootRobot)), 0);

    uint8_t byte = 0;
    QCOMPARE(client->tcp().readExact(&byte, 1, 10000), net::IoResult::kClosed);
    client->drain();
    QVERIFY(!client->receive(300));  // the old session's stream is over

    std::unique_ptr<RawClient> again;
    QVERIFY(eventually([&] {
      try {
        again = connectedClient(*server);
        return true;
      } catch (const std::exception&) {
        return false;
      }
    }));
    QCOMPARE(int(again->requestByte(Command::kGetMotorState)), 0);  // fresh controller: motors off
    QVERIFY(again->digitalInput(1));                                  // the scene is kept
    const sim::ServerStatus st = server->status();
    QCOMPARE(st.counters.reboots, uint64_t(1));
    QCOMPARE(st.counters.sessions, uint64_t(2));
    QVERIFY(!st.rebooting);
  }

  void killStopsEverythingUntilRestarted() {
    auto server = startServer();
    auto client = connectedClient(*server);
    const uint16_t port = server->port();
    server->kill();
    uint8_t byte = 0;
    QCOMPARE(client->tcp().readExact(&byte, 1, 10000), net::IoResult::kClosed);
    client->drain();
    QVERIFY(!client->receive(300));
    QVERIFY_THROWS_EXCEPTION(std::runtime_error,
                             net::TcpConnection::connect(net::makeEndpoint("127.0.0.1", port), 2000));
    const sim::ServerStatus st = server->status();
    QVERIFY(st.killed);
    QVERIFY(!st.streaming);
    QVERIFY(!st.session);

    server->stop();
    server->start();
    QCOMPARE(server->port(), port);
    auto fresh = connectedClient(*server);
    QCOMPARE(int(fresh->requestByte(Command::kGetMotorState)), 0);
    QVERIFY(!server->status().killed);
  }

  void bindFailureSaysWhatToDo() {
    auto first = startServer();
    sim::ServerConfig config;
    config.port = first->port();
    sim::Server second(config);
    try {
      second.start();
      QFAIL("a second server on the same port must not start");
    } catch (const std::runtime_error& e) {
      const QString message = e.what();
      QVERIFY2(message.contains(QString::number(first->port())), e.what());
      QVERIFY2(message.contains("in use"), e.what());
      QVERIFY2(message.contains("choose another port"), e.what());
    }
    QVERIFY(!second.running());
  }

  // The in-process simulator of the GUI and rci-cli: loopback, a free port, started, and a start
  // failure wrapped in a message that names the built-in simulator.
  void embeddedSimulatorStartsOnLoopback() {
    auto config = sim::embeddedConfig(xmate::XMATE3_PRO, sim::ClockMode::kLockStep);
    QCOMPARE(config.bind_ip, std::string("127.0.0.1"));
    auto server = sim::startEmbedded(config);
    QVERIFY(server->running());
    QVERIFY(server->port() != 0);
    QCOMPARE(server->status().clock, sim::ClockMode::kLockStep);
    config.port = server->port();
    try {
      (void)sim::startEmbedded(config);
      QFAIL("a second simulator on the same port must not start");
    } catch (const std::runtime_error& e) {
      QVERIFY2(QString(e.what()).startsWith("The built-in simulator could not start:"), e.what());
      QVERIFY2(QString(e.what()).contains("in use"), e.what());
    }
  }
};

QTEST_APPLESS_MAIN(TestSimServer)
#include "test_sim_server.moc"
