// SPDX-License-Identifier: Apache-2.0
// The simulator's TCP thread: accepts one client session at a time, reads framed requests, has
// the cycle thread execute them between two cycles, and writes the responses. A connection without
// Connect in time is closed; a client arriving while the session is held gets a "busy" Connect
// answer naming the holder (or takes over a silent session). It also closes the listener during a
// reboot pause and after kill(), so connection attempts are refused then. docs/simulator.md, "Sessions".
#include <arpa/inet.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <optional>

#include "net/clock.h"
#include "net/realtime.h"
#include "protocol/tcp_codec.h"
#include "sim/server_impl.h"

namespace xmate::sim {
namespace {

constexpr int kPollMs = 50;            // how often an idle session looks at stop/kill/reboot and waiting clients
constexpr int kRestOfFrameMs = 2000;   // a frame that started must be complete within this
constexpr int kWriteTimeoutMs = 2000;
// Clients that connect while the session is held wait here for their Connect to be answered.
constexpr size_t kMaxWaitingClients = 4;
constexpr int kWaitingRestMs = 200;    // a waiting client's frame must be complete this soon after it starts

using protocol::Command;

bool leaving(const Server::Impl& s) { return s.stopping || s.killed; }

// ---- Requests ---------------------------------------------------------------------------------------

bool connectSucceeded(const protocol::Frame& response) {
  if (response.size() < protocol::kFrameHeaderSize) return false;
  protocol::ByteResponse r;
  return protocol::decodePayload(response.data() + protocol::kFrameHeaderSize,
                                 response.size() - protocol::kFrameHeaderSize, r) == protocol::DecodeStatus::kOk &&
         r.command == Command::kConnect && r.value == uint8_t(protocol::ConnectStatus::kSuccess);
}

// Cycle thread: a Connect was accepted; states go to the peer's IP at the requested UDP port.
void startStreaming(Server::Impl& s, const net::Endpoint& peer, uint16_t udp_port) {
  if (udp_port == 0) {
    s.log("Connect asked for UDP port 0: no state stream (the client must name its UDP port)");
    return;
  }
  s.stream_to = peer;
  s.stream_to.addr.sin_port = htons(udp_port);
  s.streaming = true;
  s.state_faults.holding = false;
  s.command_faults.delayed.clear();
  ++s.counters.sessions;
  const std::string text = s.stream_to.toString();
  {
    std::lock_guard lock(s.snapshot_mutex);
    s.client_text = text;
  }
  s.log("streaming states to " + text);
}

// Cycle thread, after a request: publishes (and logs) the controller's reason if it is new.
void noteRefusal(Server::Impl& s) {
  const std::string& reason = s.controller->lastRefusal();
  {
    std::lock_guard lock(s.snapshot_mutex);
    if (reason == s.last_refusal) return;
    s.last_refusal = reason;
  }
  if (!reason.empty()) s.log("refused: " + reason);
}

// Has the cycle thread run one request; returns the whole response frame (empty if the controller
// is rebooting and cannot answer).
protocol::Frame executeRequest(Server::Impl& s, const net::Endpoint& peer, uint32_t sequence,
                               const uint8_t* payload, size_t size) {
  std::optional<uint16_t> udp_port;
  if (protocol::peekCommand(payload, size) == Command::kConnect) {
    protocol::ConnectRequest request;
    if (protocol::decodePayload(payload, size, request) == protocol::DecodeStatus::kOk) udp_port = request.udp_port;
  }
  protocol::Frame response;
  runOnCycleThread(s, [&] {
    if (!s.controller || s.killed) return;
    response = s.controller->handleRequest(sequence, payload, size);
    noteRefusal(s);
    if (udp_port && connectSucceeded(response)) startStreaming(s, peer, *udp_port);
    if (s.controller->rebootRequested()) beginReboot(s);
  });
  return response;
}

// Encodes a request without fields and hands its payload to the controller (session clean-up).
void sendInternalRequest(Server::Impl& s, Command command) {
  const protocol::Frame frame = protocol::encodeFrame(0, protocol::EmptyRequest{command});
  s.controller->handleRequest(0, frame.data() + protocol::kFrameHeaderSize,
                              frame.size() - protocol::kFrameHeaderSize);
}

// ---- Reading frames --------------------------------------------------------------------------------

struct Request {
  protocol::FrameHeader header;
  std::array<uint8_t, protocol::kMaxPayloadSize> payload{};
};

enum class ReadOutcome {
  kFrame,  // a whole request is in Request (possibly with an empty payload)
  kIdle,   // nothing arrived within the wait for the first byte
  kEnd,    // the client closed, the connection broke, or the frame was impossible
};

// Waits up to first_byte_ms for the first byte of a frame, then reads the rest within rest_ms.
ReadOutcome readRequest(Server::Impl& s, net::TcpConnection& conn, Request& request, int first_byte_ms,
                        int rest_ms) {
  uint8_t header[protocol::kFrameHeaderSize];
  net::IoResult r = conn.readExact(header, 1, first_byte_ms);
  if (r == net::IoResult::kTimeout) return ReadOutcome::kIdle;
  if (r == net::IoResult::kOk) r = conn.readExact(header + 1, sizeof header - 1, rest_ms);
  if (r != net::IoResult::kOk) {
    if (r != net::IoResult::kClosed) s.log(std::string("session: reading a request failed: ") + net::toString(r));
    return ReadOutcome::kEnd;
  }
  request.header = protocol::decodeFrameHeader(header);
  if (request.header.length > protocol::kMaxPayloadSize) {
    s.log("session: a frame announced " + std::to_string(request.header.length) + " payload bytes (at most " +
          std::to_string(protocol::kMaxPayloadSize) + " exist); closing the connection");
    return ReadOutcome::kEnd;
  }
  r = conn.readExact(request.payload.data(), request.header.length, rest_ms);
  if (r != net::IoResult::kOk) {
    s.log(std::string("session: a request's payload did not arrive: ") + net::toString(r));
    return ReadOutcome::kEnd;
  }
  return ReadOutcome::kFrame;
}

bool isConnect(const Request& r) { return protocol::peekCommand(r.payload.data(), r.header.length) == Command::kConnect; }

std::string seconds(int64_t ns) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f s", double(ns) * 1e-9);
  return text;
}

// ---- The session and the clients waiting for it ----------------------------------------------------

// The client that holds the controller.
struct Session {
  net::Endpoint peer;
  bool connected = false;    // its Connect was answered with success
  int64_t opened_ns = 0;     // accepted
  int64_t last_request_ns = 0;
};

// A client that connected while the session was held: its Connect request is awaited (until
// deadline_ns), then answered "busy" -- unless the holder gives way.
struct WaitingClient {
  net::TcpConnection conn;
  int64_t accepted_ns = 0;
  int64_t deadline_ns = 0;
};
using WaitingClients = std::array<std::optional<WaitingClient>, kMaxWaitingClients>;

int64_t connectDeadline(const Server::Impl& s, int64_t accepted_ns) {
  return s.config.connect_timeout_ms > 0 ? accepted_ns + int64_t(s.config.connect_timeout_ms) * 1'000'000 : INT64_MAX;
}

// A connection that has not completed Connect in time is closed: it would hold the only session.
bool handshakeOverdue(const Server::Impl& s, const Session& session, int64_t now) {
  return !session.connected && now > connectDeadline(s, session.opened_ns);
}

// How long the session's client has not been heard from (no TCP request, no UDP datagram).
int64_t silence(const Server::Impl& s, const Session& session, int64_t now) {
  return now - std::max(session.last_request_ns, s.last_client_datagram_ns.load(std::memory_order_relaxed));
}

// Why the holder gives way to a newcomer's Connect ("" if it keeps the controller).
std::string givesWayBecause(Server::Impl& s, const Session& session, int64_t now) {
  if (!session.connected) return "it has not completed Connect after " + seconds(now - session.opened_ns);
  if (s.config.idle_timeout_ms <= 0) return "";
  const int64_t quiet = silence(s, session, now);
  if (quiet < int64_t(s.config.idle_timeout_ms) * 1'000'000) return "";
  {
    std::lock_guard lock(s.snapshot_mutex);
    if (s.snapshot.sim.motion_active || s.snapshot.sim.dragging) return "";
  }
  return "it has been silent for " + seconds(quiet) + " (no request, no UDP datagram, no motion or hand guiding)";
}

// Answers a refused client's Connect: busy, held by the session's peer (a simulator extension).
void answerBusy(Server::Impl& s, WaitingClient& client, uint32_t sequence, const Session& session) {
  protocol::ConnectResponse busy;
  busy.status = uint8_t(protocol::ConnectStatus::kBusy);
  busy.has_holder = true;
  std::memcpy(busy.holder_ip.data(), &session.peer.addr.sin_addr.s_addr, 4);  // network byte order
  busy.holder_port = ntohs(session.peer.addr.sin_port);
  const protocol::Frame frame = protocol::encodeFrame(sequence, busy);
  (void)client.conn.sendAll(frame.data(), frame.size(), kWaitingRestMs);
  ++s.clients_refused;
  s.log("refused " + client.conn.peer().toString() + ": the session is held by " + session.peer.toString());
}

// Takes new connections into free places in the queue; a full queue closes the newcomer at once.
void acceptWaitingClients(Server::Impl& s, WaitingClients& waiting, int64_t now) {
  while (auto extra = s.listener.accept(0)) {
    auto slot = std::find_if(waiting.begin(), waiting.end(), [](const auto& w) { return !w.has_value(); });
    if (slot == waiting.end()) {
      ++s.clients_refused;
      s.log("refused " + extra->peer().toString() + ": " + std::to_string(kMaxWaitingClients) +
            " clients already wait while the session is held");
      continue;  // closed when `extra` goes
    }
    *slot = WaitingClient{std::move(*extra), now, connectDeadline(s, now)};
  }
}

// A client that takes over the controller, with the request it already sent (if any).
struct Handover {
  net::TcpConnection conn;
  int64_t accepted_ns = 0;
  std::optional<Request> first;
};

// One waiting client: drops it when it leaves, stalls or sends something else than Connect; its
// Connect gets "busy" or, when the holder gives way, the client takes over (returned).
std::optional<Handover> serveWaitingClient(Server::Impl& s, const Session& session,
                                           std::optional<WaitingClient>& client, int64_t now) {
  Request request;
  const ReadOutcome outcome = readRequest(s, client->conn, request, 0, kWaitingRestMs);
  const std::string who = client->conn.peer().toString();
  if (outcome == ReadOutcome::kIdle) {
    if (now > client->deadline_ns) {
      ++s.sessions_dropped;
      s.log("closed " + who + ": no Connect request within " + std::to_string(s.config.connect_timeout_ms) + " ms");
      client.reset();
    }
    return std::nullopt;
  }
  if (outcome == ReadOutcome::kEnd) {
    client.reset();
    return std::nullopt;
  }
  if (!isConnect(request)) {
    ++s.clients_refused;
    s.log("refused " + who + ": it sent " + protocol::commandName(protocol::peekCommand(request.payload.data(),
                                                                                       request.header.length)) +
          " before Connect while the session is held by " + session.peer.toString());
    client.reset();
    return std::nullopt;
  }
  if (const std::string why = givesWayBecause(s, session, now); !why.empty()) {
    ++s.sessions_dropped;
    s.log("dropped the session of " + session.peer.toString() + ": " + why + "; " + who + " takes over");
    Handover next{std::move(client->conn), client->accepted_ns, request};
    client.reset();
    return next;
  }
  answerBusy(s, *client, request.header.sequence, session);
  client.reset();
  return std::nullopt;
}

std::optional<Handover> serveWaitingClients(Server::Impl& s, const Session& session, WaitingClients& waiting) {
  const int64_t now = net::monotonicNs();
  acceptWaitingClients(s, waiting, now);
  for (auto& client : waiting)
    if (client)
      if (auto next = serveWaitingClient(s, session, client, now)) return next;
  return std::nullopt;
}

// When the session ends by itself, the longest-waiting client is served next.
std::optional<Handover> nextInLine(WaitingClients& waiting) {
  auto oldest = waiting.end();
  for (auto it = waiting.begin(); it != waiting.end(); ++it)
    if (*it && (oldest == waiting.end() || (*it)->accepted_ns < (*oldest)->accepted_ns)) oldest = it;
  if (oldest == waiting.end()) return std::nullopt;
  Handover next{std::move((*oldest)->conn), (*oldest)->accepted_ns, std::nullopt};
  oldest->reset();
  return next;
}

// Runs one request of the session and sends its response; false when the session must end.
bool serveRequest(Server::Impl& s, net::TcpConnection& conn, Session& session, const Request& request) {
  session.last_request_ns = net::monotonicNs();
  protocol::Frame response;
  try {
    response = executeRequest(s, session.peer, request.header.sequence, request.payload.data(), request.header.length);
  } catch (const std::exception& e) {
    s.log(std::string("session: the controller failed on a request, closing the session: ") + e.what());
    return false;
  }
  if (response.empty()) return false;
  if (isConnect(request) && connectSucceeded(response)) session.connected = true;
  return conn.sendAll(response.data(), response.size(), kWriteTimeoutMs) == net::IoResult::kOk;
}

// Serves one client until it leaves, breaks the rules, gives way to another, or the controller
// reboots or stops. Returns the client to serve next, if one is already waiting.
std::optional<Handover> serveSession(Server::Impl& s, Handover client) {
  const uint64_t boot = s.reboots_begun;
  net::TcpConnection& conn = client.conn;
  Session session;
  session.peer = conn.peer();
  session.opened_ns = session.last_request_ns = client.accepted_ns;
  s.session_open = true;
  s.log("session opened by " + session.peer.toString());
  WaitingClients waiting;
  std::optional<Handover> next;
  Request request;
  bool have_request = client.first.has_value();
  if (have_request) request = *client.first;
  while (!leaving(s) && s.reboots_begun == boot) {
    if (!have_request) {
      if ((next = serveWaitingClients(s, session, waiting))) break;
      if (handshakeOverdue(s, session, net::monotonicNs())) {
        ++s.sessions_dropped;
        s.log("closed " + session.peer.toString() + ": no Connect request within " +
              std::to_string(s.config.connect_timeout_ms) + " ms (it would hold the only session)");
        break;
      }
      const ReadOutcome outcome = readRequest(s, conn, request, kPollMs, kRestOfFrameMs);
      if (outcome == ReadOutcome::kIdle) continue;
      if (outcome == ReadOutcome::kEnd) break;
    }
    have_request = false;
    if (!serveRequest(s, conn, session, request)) break;
  }
  conn.close();
  if (!s.killed) runOnCycleThread(s, [&] { endSessionOnController(s); });
  s.session_open = false;
  s.log(s.killed ? "session cut (controller killed)" : "session closed");
  if (leaving(s) || s.reboots_begun != boot) return std::nullopt;  // waiting clients are closed
  return next ? std::move(next) : nextInLine(waiting);
}

// ---- Listener ---------------------------------------------------------------------------------------

// During the reboot pause nobody may connect: close the listener, wait, listen again.
void sitOutReboot(Server::Impl& s) {
  s.listener.close();
  while (s.rebooting && !leaving(s)) net::sleepUntilNs(net::monotonicNs() + kPollMs * 1'000'000LL);
}

bool listenAgain(Server::Impl& s) {
  try {
    s.listener.listen(s.config.bind_ip, s.bound_port);
    return true;
  } catch (const std::exception& e) {
    s.log(std::string("cannot listen again after the reboot, retrying: ") + e.what());
    net::sleepUntilNs(net::monotonicNs() + 500'000'000LL);
    return false;
  }
}

}  // namespace

