// SPDX-License-Identifier: Apache-2.0
// Why the controller refused a motion, hand guiding or power request with "not possible in the
// robot's current state", told from what the client can see -- the newest state (robot mode, error
// bits, whether the arm moves), and asked when needed, the safety-stop and motor state -- so that a
// refusal names the cause that holds and what to do, never a list of causes that may not apply.
#pragma once

#include <string>

namespace xmate::client {

class Connection;

// What the caller meant to do, for the one cause that depends on it (a motion already running).
enum class Request { kMotion, kHandGuiding, kMotorPower, kSetting };

// "; hand guiding is on: call stopDrag() first" -- the first cause that holds, in the order error
// bits, emergency stop, guard stop, motors off (motions and hand guiding), hand guiding, a motion
// running, the arm still stopping (motions and hand guiding); else "; the controller gave no reason
// the client can see (robot mode kIdle, ...)".
// The caller's thread (it may send getSafetyStopState / getMotorState); never throws.
std::string refusalCause(Connection& connection, Request request);

}  // namespace xmate::client
