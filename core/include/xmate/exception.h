// SPDX-License-Identifier: Apache-2.0
// Exceptions thrown by the RCI client library (docs/api.md, "Exceptions").
// Every one is an xmate::XmateException, itself a std::runtime_error with a readable message.
#pragma once

#include <array>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <xmate/rci_types.h>

namespace xmate {

class XmateException : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// TCP/UDP thread creation failed or the connection broke.
class NetworkException : public XmateException { public: using XmateException::XmateException; };
// UDP receive timed out or a datagram had the wrong length (usually a version mismatch).
class UdpException : public XmateException { public: using XmateException::XmateException; };
// TCP connect/read/write failed: check the controller's IP address and port.
class TcpException : public XmateException { public: using XmateException::XmateException; };
// Registering or running the control callback failed.
class EventException : public XmateException { public: using XmateException::XmateException; };
// One cycle of the control loop as the client saw it.
struct ControlRecord {
  RCI::robot::RobotState state;
  RCI::robot::RobotCommand command;  // what the client answered (zero if it had not answered)
};

// The controller reported error bits (or the exchange became unstable) and ended Control().
// The message names the bits; log holds the last cycles before the error, oldest first.
class ControlException : public XmateException {
 public:
  ControlException(const std::string& what, std::array<bool, 20> errors, std::vector<ControlRecord> log)
      : XmateException(what), errors(errors), log(std::move(log)) {}
  std::array<bool, 20> errors;
  std::vector<ControlRecord> log;
};
// The controller answered a TCP request with something this library does not understand.
class ProtocolException : public XmateException { public: using XmateException::XmateException; };
// The controller refused a TCP command.
class CommandException : public XmateException { public: using XmateException::XmateException; };
// Real-time setup (scheduling, memory locking) failed where it was required.
class RealtimeException : public XmateException { public: using XmateException::XmateException; };
// A MOVEJ/MOVEL/MOVEC (or a planner) could not plan the motion: unreachable, degenerate, limits.
class MotionException : public XmateException { public: using XmateException::XmateException; };
// A call that is not allowed in the current state (for example motion while dragging).
class InvalidOperationException : public XmateException { public: using XmateException::XmateException; };

}  // namespace xmate
