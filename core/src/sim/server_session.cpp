// The simulator's TCP thread: accepts one client session at a time, reads framed requests, has
// the cycle thread execute them between two cycles, and writes the responses. It also closes the
// listener during a reboot pause and after kill(), so connection attempts are refused then.
#include <arpa/inet.h>

#include <array>
#include <optional>

#include "net/clock.h"
#include "net/realtime.h"
#include "protocol/tcp_codec.h"
#include "sim/server_impl.h"

namespace xmate::sim {
namespace {

constexpr int kPollMs = 50;            // how often an idle session looks at stop/kill/reboot
constexpr int kRestOfFrameMs = 2000;   // a frame that started must be complete within this
constexpr int kWriteTimeoutMs = 2000;

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

// ---- One session ------------------------------------------------------------------------------------

struct Request {
  protocol::FrameHeader header;
  std::array<uint8_t, protocol::kMaxPayloadSize> payload{};
};

enum class ReadOutcome {
  kFrame,  // a whole request is in Request (possibly with an empty payload)
  kIdle,   // nothing arrived within kPollMs
  kEnd,    // the client closed, the connection broke, or the frame was impossible
};

// Waits briefly for the first byte of a frame, then reads the rest with a longer timeout.
ReadOutcome readRequest(Server::Impl& s, net::TcpConnection& conn, Request& request) {
  uint8_t header[protocol::kFrameHeaderSize];
  net::IoResult r = conn.readExact(header, 1, kPollMs);
  if (r == net::IoResult::kTimeout) return ReadOutcome::kIdle;
  if (r == net::IoResult::kOk) r = conn.readExact(header + 1, sizeof header - 1, kRestOfFrameMs);
  if (r != net::IoResult::kOk) {
    if (r != net::IoResult::kClosed) s.log(std::string("session: reading a request failed: ") + net::toString(r));
    return ReadOutcome::kEnd;
  }
  request.header = protocol::decodeFrameHeader(header);
  if (request.header.length > protocol::kMaxPayloadSize) {
    s.log("session: a frame announced " + std::to_string(request.header.length) + " payload bytes (at most " +
          std::to_string(protocol::kMaxPayloadSize) + " exist); closing the session");
    return ReadOutcome::kEnd;
  }
  r = conn.readExact(request.payload.data(), request.header.length, kRestOfFrameMs);
  if (r != net::IoResult::kOk) {
    s.log(std::string("session: a request's payload did not arrive: ") + net::toString(r));
    return ReadOutcome::kEnd;
  }
  return ReadOutcome::kFrame;
}

// One session at a time: a second client is disconnected at once.
void refuseExtraClients(Server::Impl& s) {
  if (auto extra = s.listener.accept(0)) {
    s.log("refused " + extra->peer().toString() + ": one session at a time");
    extra->close();
  }
}

void serveSession(Server::Impl& s, net::TcpConnection& conn) {
  const uint64_t boot = s.reboots_begun;
  const net::Endpoint peer = conn.peer();
  s.session_open = true;
  s.log("session opened by " + peer.toString());
  Request request;
  while (!leaving(s) && s.reboots_begun == boot) {
    refuseExtraClients(s);
    const ReadOutcome outcome = readRequest(s, conn, request);
    if (outcome == ReadOutcome::kIdle) continue;
    if (outcome == ReadOutcome::kEnd) break;
    protocol::Frame response;
    try {
      response = executeRequest(s, peer, request.header.sequence, request.payload.data(), request.header.length);
    } catch (const std::exception& e) {
      s.log(std::string("session: the controller failed on a request, closing the session: ") + e.what());
      break;
    }
    if (response.empty()) break;
    if (conn.sendAll(response.data(), response.size(), kWriteTimeoutMs) != net::IoResult::kOk) break;
  }
  conn.close();
  if (!s.killed) runOnCycleThread(s, [&] { endSessionOnController(s); });
  s.session_open = false;
  s.log(s.killed ? "session cut (controller killed)" : "session closed");
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
  while (!leaving(s)) {
    if (s.rebooting) {
      sitOutReboot(s);
      continue;
    }
    if (!s.listener.isOpen() && !listenAgain(s)) continue;
    std::optional<net::TcpConnection> conn = s.listener.accept(kPollMs);
    if (!conn) continue;
    if (s.rebooting || leaving(s)) continue;  // refused: the connection closes here
    serveSession(s, *conn);
  }
  s.listener.close();
}

}  // namespace xmate::sim
