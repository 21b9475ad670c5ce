// SPDX-License-Identifier: Apache-2.0
// Operator text for failed and refused commands (operator_text.h): the library's and the
// controller's messages are recognised by exception type and by their known phrases, refusals
// without a reason are explained from the live state, and the raw message stays as the detail.
#include <QCoreApplication>
#include <QRegularExpression>
#include <QStringList>

#include <optional>
#include <stdexcept>

#include <xmate/exception.h>

#include "client/error_bits.h"
#include "session/session.h"
#include "text/operator_text.h"

namespace rci::ui::text {
namespace {

QString tr(const char* text) { return QCoreApplication::translate("OperatorText", text); }

constexpr double kDegPerRad = 57.295779513082320876798;

using Found = std::optional<OperatorMessage>;

OperatorMessage says(const QString& title, const QString& what, const QString& todo) { return {title, what, todo, {}, false}; }

// The raw message taken apart: "instruction 3 (MOVEL "P3"): the controller aborted the motion:
// Control(kJointPosition): the controller stopped ..." -> context, call, body.
struct Parsed {
  QString context;  // "Instruction 3 (MOVEL "P3")" from a program run, or empty
  QString call;     // "startMove", "Control(kJointPosition)", "MOVEL", ... or empty
  QString body;     // the rest
  QString lower;    // the whole message in lower case, for phrase matching
};

Parsed parse(const QString& raw) {
  Parsed p;
  QString rest = raw.trimmed();
  static const QRegularExpression instruction(QStringLiteral(R"(^instruction (\d+)( \([^)]*\))?: )"));
  if (const auto m = instruction.match(rest); m.hasMatch()) {
    p.context = tr("Instruction %1").arg(m.captured(1)) + m.captured(2);
    rest = rest.mid(m.capturedLength());
  }
  static const QString aborted = QStringLiteral("the controller aborted the motion: ");
  if (rest.startsWith(aborted)) rest = rest.mid(aborted.size());
  static const QRegularExpression call(QStringLiteral(R"(^([A-Za-z_]+(\([A-Za-z_]*\))?): )"));
  if (const auto m = call.match(rest); m.hasMatch()) {
    p.call = m.captured(1);
    rest = rest.mid(m.capturedLength());
  }
  p.body = rest;
  p.lower = raw.toLower();
  return p;
}

bool has(const Parsed& p, const char* phrase) { return p.lower.contains(QLatin1String(phrase)); }
bool callIs(const Parsed& p, const char* name) { return p.call.startsWith(QLatin1String(name)); }

// ---- The robot's state made the command impossible ------------------------------------------

OperatorMessage notConnected() {
  return says(tr("Not connected"), {}, tr("Connect to the simulator or a robot with Connect in the toolbar."));
}
OperatorMessage emergencyStop() {
  return says(tr("The emergency stop is pressed"), {},
              tr("Release it, press Recover in the Safety panel, then Power on in the Power panel."));
}
OperatorMessage guardStop() {
  return says(tr("The guard stop is active"), tr("The guard (safety door) is open."), tr("Close it, then try again."));
}
OperatorMessage motorsOff() { return says(tr("The motors are off"), {}, tr("Press Power on in the Power panel.")); }
OperatorMessage guiding() { return says(tr("Hand guiding is on"), {}, tr("Press Stop guiding in the Drag panel first.")); }
OperatorMessage motionRunning() {
  return says(tr("Another motion is running"), {},
              tr("Wait until it ends (release the jog button, or press Stop in the Program panel), then try again."));
}
OperatorMessage stillStopping() {
  return says(tr("The arm is still coming to rest"), {},
              tr("Wait until the status bar no longer says \"stopping\", then try again."));
}
OperatorMessage rebooting() {
  return says(tr("The controller is restarting"), {}, tr("Wait until the window has reconnected, then try again."));
}

OperatorMessage errorsSet(const RobotView& view) {
  OperatorMessage m = says(tr("The robot reported an error"), {}, tr("See the Safety panel, then press Recover there."));
  if (!view.live) return m;
  QStringList titles;
  for (const OperatorMessage& problem : activeProblems(view)) titles << problem.title;
  if (!titles.isEmpty()) m.what = tr("Active: %1.").arg(titles.join(QStringLiteral("; ")));
  return m;
}

bool anyError(const LiveState& live) {
  for (bool bit : live.state.errors)
    if (bit) return true;
  return false;
}

// "Not possible in the robot's current state" carries no reason: the live state gives it.
Found refuseFromState(const Parsed& p, const RobotView& view) {
  if (!view.live) return std::nullopt;
  const LiveState& live = *view.live;
  using RCI::robot::RobotMode;
  if (live.safety_stop == 2) return emergencyStop();
  if (anyError(live) && !callIs(p, "automaticErrorRecovery")) return errorsSet(view);
  const bool motion_call = callIs(p, "startMove") || callIs(p, "startDrag") || callIs(p, "Control");
  if (motion_call && live.motor_state == 0) return motorsOff();
  if (motion_call && live.safety_stop == 3) return guardStop();
  const bool dragging = live.state.robot_mode == RobotMode::kGuiding || (live.simulated && live.sim.dragging);
  if (dragging && !callIs(p, "stopDrag") && !callIs(p, "setMotorPower")) return guiding();
  if (motion_call && (live.motion_running || live.state.robot_mode == RobotMode::kMove)) return motionRunning();
  return std::nullopt;
}

// Refusals whose reason depends on the command.
Found refuseByCommand(const Parsed& p) {
  if (callIs(p, "setCartesianLimit") && has(p, "outside the requested box"))
    return says(tr("The robot refused the safety box"), tr("The TCP is outside the new box."),
                tr("Move the TCP inside first or enlarge the box (Centre on TCP helps), then apply again."));
  if (callIs(p, "setJointLimit") || callIs(p, "setCartesianLimit"))
    return says(callIs(p, "setJointLimit") ? tr("The robot refused the soft limits") : tr("The robot refused the safety box"),
                {}, tr("Apply them again once the robot stands still."));
  if (callIs(p, "automaticErrorRecovery"))
    return says(tr("Recover was refused"), tr("The robot cannot recover in its current state."),
                tr("Release the emergency stop if it is pressed and close the guard, then press Recover again."));
  if (callIs(p, "setMotorPower"))
    return says(tr("The robot did not switch the motors on"), {},
                tr("Release the emergency stop if it is pressed and press Recover in the Safety panel if it shows "
                   "an error, then press Power on again."));
  if (has(p, "cannot change during a motion") || has(p, "not possible while a motion or hand guiding"))
    return says(tr("Settings cannot change while the robot moves or is hand guided"), {},
                tr("Wait for the motion to end or press Stop guiding in the Drag panel, then apply again."));
  return std::nullopt;
}

// The hints the library adds to a refusal, when the live state could not say more.
Found refuseByHint(const Parsed& p, const RobotView& view) {
  if (has(p, "a motion is already running") || has(p, "a motion is running")) return motionRunning();
  if (has(p, "hand guiding is active") || has(p, "hand guiding is on")) return guiding();
  if (has(p, "emergency stop is pressed") || has(p, "aborted by an emergency stop") || has(p, "manual recovery required"))
    return emergencyStop();
  if (has(p, "aborted by a reflex") || has(p, "error bits are set") || has(p, "aborted by an error")) return errorsSet(view);
  if (has(p, "the motors are off")) return motorsOff();
  if (has(p, "guard stop is active")) return guardStop();
  if (has(p, "still stopping")) return stillStopping();
  if (has(p, "rebooting")) return rebooting();
  if (callIs(p, "startMove") && has(p, "singular pose"))
    return says(tr("The arm is in an awkward pose for a straight-line move"),
                tr("The arm is stretched or two wrist axes are in line."),
                tr("Jog a joint a little (Jog panel, joint buttons), then try again."));
  if (has(p, "not possible in the robot's current state")) {
    if (Found m = refuseByCommand(p)) return m;
    if (has(p, "gave no reason"))
      return says(tr("The robot refused without a reason"),
                  tr("The motors are on, no stop or error is active and the arm stands still."),
                  tr("Try again; if it keeps refusing, restart the controller."));
    return says(tr("The robot cannot do this now"), tr("It may be moving, hand guided or still stopping."),
                tr("Wait a moment, then try again."));
  }
  if (has(p, "invalid argument"))
    return says(tr("The robot refused the value"), {},
                tr("Check the values against the ranges in the fields' tooltips, then apply again."));
  return std::nullopt;
}

// ---- Motions that ended badly ----------------------------------------------------------------

// The bits named in a ControlException's message ("... with error bits 15 kCollision (...)").
std::array<bool, kErrorBitCount> bitsNamedIn(const QString& raw) {
  std::array<bool, kErrorBitCount> bits{};
  static const QRegularExpression named(QStringLiteral(R"(\b(k[A-Z][A-Za-z]+)\b)"));
  for (auto it = named.globalMatch(raw); it.hasNext();) {
    const QString name = it.next().captured(1);
    for (int bit = 0; bit < kErrorBitCount; ++bit)
      if (name == QLatin1String(xmate::client::errorBitName(bit))) bits[size_t(bit)] = true;
  }
  return bits;
}

OperatorMessage stoppedWithBits(const std::array<bool, kErrorBitCount>& bits, const RobotView& view) {
  // The bits as the Safety panel explains them, with the live specifics when the view has them.
  LiveState shown;
  RobotView bits_view = view;
  if (view.live) shown = *view.live;
  shown.state.errors = bits;
  shown.safety_stop = 1;
  bits_view.live = &shown;
  QStringList titles, whats, todos, names;
  for (const OperatorMessage& m : activeProblems(bits_view)) {
    if (m.detail.isEmpty()) continue;  // only the bits, not limits without a bit
    titles << m.title;
    whats << m.what;
    if (!todos.contains(m.todo)) todos << m.todo;
  }
  if (titles.isEmpty()) {
    return says(tr("The robot stopped the motion because of an error"), {},
                tr("See the Safety panel, then press Recover there."));
  }
  return says(tr("The robot stopped the motion: %1").arg(titles.join(QStringLiteral("; "))), whats.join(QLatin1Char(' ')),
              todos.join(QLatin1Char(' ')));
}

Found motionEnded(const Parsed& p, const RobotView& view) {
  if (has(p, "with error bits")) return stoppedWithBits(bitsNamedIn(p.body), view);
  if (has(p, "ended the motion without error bits"))
    return says(tr("The robot ended the motion"), tr("An emergency stop, a guard stop or another program stopped it."),
                tr("Look at the stop lamps in the Safety panel; release the stop, then start the motion again."));
  if (has(p, "did not start the motion within"))
    return says(tr("The robot did not start the motion"), {},
                tr("Try again; if it happens again, disconnect and connect again."));
  if (has(p, "kept moving for"))
    return says(tr("The robot did not stop at the end of the motion"), tr("The window stopped it."),
                tr("Check where the arm is, then continue."));
  if (has(p, "stopped by the operator")) return says(tr("Stopped by the operator"), {}, {});
  return std::nullopt;
}

// ---- Planning (a move that cannot be made) --------------------------------------------------

const char* const kRetouch = QT_TRANSLATE_NOOP("OperatorText",
    "Re-teach the target or via point within the arm's reach and away from that pose (Touch up in the Program "
    "panel), or make it a joint move (type J).");

Found planning(const Parsed& p) {
  static const QRegularExpression follow(QStringLiteral(R"(cannot be followed at (\d+)%.*m: (.+?) \(IK code)"));
  if (const auto m = follow.match(p.body); m.hasMatch())
    return says(tr("The path cannot be followed"), tr("At %1 % of the way %2.").arg(m.captured(1), m.captured(2)),
                tr(kRetouch));
  static const QRegularExpression singular(QStringLiteral(R"(too close to a singular pose: at (\d+)%)"));
  if (const auto m = singular.match(p.body); m.hasMatch())
    return says(tr("The path passes too close to an awkward pose"),
                tr("At %1 % of the way the arm would have to stretch fully or line up two wrist axes.").arg(m.captured(1)),
                tr(kRetouch));
  static const QRegularExpression range(
      QStringLiteral(R"(q_target\[(\d)\] = (-?[\d.]+) rad is outside the joint range \[(-?[\d.]+), (-?[\d.]+)\])"));
  if (const auto m = range.match(p.body); m.hasMatch()) {
    auto deg = [&](int i) { return QString::number(m.captured(i).toDouble() * kDegPerRad, 'f', 1); };
    return says(tr("The target is outside the joint range"),
                tr("It puts J%1 at %2°, outside %3° to %4°.").arg(m.captured(1).toInt() + 1).arg(deg(2), deg(3), deg(4)),
                tr("Re-teach the target (Touch up in the Program panel)."));
  }
  static const QRegularExpression joint_limit(QStringLiteral(
      R"(joint (\d) would reach (-?[\d.]+) deg, beyond its (soft )?(upper|lower) limit of (-?[\d.]+) deg.*?(at the target|(\d+) % of the way))"));
  if (const auto m = joint_limit.match(p.body); m.hasMatch()) {
    const bool soft = !m.captured(3).isEmpty();
    const QString where = m.captured(6) == QLatin1String("at the target") ? tr("at the target")
                                                                         : tr("at %1 % of the way").arg(m.captured(7));
    return says(soft ? tr("The motion would pass a soft limit") : tr("The motion would leave the joint range"),
                tr("J%1 would reach %2° %3, beyond its %4 limit of %5°. Nothing moved.")
                    .arg(m.captured(1), m.captured(2), where,
                         m.captured(4) == QLatin1String("upper") ? tr("upper") : tr("lower"), m.captured(5)),
                soft ? tr("Re-teach the target within the limits, or widen them in the Soft limits panel.")
                     : tr("Re-teach the target (Touch up in the Program panel)."));
  }
  static const QRegularExpression box(QStringLiteral(
      R"(leave the safety box through its ([+-][xyz]) face \((-?[\d.]+) m from the box centre\) and reach (-?[\d.]+) m.*?(at the target|(\d+) % of the way))"));
  if (const auto m = box.match(p.body); m.hasMatch()) {
    const QString where = m.captured(4) == QLatin1String("at the target") ? tr("at the target")
                                                                         : tr("at %1 % of the way").arg(m.captured(5));
    return says(tr("The motion would leave the safety box"),
                tr("The TCP would cross the box's %1 face %2 (%3 m from its centre, the TCP at %4 m). Nothing moved.")
                    .arg(m.captured(1), where, m.captured(2), m.captured(3)),
                tr("Re-teach the target inside the box, add a waypoint inside it, or enlarge the box in the Safety box "
                   "panel."));
  }
  if (has(p, "still stopping")) return stillStopping();
  if (has(p, "ik failed during the motion"))
    return says(tr("The path could not be followed during the motion"), tr("The motion was stopped."),
                tr(kRetouch));
  if (has(p, "from the robot's position") || has(p, "from the robot's tcp pose") || has(p, "start.psi") ||
      has(p, "the model puts the tcp"))
    return says(tr("The motion did not start from where the robot is"), {},
                tr("Wait until the arm is at rest, then try again."));
  static const QRegularExpression di(QStringLiteral(R"((DI\d_\d) did not become (true|false) within (\d+) ms)"));
  if (const auto m = di.match(p.body); m.hasMatch())
    return says(tr("The input did not change in time"),
                tr("%1 did not become %2 within %3 ms.")
                    .arg(m.captured(1), m.captured(2) == QLatin1String("true") ? tr("high") : tr("low"), m.captured(3)),
                tr("Check the sensor and its wiring, or give the WAIT_DI instruction a longer timeout."));
  const bool move_call = callIs(p, "MOVEJ") || callIs(p, "MOVEL") || callIs(p, "MOVEC");
  if (move_call) {
    OperatorMessage m = says(tr("The motion cannot be planned"), {}, tr(kRetouch));
    m.detail_inline = true;
    return m;
  }
  return std::nullopt;
}

// ---- The connection -------------------------------------------------------------------------

Found connection(const Parsed& p) {
  if (has(p, "not connected")) return notConnected();
  if (p.call == QLatin1String("connect"))
    return says(tr("Cannot reach the robot"), {},
                tr("Check that the controller is switched on and in RCI mode, and that the address in the toolbar "
                   "is right, then press Connect."));
  if (has(p, "no state from") || has(p, "no response") || has(p, "cannot send to") || has(p, "no session with the controller") ||
      has(p, "session with the controller was closed") || has(p, "stopped answering") || has(p, "stopped sending states"))
    return says(tr("Lost contact with the robot"), tr("The controller stopped answering (network or controller problem)."),
                tr("Check the network cable and that the controller is on; the window reconnects by itself, otherwise "
                   "press Connect in the toolbar."));
  if (has(p, "another protocol version") || has(p, "another rci protocol version"))
    return says(tr("The robot speaks another protocol version"), {},
                tr("Use an RCI Studio version that matches the controller's software."));
  return std::nullopt;
}

OperatorMessage fallback() {
  OperatorMessage m = says(tr("The command did not succeed"), {}, {});
  m.detail_inline = true;
  return m;
}

OperatorMessage classify(const Parsed& p, const RobotView& view) {
  if (Found m = connection(p)) return *m;
  if (Found m = motionEnded(p, view)) return *m;
  if (has(p, "not possible in the robot's current state") || has(p, "not possible while")) {
    if (Found m = refuseFromState(p, view)) return *m;
  }
  if (Found m = refuseByHint(p, view)) return *m;
  if (Found m = refuseByCommand(p)) return *m;
  if (Found m = planning(p)) return *m;
  return fallback();
}

OperatorMessage finish(OperatorMessage m, const Parsed& p, const QString& raw) {
  if (!p.context.isEmpty()) m.title = p.context + QStringLiteral(": ") + m.title;
  m.detail = raw;
  return m;
}

}  // namespace

OperatorMessage failure(const QString& raw, const RobotView& view) {
  const Parsed p = parse(raw);
  return finish(classify(p, view), p, raw);
}

OperatorMessage failure(const std::exception& error, const RobotView& view) {
  const QString raw = QString::fromUtf8(error.what());
  const Parsed p = parse(raw);
  if (const auto* control = dynamic_cast<const xmate::ControlException*>(&error)) {
    bool any = false;
    for (bool bit : control->errors) any = any || bit;
    if (any) return finish(stoppedWithBits(control->errors, view), p, raw);
  }
  if (dynamic_cast<const xmate::TcpException*>(&error) || dynamic_cast<const xmate::UdpException*>(&error) ||
      dynamic_cast<const xmate::NetworkException*>(&error)) {
    if (Found m = connection(p)) return finish(*m, p, raw);
    return finish(says(tr("Lost contact with the robot"), {},
                       tr("Check the network cable and that the controller is on, then press Connect in the toolbar.")),
                  p, raw);
  }
  if (dynamic_cast<const xmate::MotionException*>(&error)) {
    if (Found m = planning(p)) return finish(*m, p, raw);
    OperatorMessage m = says(tr("The motion cannot be planned"), {}, tr(kRetouch));
    m.detail_inline = true;
    return finish(m, p, raw);
  }
  if (dynamic_cast<const std::invalid_argument*>(&error)) {
    OperatorMessage m = says(tr("A value is out of range"), {}, tr("Correct it and try again."));
    m.detail_inline = true;
    return finish(m, p, raw);
  }
  return failure(raw, view);
}

QString connectFailure(const QString& target, const QString& reason) {
  const OperatorMessage m = failure(reason);
  return tr("Could not connect to %1: %2").arg(target, m.detail_inline ? reason : m.line());
}

}  // namespace rci::ui::text
