// SPDX-License-Identifier: Apache-2.0
// The window's entry points to the 3D view (parts.h): createRobotView wires a RobotView to a
// Session (the arm's state on tick() for either family, safety box on operatorSettingsChanged(),
// waypoints and planned path on programOverlayChanged(), a KUKA's RSI correction envelope, mouse
// pull to the xMate or KUKA simulator); captureRobotView renders it to an image.
#include <QCoreApplication>
#include <QMatrix4x4>

#include <algorithm>
#include <cmath>
#include <exception>
#include <memory>

#include "arm/rsi_arm.h"
#include "correction_envelope.h"
#include "model/robot_spec.h"
#include "robot_scene.h"
#include "robot_view.h"
#include "session/session.h"
#include "sim/krc_server.h"
#include "window/parts.h"

namespace rci::ui {
namespace {

constexpr int kCollisionBit = 15;  // kCollision (docs/error_bits.md)

void showSafetyBox(RobotView& view, const SafetyBox& box) {
  QMatrix4x4 frame;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) frame(r, c) = float(box.frame[size_t(r * 4 + c)]);
  view.setSafetyBox(box.enabled, QVector3D(float(box.size[0]), float(box.size[1]), float(box.size[2])), frame);
}

// Near-limit tints from the arm's joints (either family); the overload tints from what only an
// xMate reports (external torques, the collision bit: zero on a KUKA).
std::vector<LinkTint> tintsOf(const Session& session) {
  const LiveState& live = session.live();
  const xmate::model::RobotSpec& spec = session.spec();
  TintInputs in;
  in.dof = spec.dof;
  in.q = live.arm.sample.q;
  in.lower = spec.q_min;
  in.upper = spec.q_max;
  const OperatorSettings& settings = session.operatorSettings();
  if (settings.soft_limits_enabled) {  // the tighter of the hardware and the soft limits
    for (size_t i = 0; i < in.lower.size(); ++i) {
      in.lower[i] = std::max(in.lower[i], settings.soft_lower_deg[i] * M_PI / 180.0);
      in.upper[i] = std::min(in.upper[i], settings.soft_upper_deg[i] * M_PI / 180.0);
    }
  }
  in.tau_ext = live.tau_ext;
  in.thresholds = settings.collision_thresholds;
  in.collision = live.state.errors[kCollisionBit];
  return linkTints(in);
}

// Whether the mouse pull may push the robot: in the KUKA simulator always (the force acts at the
// flange), in the xMate simulator while it drags; never on a real robot.
void enablePull(RobotView& view, Session& session) {
  const LiveState& live = session.live();
  if (session.kukaSimulator() != nullptr) {
    view.setPullEnabled(live.connected);
  } else if (session.rsiArm() != nullptr) {
    view.setPullEnabled(false, QCoreApplication::translate("RobotView",
                                                           "Mouse pull pushes the built-in simulators only; this is "
                                                           "a real robot."));
  } else {
    view.setPullEnabled(session.simulator() != nullptr && live.simulated && live.sim.dragging);
  }
}

void showLiveState(RobotView& view, Session& session) {
  const LiveState& live = session.live();
  if (!session.isOpen() || !live.has_arm_state) return;
  if (view.spec().name != session.spec().name) view.setModel(session.spec());
  if (!view.liveUpdateDue()) return;
  view.setJointPositions(live.arm.sample.q);
  view.setTcpPose(live.arm.tcp);
  view.setLinkTints(tintsOf(session));
  enablePull(view, session);
}

// The RSI session the correction envelope was drawn for.
struct EnvelopeShown {
  bool visible = false;
  uint32_t session = 0;
  std::array<double, 6> q_on{};
};

// A KUKA's correction envelope while RSI runs: drawn anew when an RSI session starts (its start
// pose q_on changes), hidden while RSI is off and on an xMate.
void showCorrectionEnvelope(RobotView& view, Session& session, EnvelopeShown& shown) {
  xmate::arm::RsiArm* rsi = session.rsiArm();
  xmate::arm::StreamState state;
  const bool running = rsi != nullptr && session.isOpen() &&
                       session.live().rsi.phase == xmate::rsi::SessionPhase::kRunning && rsi->stream().state(state) &&
                       view.scene() != nullptr && view.scene()->poser() != nullptr &&
                       view.scene()->poser()->spec().name == rsi->spec().name;
  if (!running) {
    if (shown.visible) view.setCorrectionEnvelope(false);
    shown = {};
    return;
  }
  if (shown.visible && shown.session == state.session && shown.q_on == state.q_on) return;
  const xmate::rsi::AxisCorrectionLimits& limits = rsi->stream().limits();
  const CorrectionEnvelope envelope =
      correctionEnvelope(*view.scene()->poser(), state.q_on, limits.lower, limits.upper);
  view.setCorrectionEnvelope(envelope.valid, envelope.min, envelope.max);
  shown = {envelope.valid, state.session, state.q_on};
}

QVector3D toVector(const std::array<double, 3>& p) { return QVector3D(float(p[0]), float(p[1]), float(p[2])); }

// The Program panel's waypoints and planned path (Session::programOverlay).
void showProgramOverlay(RobotView& view, const ProgramOverlay& overlay) {
  std::vector<QVector3D> waypoints, path;
  waypoints.reserve(overlay.waypoints.size());
  for (const auto& p : overlay.waypoints) waypoints.push_back(toVector(p));
  path.reserve(overlay.path.size());
  for (const auto& p : overlay.path) path.push_back(toVector(p));
  view.setWaypoints(waypoints);
  view.setPlannedPath(path);
}

// The spring force of the mouse pull, as an external wrench (base frame): at the TCP in the xMate
// simulator, at the flange in the KUKA simulator (its F/T sensor then reads it).
void applyPull(Session& session, const QVector3D& force) {
  const std::array<double, 6> wrench{force.x(), force.y(), force.z(), 0, 0, 0};
  if (xmate::sim::Server* sim = session.simulator()) {
    try {
      sim->setExternalWrench(wrench);
    } catch (const std::exception&) {
      // Refused wrench (simulator stopping): nothing to pull any more.
    }
  } else if (xmate::sim::KrcServer* krc = session.kukaSimulator()) {
    krc->krc().setExternalWrench(wrench);
  }
}

}  // namespace

