// SPDX-License-Identifier: Apache-2.0
// Operator text: the one place where the window turns error bits, robot modes, safety stops, joints
// beyond their limits, the TCP outside the safety box and failed or refused commands into words for
// the person at the robot -- what happened and what to press in this window. The programmer's words
// (enum names, library messages) travel along only as a detail for tooltips or parentheses.
#pragma once

#include <QString>

#include <array>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include <xmate/rci_types.h>

namespace xmate::model {
struct RobotSpec;
}

namespace rci::ui {

class Session;
struct LiveState;
struct OperatorSettings;
struct SafetyBox;

namespace text {

inline constexpr int kErrorBitCount = 20;

// One thing to tell the operator. title, what and todo never name an API call, a C++ enum or a
// document; detail carries the programmer's words for a tooltip.
struct OperatorMessage {
  QString title;   // "Collision detected"
  QString what;    // what happened, in plain words, with the specifics (joint, value, limit)
  QString todo;    // what to press in this window
  QString detail;  // enum name or library message (tooltip only)
  bool detail_inline = false;  // a fallback: line() ends with the detail in parentheses

  // "Title. What. Todo." as one line (the detail in parentheses when detail_inline).
  QString line() const;
  // The same for a rich-text label: bold title, then what and todo on their own lines.
  QString html() const;
  bool empty() const { return title.isEmpty(); }
};

// ---- Error bits, robot modes, safety stops --------------------------------------------------

// "Collision detected", "Joint position limit reached", ... for bit 0..19.
QString errorBitTitle(int bit);
// Title, what happened and what to do for a bit, without live specifics; detail = enum name.
OperatorMessage errorBit(int bit);
// The bits' enum name ("kCollision"), for tooltips and details only.
QString errorBitName(int bit);
// "Idle", "Moving", "Hand guiding", "Stopped by an error", ...
QString robotMode(RCI::robot::RobotMode mode);
// safety stop state as polled: 1 none, 2 emergency stop, 3 guard stop.
QString safetyStop(int safety_stop);

// ---- Limits and the safety box, from the live state ---------------------------------------

// What the window knows about the robot; any pointer may be null (then nothing specific is said).
struct RobotView {
  const LiveState* live = nullptr;            // only when a state arrived
  const OperatorSettings* settings = nullptr;
  const xmate::model::RobotSpec* spec = nullptr;
};
// The view of an open session (live only once a state arrived).
RobotView viewOf(Session& session);

// A joint beyond its limit: the soft limit when the window enabled soft limits, else the model's.
struct JointExcursion {
  int joint = 0;  // 0-based
  bool upper = true;
  double value_deg = 0;
  double limit_deg = 0;
  bool soft = false;
  double beyondDeg() const { return upper ? value_deg - limit_deg : limit_deg - value_deg; }
};
std::vector<JointExcursion> jointsBeyondLimits(const std::array<double, 7>& q, int dof, const OperatorSettings* settings,
                                               const xmate::model::RobotSpec& spec);
// "J6 reached its upper limit (120.7° > 120.0°)"
QString describe(const JointExcursion& e);
// "J6 is 0.7° beyond its upper limit: Jog J6 − or guide it back towards the range, then press
// Recover in the Safety panel"
QString remedy(const JointExcursion& e);

// The TCP outside the enabled safety box: how far and along which box sides.
struct BoxExcursion {
  double distance_m = 0;                 // from the box
  std::array<double, 3> excess_m{};      // per box axis, beyond the side (0 if within)
  std::array<int, 3> side{};             // +1 beyond the + side, -1 beyond the - side, 0 within
  std::array<QString, 3> back;           // per axis: "x −" (the jog button that moves back), or ""
};
std::optional<BoxExcursion> tcpOutsideBox(const std::array<double, 16>& tcp_pose, const SafetyBox& box);
// "The TCP is 23 mm outside the safety box (beyond its +x side)"
QString describe(const BoxExcursion& e);
// "Move the TCP back into the box: jog TCP x − (Jog panel) or guide it"
QString remedy(const BoxExcursion& e);

// Everything wrong right now, most urgent first: safety stops, active error bits (with the joints
// and box specifics), and joints or the TCP beyond their limits without an error bit.
std::vector<OperatorMessage> activeProblems(const RobotView& view);
// The same message for one bit as activeProblems() gives it (with specifics when view has them).
OperatorMessage errorBit(int bit, const RobotView& view);

// ---- Failed and refused commands ------------------------------------------------------------

// A command's failure (the exception's what(), as Session reports it) in plain words and what to
// press; the raw message is the detail. view refines refusals the robot gives no reason for.
OperatorMessage failure(const QString& raw, const RobotView& view = {});
// The same, using the exception's type too.
OperatorMessage failure(const std::exception& error, const RobotView& view = {});

// "Could not connect to Robot 10.0.0.2:1337 (xMate7 Pro): Cannot reach the robot. Check ..." for
// a failed open (the reason itself when it is not recognised).
QString connectFailure(const QString& target, const QString& reason);

// A value an editor refuses before sending (core/src/model/parameter_checks.h), with the fields'
// names instead of the parameters': "J3 threshold = 90 is outside (0, 60] Nm".
QString valueRefusal(const std::string& raw);

// A pre-flight problem of a program ("instruction 2 (MOVEL): the path cannot be followed ..."),
// without the solver's codes and with the button that re-teaches.
QString programProblem(const std::string& raw);

}  // namespace text
}  // namespace rci::ui
