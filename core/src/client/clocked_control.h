// SPDX-License-Identifier: Apache-2.0
// Robot::Control() for the library's own motion generators (MOVEJ/MOVEL/MOVEC, the teach executor),
// which keep time by the controller's message_id and bridge gaps themselves (stall_bridge.h): the
// callback sees each gap instead of being called again for the states it missed.
#pragma once

#include <xmate/robot.h>

namespace xmate::client {

// As Robot::Control, with MissedStates::kSkip (connection.h). The caller's thread, blocking; the
// callback runs on the real-time thread and must be real-time safe.
void controlByMessageId(Robot& robot, const JointControl& callback);
void controlByMessageId(Robot& robot, const CartesianControl& callback);

}  // namespace xmate::client