QWidget* createRobotView(Session& session, QWidget* parent) {
  auto* view = new RobotView(parent);
  view->setObjectName(QStringLiteral("robotView"));
  if (!view->is3D()) return view;
  Session* s = &session;
  view->setModel(session.spec());
  showSafetyBox(*view, session.operatorSettings().box);
  auto envelope = std::make_shared<EnvelopeShown>();
  QObject::connect(s, &Session::tick, view, [view, s, envelope] {
    showLiveState(*view, *s);
    showCorrectionEnvelope(*view, *s, *envelope);
  });
  QObject::connect(s, &Session::operatorSettingsChanged, view,
                   [view, s] { showSafetyBox(*view, s->operatorSettings().box); });
  QObject::connect(s, &Session::programOverlayChanged, view,
                   [view, s] { showProgramOverlay(*view, s->programOverlay()); });
  QObject::connect(s, &Session::opened, view, [view, s] { view->setModel(s->spec()); });
  QObject::connect(s, &Session::closed, view, [view, envelope] {
    view->setPullEnabled(false);
    view->setLinkTints({});
    view->setCorrectionEnvelope(false);
    *envelope = {};
  });
  QObject::connect(view, &RobotView::pullForceChanged, s, [s](const QVector3D& force) { applyPull(*s, force); });
  return view;
}

void captureRobotView(QWidget* view, std::function<void(const QImage&)> done) {
  auto* robot_view = qobject_cast<RobotView*>(view);
  if (!robot_view) {
    done(QImage());
    return;
  }
  robot_view->captureWidget(std::move(done));
}

}  // namespace rci::ui
