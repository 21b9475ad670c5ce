// SPDX-License-Identifier: Apache-2.0
// Whether the arm stands still, read from the state stream. After a reflex, a stop, an error
// recovery or the end of hand guiding the arm keeps moving for a while (the controller's stop ramp),
// and the controller refuses new motions until it stands still: the client waits for standstill
// before it asks (Robot::startMove, startDrag) and names the moving joint when it cannot.
#pragma once

#include <cstdint>
#include <string>

#include <xmate/rci_types.h>

namespace xmate::client {

// Two levels, per joint, rad/s of the measured and the commanded speed (whichever is higher).
// Still: the "hold still" answers between StartMove and the motion follow the measured position and
// the controller checks their jerk, and a creep of v rad/s starting from rest reads as a jerk of
// v / (1 ms)^2 -- so a motion starts best once every joint is far below the 3.5e-3 rad/s that make
// 3500 rad/s^3 (the smallest rated jerk). At rest: slow enough that the arm is no longer stopping
// (a real arm's measured speed may never settle below the first level: its encoders are noisy).
inline constexpr double kStillSpeed = 1e-3;
inline constexpr double kRestSpeed = 0.01;
// A level counts once every joint was below it in this many states in a row (1 ms each).
inline constexpr uint32_t kStillStates = 10;
// How long a motion request waits for the arm to stand still; then it goes ahead if the arm is at
// rest, and is refused if it is still stopping.
inline constexpr int kStandstillWaitMs = 1000;

struct Standstill {
  bool known = false;         // a state has arrived
  bool still = false;         // every joint below kStillSpeed for kStillStates states in a row
  bool at_rest = false;       // every joint below kRestSpeed for kStillStates states in a row
  int fastest_joint = 0;      // 0-based: the fastest joint of the newest state ...
  double fastest_speed = 0;   // ... and its speed, rad/s (the larger of measured and commanded)
  uint64_t message_id = 0;    // the newest state's
  RCI::robot::RobotMode robot_mode = RCI::robot::RobotMode::kOther;
};

// Follows the state stream. The real-time thread's: update() is real-time safe.
class StandstillWatch {
 public:
  const Standstill& update(const RCI::robot::RobotState& s, int dof);

 private:
  Standstill now_;
  uint32_t still_states_ = 0, rest_states_ = 0;
};

// True when the arm is settling on its own: no motion and no hand guiding running, no error bits (a
// reflex must be recovered first), but not yet still. A motion request waits for it to end.
bool settling(const Standstill& s, const RCI::robot::RobotState& newest);
// True when it is still stopping: settling and not even at rest (what the window shows, and a
// refusal's cause).
bool stoppingOnItsOwn(const Standstill& s, const RCI::robot::RobotState& newest);

// How far the arm moved while a request waited for it to stand still (all 0 when it did not wait):
// a start the caller read just before may be off by that much.
struct StandstillWait {
  double joint_travel = 0;     // rad, the largest change of one joint
  double tcp_travel = 0;       // m
  double rotation_travel = 0;  // rad
};
StandstillWait travelBetween(const RCI::robot::RobotState& before, const RCI::robot::RobotState& after, int dof);

// "the arm is still stopping (joint 2 at 0.12 rad/s)" (joints numbered from 1).
std::string stillStoppingText(const Standstill& s);

}  // namespace xmate::client
