// SPDX-License-Identifier: Apache-2.0
// Checks of what a control callback returned, run by the real-time thread before the command is
// sent: every value finite, Cartesian poses homogeneous. Allocation-free; the message for the
// exception is written afterwards on the caller's thread (describeCommandFault).
#pragma once

#include <string>

#include <xmate/rci_types.h>

namespace xmate::client {

enum class ControlKind { kJoint, kCartesian, kTorque };
const char* toString(ControlKind kind);  // "JointControl", ...

struct CommandFault {
  enum Kind { kNone, kNotFinite, kNotHomogeneous } kind = kNone;
  int index = -1;     // the offending element (q[i], tau[i], pose element i, 16 for psi_c)
  double value = 0;   // its value, or the orthonormality error for kNotHomogeneous
};

CommandFault checkCommand(const JointPositions& command, int dof);
CommandFault checkCommand(const CartesianPose& command);
CommandFault checkCommand(const Torques& command, int dof);

// "Control(JointControl): the callback returned q[3] = nan at message_id 1234"
std::string describeCommandFault(ControlKind kind, const CommandFault& fault, uint64_t message_id);

}  // namespace xmate::client
