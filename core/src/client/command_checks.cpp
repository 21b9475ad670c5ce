// SPDX-License-Identifier: Apache-2.0
// The per-cycle validity checks of callback commands and their messages.
#include "client/command_checks.h"

#include <cmath>
#include <cstdio>

#include "model/parameter_checks.h"  // kHomogeneousTolerance

namespace xmate::client {
namespace {

template <size_t N>
CommandFault firstNonFinite(const std::array<double, N>& values, int count) {
  for (int i = 0; i < count; ++i)
    if (!std::isfinite(values[i])) return {CommandFault::kNotFinite, i, values[i]};
  return {};
}

// Largest deviation of R^T R from the identity, and of the last row from 0 0 0 1.
double homogeneityError(const std::array<double, 16>& m) {
  double worst = std::abs(m[12]) + std::abs(m[13]) + std::abs(m[14]) + std::abs(m[15] - 1.0);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      double dot = 0;
      for (int r = 0; r < 3; ++r) dot += m[4 * r + a] * m[4 * r + b];
      worst = std::fmax(worst, std::abs(dot - (a == b ? 1.0 : 0.0)));
    }
  return worst;
}

}  // namespace

const char* toString(ControlKind kind) {
  switch (kind) {
    case ControlKind::kJoint: return "JointControl";
    case ControlKind::kCartesian: return "CartesianControl";
    case ControlKind::kTorque: return "TorqueControl";
  }
  return "?";
}

CommandFault checkCommand(const JointPositions& command, int dof) { return firstNonFinite(command.q, dof); }

CommandFault checkCommand(const Torques& command, int dof) { return firstNonFinite(command.tau, dof); }

CommandFault checkCommand(const CartesianPose& command) {
  if (CommandFault f = firstNonFinite(command.toolTobase_pos_c, 16); f.kind != CommandFault::kNone) return f;
  if (command.psi_valid && !std::isfinite(command.psi_c)) return {CommandFault::kNotFinite, 16, command.psi_c};
  const double error = homogeneityError(command.toolTobase_pos_c);
  // The rotation may carry the rounding of a few matrix products; the tolerance is the one the
  // settings use (model::kHomogeneousTolerance).
  if (error > model::kHomogeneousTolerance) return {CommandFault::kNotHomogeneous, -1, error};
  return {};
}

std::string describeCommandFault(ControlKind kind, const CommandFault& fault, uint64_t message_id) {
  char buf[320];
  const char* field = kind == ControlKind::kJoint ? "q" : kind == ControlKind::kTorque ? "tau" : "toolTobase_pos_c";
  if (fault.kind == CommandFault::kNotFinite) {
    if (kind == ControlKind::kCartesian && fault.index == 16)
      std::snprintf(buf, sizeof buf, "Control(%s): the callback returned psi_c = %g (psi_valid is true) at message_id %llu",
                    toString(kind), fault.value, static_cast<unsigned long long>(message_id));
    else
      std::snprintf(buf, sizeof buf, "Control(%s): the callback returned %s[%d] = %g at message_id %llu",
                    toString(kind), field, fault.index, fault.value, static_cast<unsigned long long>(message_id));
  } else {
    std::snprintf(buf, sizeof buf,
                  "Control(%s): the callback returned a toolTobase_pos_c that is not a homogeneous transform "
                  "(rotation not orthonormal or last row not 0 0 0 1; error %g, allowed %g) at message_id %llu",
                  toString(kind), fault.value, model::kHomogeneousTolerance, static_cast<unsigned long long>(message_id));
  }
  return std::string(buf) + "; the motion was stopped. Return finite values and row-major homogeneous poses.";
}

}  // namespace xmate::client
