// SPDX-License-Identifier: Apache-2.0
// The window's entry points to the 3D view (parts.h): createRobotView wires a RobotView to a
// Session (state on tick(), safety box on operatorSettingsChanged(), waypoints and planned path on
// programOverlayChanged(), mouse pull to the simulator);
// captureRobotView renders it to an image.
#include <QMatrix4x4>

#include <algorithm>
#include <cmath>
#include <exception>

#include "model/robot_spec.h"
#include "robot_view.h"
#include "session/session.h"
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

std::vector<LinkTint> tintsOf(const Session& session) {
  const LiveState& live = session.live();
  const xmate::model::RobotSpec& spec = xmate::model::robotSpec(session.target().type);
  TintInputs in;
  in.dof = spec.dof;
  in.q = live.state.q;
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

void showLiveState(RobotView& view, Session& session) {
  const LiveState& live = session.live();
  if (!session.isOpen() || !live.has_state) return;
  if (view.model() != session.target().type) view.setModel(session.target().type);
  if (!view.liveUpdateDue()) return;
  view.setJointPositions(live.state.q);
  view.setTcpPose(live.state.toolTobase_pos_m);
  view.setLinkTints(tintsOf(session));
  view.setPullEnabled(session.simulator() != nullptr && live.simulated && live.sim.dragging);
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

// The spring force of the mouse pull, as an external wrench at the TCP (base frame).
void applyPull(Session& session, const QVector3D& force) {
  xmate::sim::Server* sim = session.simulator();
  if (!sim) return;
  try {
    sim->setExternalWrench({force.x(), force.y(), force.z(), 0, 0, 0});
  } catch (const std::exception&) {
    // Refused wrench (simulator stopping): nothing to pull any more.
  }
}

}  // namespace

QWidget* createRobotView(Session& session, QWidget* parent) {
  auto* view = new RobotView(parent);
  view->setObjectName(QStringLiteral("robotView"));
  if (!view->is3D()) return view;
  Session* s = &session;
  view->setModel(session.target().type);
  showSafetyBox(*view, session.operatorSettings().box);
  QObject::connect(s, &Session::tick, view, [view, s] { showLiveState(*view, *s); });
  QObject::connect(s, &Session::operatorSettingsChanged, view,
                   [view, s] { showSafetyBox(*view, s->operatorSettings().box); });
  QObject::connect(s, &Session::programOverlayChanged, view,
                   [view, s] { showProgramOverlay(*view, s->programOverlay()); });
  QObject::connect(s, &Session::opened, view, [view, s] { view->setModel(s->target().type); });
  QObject::connect(s, &Session::closed, view, [view] {
    view->setPullEnabled(false);
    view->setLinkTints({});
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