void endSessionOnController(Server::Impl& s) {
  s.streaming = false;
  s.state_faults.holding = false;
  s.command_faults.delayed.clear();
  {
    std::lock_guard lock(s.snapshot_mutex);
    s.client_text.clear();
  }
  if (!s.controller) return;
  const SimStatus status = s.controller->status();
  if (status.motion_active) sendInternalRequest(s, Command::kStopMove);
  if (status.dragging) sendInternalRequest(s, Command::kStopDrag);
}

void runTcpThread(Server::Impl& s) {
  net::nameThisThread("rci-sim-tcp");
  std::optional<Handover> next;  // a client that already waits for the controller
  while (!leaving(s)) {
    if (s.rebooting) {
      next.reset();
      sitOutReboot(s);
      continue;
    }
    if (!s.listener.isOpen() && !listenAgain(s)) continue;
    if (!next) {
      std::optional<net::TcpConnection> conn = s.listener.accept(kPollMs);
      if (!conn) continue;
      if (s.rebooting || leaving(s)) continue;  // refused: the connection closes here
      next = Handover{std::move(*conn), net::monotonicNs(), std::nullopt};
    }
    Handover client = std::move(*next);
    next = serveSession(s, std::move(client));
  }
  s.listener.close();
}

}  // namespace xmate::sim
