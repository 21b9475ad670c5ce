// SPDX-License-Identifier: Apache-2.0
// Program panel: running the program with the teach executor through Session::runArmMotion -- run,
// step, pause, resume, stop, go to a waypoint, the progress display, the pre-flight problems and
// the 3D view's program overlay (waypoints, the planned path and the path being recorded).
#include <QBrush>
#include <QComboBox>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QSlider>
#include <QTableView>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <optional>

#include <xmate/model.h>

#include "arm/arm.h"
#include "model/arm_kinematics.h"
#include "panels/fields.h"
#include "panels/lamp.h"
#include "panels/program_model.h"
#include "panels/program_panel.h"
#include "session/session.h"
#include "teach/program_io.h"
#include "teach/recording.h"
#include "text/operator_text.h"

namespace rci::ui {

using xmate::teach::RunState;

namespace {

// Go to: a joint move at no more than this speed ratio.
constexpr double kGotoSpeed = 0.2;

}  // namespace

void ProgramPanel::runClicked() {
  startRun(program(), false, tr("run"));
}

void ProgramPanel::stepClicked() {
  if (running_) {
    run_slot_->executor.setSingleStep(true);
    run_slot_->executor.resume();
    return;
  }
  startRun(program(), true, tr("step"));
}

void ProgramPanel::pauseClicked() {
  if (running_) run_slot_->executor.pause();
}

void ProgramPanel::resumeClicked() {
  if (!running_) return;
  run_slot_->executor.setSingleStep(false);
  run_slot_->executor.resume();
}

void ProgramPanel::stopClicked() {
  if (!running_) return;
  run_slot_->executor.stop();
  session().requestStop();  // the same token the toolbar's Stop motion sets
}

void ProgramPanel::gotoClicked() {
  const int row = selectedRow();
  if (row < 0 || !xmate::teach::isMotion(model_->instruction(row).type)) {
    showStatus(tr("Go to: select a move instruction first."), true);
    return;
  }
  const auto& in = model_->instruction(row);
  xmate::teach::Target target = in.target;
  if (in.type == xmate::teach::InstructionType::kPath) {  // a path: where it starts
    if (in.path.q.empty()) {
      showStatus(tr("Go to: the path has no samples — record it again."), true);
      return;
    }
    target = xmate::teach::Target{};
    target.has_q = true;
    target.q = in.path.q.front();
  }
  xmate::teach::Program one;
  one.robot = program().robot;
  one.instructions.push_back(xmate::teach::moveJ(target, std::min(in.speed, kGotoSpeed), in.name));
  startRun(one, false, tr("go to instruction %1").arg(row + 1));
}

void ProgramPanel::startRun(const xmate::teach::Program& program, bool single_step, const QString& action) {
  if (running_) {
    showStatus(tr("%1: a run is already active.").arg(action), true);
    return;
  }
  if (!isOpen()) {
    showStatus(tr("%1: not connected — connect to a robot or the simulator first.").arg(action), true);
    return;
  }
  if (refusedWhileRecording(action)) return;
  xmate::teach::ExecutorOptions options = executorOptions();
  options.single_step = single_step;
  options.speed_override = speed_->value() / 100.0;
  running_ = true;
  goto_run_ = action.startsWith(tr("go to"));
  run_label_ = title() + QStringLiteral(": ") + action;
  run_state_->setText(tr("Starting: %1").arg(action));
  progress_->setValue(0);
  progress_->setFormat(goto_run_ ? tr("Go to: %p %") : tr("Checking"));
  showStatus(action + QStringLiteral(" ..."), false);
  updateButtons();
  std::shared_ptr<RunSlot> slot = run_slot_;
  // The executor drives an xMate through its vendor API and a KUKA through its RSI arm.
  session().runArmMotion(run_label_, [slot, program, options](xmate::arm::Arm& arm, const MotionToken& token) {
    xmate::teach::ExecutorOptions with_token = options;
    with_token.stop_token = &token.stopFlag();  // Stop, disconnect and quit end the run
    slot->report = slot->executor.run(arm, program, with_token);
  });
}

xmate::teach::ExecutorOptions ProgramPanel::executorOptions() const {
  xmate::teach::ExecutorOptions options;
  const OperatorSettings& s = session().operatorSettings();
  if (s.soft_limits_enabled) {
    options.has_soft_limits = true;
    for (size_t j = 0; j < 7; ++j) {
      options.soft_lower[j] = s.soft_lower_deg[j] / kDegPerRad;
      options.soft_upper[j] = s.soft_upper_deg[j] / kDegPerRad;
    }
  }
  if (s.box.enabled) {
    options.has_box = true;
    options.box.size = s.box.size;
    options.box.frame = s.box.frame;
  }
  return options;
}

xmate::teach::TraceOptions ProgramPanel::traceOptions() const {
  const xmate::teach::ExecutorOptions e = executorOptions();
  xmate::teach::TraceOptions options;
  options.q_start = currentQ();
  if (auto* robot = session().robot()) options.tool = robot->toolFrame();
  if (haveLiveState()) {  // the measured TCP, for the check of the program's tool
    options.has_tcp = true;
    options.tcp = session().live().arm.tcp;
  }
  options.has_soft_limits = e.has_soft_limits;
  options.soft_lower = e.soft_lower;
  options.soft_upper = e.soft_upper;
  options.has_box = e.has_box;
  options.box = e.box;
  // Where motions are held within correction limits (RSI), the joints a PATH may reach: the start
  // pose plus those limits.
  const xmate::arm::Arm* arm = session().arm();
  if (arm && xmate::arm::has(arm->capabilities(), xmate::arm::Capability::kCorrectionLimits)) {
    try {
      const xmate::arm::MotionBounds bounds = arm->motionBounds();
      options.joint_lower = bounds.lower;
      options.joint_upper = bounds.upper;
      options.has_joint_bounds = true;
    } catch (const std::runtime_error&) {  // RSI not running yet: nothing to check against
    }
  }
  return options;
}

std::array<double, 7> ProgramPanel::currentQ() const {
  if (haveLiveState()) return session().live().arm.sample.q;
  return {};
}

void ProgramPanel::commandDone(const QString& action, bool ok, const QString&) {
  // runArmMotion refuses (e.g. another motion runs) with commandFinished and no motionFinished.
  if (!ok && running_ && title() + QStringLiteral(": ") + action == run_label_) {
    running_ = false;
    run_label_.clear();
    run_state_->setText(tr("Not started"));
    progress_->setFormat(tr("Idle"));
    updateButtons();
  }
}

void ProgramPanel::runFinished(const QString& label, bool ok, const QString& message) {
  if (!running_ || label != run_label_) return;
  const QString action = label.mid(title().size() + 2);
  running_ = false;
  run_label_.clear();
  model_->setCurrent(-1);
  updateOverlay();  // from where the robot is now
  if (!ok) {
    run_state_->setText(tr("Failed"));
    progress_->setFormat(tr("Failed"));
    showFailure(action, message);
  } else {
    last_report_ = run_slot_->report;
    if (!goto_run_) model_->setResults(instructionResults(last_report_));
    showReport(last_report_);
  }
  updateButtons();
}

void ProgramPanel::showReport(const xmate::teach::RunReport& report) {
  const QString what = goto_run_ ? tr("Go to") : tr("Run");
  const QString message = QString::fromStdString(report.message);
  run_state_->setText(QString::fromLatin1(xmate::teach::runStateName(report.outcome)));
  switch (report.outcome) {
    case RunState::kFinished:
      progress_->setValue(1000);
      progress_->setFormat(tr("Done"));
      showStatus(tr("%1 finished in %2 s.").arg(what).arg(report.duration, 0, 'f', 1), false);
      session().reportEvent(Session::EventLevel::kInfo, title() + QStringLiteral(": ") + statusLine()->text());
      if (!goto_run_) reportPaths(report);
      break;
    case RunState::kStopped:
      progress_->setFormat(tr("Stopped"));
      showStatus(message.isEmpty() ? tr("%1 stopped.").arg(what) : tr("%1 stopped: %2").arg(what, text::failure(message).line()),
                 false, message);
      session().reportEvent(Session::EventLevel::kWarning, title() + QStringLiteral(": ") + statusLine()->text(), message);
      break;
    case RunState::kRefused:
      progress_->setValue(0);
      progress_->setFormat(tr("Refused"));
      showProblems(report.problems);
      showStatus(tr("%1 refused by the pre-flight, nothing moved: %n problem(s), listed below.", nullptr,
                    int(report.problems.size()))
                     .arg(what) +
                     (report.problems.empty() ? QStringLiteral(" ") + message : QString()),
                 true);
      session().reportEvent(Session::EventLevel::kWarning, title() + QStringLiteral(": ") + statusLine()->text(), message);
      break;
    default:
      progress_->setFormat(tr("Failed"));
      showFailure(what, message);
      session().reportEvent(Session::EventLevel::kError, title() + QStringLiteral(": ") + statusLine()->text(), message);
      if (report.failed_instruction >= 0 && !goto_run_) selectRow(int(report.failed_instruction));
      break;
  }
}

void ProgramPanel::showProblems(const std::vector<xmate::teach::Problem>& problems,
                                const std::vector<xmate::teach::Problem>& notices) {
  problems_->clear();
  for (const auto& p : problems) {
    auto* item = new QListWidgetItem(text::programProblem(p.message), problems_);
    item->setToolTip(QString::fromStdString(p.message));
    item->setData(Qt::UserRole, int(p.instruction));
    item->setForeground(QBrush(lampRed()));
  }
  for (const auto& n : notices) {  // in the normal colour: nothing is wrong
    auto* item = new QListWidgetItem(text::programProblem(n.message), problems_);
    item->setToolTip(QString::fromStdString(n.message));
    item->setData(Qt::UserRole, int(n.instruction));
  }
  problems_label_->setText(problems.empty() ? tr("Pre-flight notes (nothing wrong; read before you run):")
                                            : tr("Pre-flight problems (nothing moves while there are any):"));
  const bool any = !problems.empty() || !notices.empty();
  // As tall as a wrapped line or two per entry, at most four lines: the instruction list below keeps
  // its room when there is only a note.
  const int lines = std::min(4, 2 * problems_->count());
  problems_->setFixedHeight(problems_->fontMetrics().lineSpacing() * std::max(lines, 2) + 8);
  problems_label_->setVisible(any);
  problems_->setVisible(any);
}

void ProgramPanel::resetRunDisplay() {
  progress_->setValue(0);
  progress_->setFormat(tr("Idle"));
  run_state_->setText(tr("Idle"));
}

void ProgramPanel::updateProgress() {
  if (!running_) return;
  const xmate::teach::Progress p = run_slot_->executor.progress();
  run_state_->setText(QString::fromLatin1(xmate::teach::runStateName(p.state)));
  if (p.instruction < 0) return;
  const double fraction = std::clamp(p.fraction, 0.0, 1.0);
  if (goto_run_) {
    progress_->setValue(int(fraction * 1000));
    progress_->setFormat(tr("Go to: %1 %").arg(int(fraction * 100)));
    return;
  }
  const int n = model_->count();
  progress_->setValue(int((double(p.instruction) + fraction) / std::max(n, 1) * 1000));
  progress_->setFormat(tr("Instruction %1 of %2: %3 %").arg(p.instruction + 1).arg(n).arg(int(fraction * 100)));
  model_->setCurrent(int(p.instruction));
}

void ProgramPanel::refresh(const LiveState& live) {
  updateProgress();
  updateButtons();
  followRobot(live);
  const int di = di_trigger_->currentData().toInt();
  if (di < 0 || di >= 64) return;
  const bool level = (live.inputs >> di) & 1u;
  const bool rising = di_known_ && level && !last_di_;
  last_di_ = level;
  di_known_ = true;
  if (rising && record_->isEnabled()) record();
}

void ProgramPanel::sessionOpened() {
  di_known_ = false;  // no inputs polled yet
  fillDiTrigger();
  if (model_->count() == 0) newProgram();
  updateButtons();
  updateOverlay();
}

void ProgramPanel::sessionClosed() {
  // A run cannot outlive its session: the session's stop token ends it; stop the executor too, and
  // leave it to its job -- the next run gets a fresh executor even if the old one is still ending.
  if (running_) {
    run_slot_->executor.stop();
    run_slot_ = std::make_shared<RunSlot>();
    running_ = false;
    run_label_.clear();
    model_->setCurrent(-1);
    run_state_->setText(tr("Ended: the connection closed"));
    showStatus(tr("The run ended: the connection closed. Connect again, then run or step from the start."), true);
  }
  cancelPendingVia();
  // What the operator demonstrated so far is kept: the recording ends with it.
  if (isRecordingPath()) stopPathRecording(tr("the connection closed"));
  updateButtons();
}

std::string ProgramPanel::otherModelProblem() const {
  try {
    xmate::teach::requireRobot(program(), spec());
    return {};
  } catch (const std::exception& e) {
    return e.what();
  }
}

void ProgramPanel::updateOverlay() {
  const auto& p = program();
  // A program for another model: its poses and joints mean nothing for this robot -- no preview,
  // and that one problem instead of what tracing it on this arm would say.
  if (const std::string other = otherModelProblem(); !other.empty()) {
    overlay_ = {};
    planned_path_.clear();
    trace_again_ = false;
    if (!running_) showProblems({{0, other}});
    publishOverlay();
    return;
  }
  const xmate::teach::TraceOptions options = traceOptions();
  std::optional<xmate::model::ArmKinematics> model;  // for targets taught as joints only
  auto position = [&](const xmate::teach::Target& t) -> std::array<double, 3> {
    if (t.has_pose) return {t.pose[3], t.pose[7], t.pose[11]};
    if (!model) {
      model.emplace(*p.robot);
      model->SetCoor(p.has_tool ? p.tool : options.tool);
    }
    const auto pose = model->GetCartPose(t.q);
    return {pose[3], pose[7], pose[11]};
  };
  overlay_.waypoints.clear();
  overlay_.labels.clear();
  overlay_.selected = -1;
  const int selected = selectedRow();
  for (size_t i = 0; i < p.instructions.size(); ++i) {
    const auto& in = p.instructions[i];
    if (!xmate::teach::isMotion(in.type)) continue;
    const QString name = in.name.empty() ? QStringLiteral("#%1").arg(i + 1) : QString::fromStdString(in.name);
    if (in.type == xmate::teach::InstructionType::kMoveC) {
      overlay_.waypoints.push_back(position(in.via));
      overlay_.labels.push_back(name + tr(" via"));
    }
    xmate::teach::Target end = in.target;
    if (in.type == xmate::teach::InstructionType::kPath) {  // a path's marker: where it ends
      if (in.path.q.empty()) continue;
      end = xmate::teach::Target{};
      end.has_q = true;
      end.q = in.path.q.back();
    }
    if (int(i) == selected) overlay_.selected = int(overlay_.waypoints.size());
    overlay_.waypoints.push_back(position(end));
    overlay_.labels.push_back(name);
  }
  // The planned path and the pre-flight start where the robot is: only with its state. Until the
  // trace is back the view keeps the previous path.
  if (!haveLiveState()) {
    planned_path_.clear();
    trace_again_ = false;  // a trace still running is for a state that is gone
    if (!running_) showProblems({});
  } else {
    startTrace();
  }
  publishOverlay();
}

void ProgramPanel::publishOverlay() {
  overlay_.path = planned_path_;
  overlay_.path.insert(overlay_.path.end(), recording_trace_.begin(), recording_trace_.end());
  session().setProgramOverlay(overlay_);
}

bool ProgramPanel::isTracing() const { return trace_watcher_ && trace_watcher_->isRunning(); }

void ProgramPanel::startTrace() {
  if (!trace_watcher_) {
    trace_watcher_ = new QFutureWatcher<xmate::teach::ProgramTrace>(this);
    connect(trace_watcher_, &QFutureWatcherBase::finished, this, &ProgramPanel::traceFinished);
  }
  if (trace_watcher_->isRunning()) {
    trace_again_ = true;
    return;
  }
  trace_again_ = false;
  const xmate::teach::TraceOptions options = traceOptions();
  traced_q_ = options.q_start;
  traced_tcp_ = options.tcp;
  // The worker gets copies: the panel may change the program, or go away, meanwhile.
  trace_watcher_->setFuture(QtConcurrent::run(
      [program = program(), options] { return xmate::teach::traceProgram(program, options); }));
}

void ProgramPanel::followRobot(const LiveState& live) {
  constexpr double kMoved = 1e-4;         // rad, m: far below what the preview or a problem shows
  constexpr double kRestingStep = 3e-4;   // rad per display tick (~0.01 rad/s): trace where the arm stopped, not along a drag
  const std::array<double, 7> previous = followed_q_;
  followed_q_ = live.arm.sample.q;
  if (!live.has_arm_state || running_ || model_->count() == 0 || isTracing()) return;
  double moved = 0, step = 0;
  for (size_t i = 0; i < 7; ++i) {
    moved = std::max(moved, std::abs(live.arm.sample.q[i] - traced_q_[i]));
    step = std::max(step, std::abs(live.arm.sample.q[i] - previous[i]));
  }
  for (size_t i = 0; i < 12; ++i) moved = std::max(moved, std::abs(live.arm.tcp[i] - traced_tcp_[i]));
  if (moved > kMoved && step < kRestingStep) updateOverlay();
}

void ProgramPanel::traceFinished() {
  if (trace_again_) {  // the program or the pose changed while it ran: that result is stale
    startTrace();
    return;
  }
  if (!haveLiveState() || !otherModelProblem().empty()) return;  // nothing of it applies now
  const xmate::teach::ProgramTrace trace = trace_watcher_->result();
  planned_path_.clear();
  for (const auto& t : trace.instructions) planned_path_.insert(planned_path_.end(), t.tcp_path.begin(), t.tcp_path.end());
  publishOverlay();
  if (!running_) showProblems(trace.problems, trace.notices);
}

}  // namespace rci::ui
