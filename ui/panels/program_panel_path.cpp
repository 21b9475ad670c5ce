// SPDX-License-Identifier: Apache-2.0
// Program panel: teach by demonstration -- recording the path the operator guides the arm
// along as a PATH instruction (every cycle of the arm's sample stream, shown live in the 3D view),
// and the last run's result per instruction in words (a PATH's deviation from the demonstration and
// how much the robot's limits slowed it).
#include <QLabel>
#include <QPushButton>

#include <algorithm>
#include <cmath>

#include "arm/arm.h"
#include "panels/fields.h"
#include "panels/program_model.h"
#include "panels/program_panel.h"
#include "session/session.h"
#include "teach/recording.h"

namespace rci::ui {

using xmate::teach::Instruction;
using xmate::teach::InstructionType;

namespace {

// The 3D view's trace of the path being recorded: one TCP point per this much recording.
constexpr double kTracePeriod = 0.01;  // s

// "8 203": digits in groups of three (a no-break space between them, so a count never wraps), as the operator reads counts.
QString groupDigits(uint64_t n) {
  QString digits = QString::number(n);
  for (int i = digits.size() - 3; i > 0; i -= 3) digits.insert(i, QChar(0x00A0));
  return digits;
}

// The recorder's reason as a sentence (a full stop at its end).
QString sentence(QString text) {
  text = text.trimmed();
  if (!text.isEmpty() && !text.endsWith(QLatin1Char('.'))) text += QLatin1Char('.');
  return text;
}

QString lostText(uint64_t lost) {
  return lost == 0 ? ProgramPanel::tr("none lost")
                   : ProgramPanel::tr("%1 lost (bridged by the spline through the others)").arg(groupDigits(lost));
}

}  // namespace

void ProgramPanel::startPathRecording() {
  if (!mayRecord()) return;
  xmate::arm::Arm* arm = session().arm();
  if (!arm) return;  // mayRecord saw a state: the arm is there
  adoptToolForPath();
  path_recorder_ = std::make_unique<xmate::teach::PathRecorder>(session().spec(), arm->cycleSeconds());
  dropped_at_start_ = dropped_now_ = arm->samplesDropped();
  recording_trace_.clear();
  trace_every_ = size_t(std::max(1L, std::lround(kTracePeriod / arm->cycleSeconds())));
  trace_counter_ = 0;
  updateRecordButton();
  updateButtons();
  showRecordingState();
  note(tr("Recording a path: guide the arm along it, then press Stop recording path (F9)."), false);
}

void ProgramPanel::adoptToolForPath() {
  path_has_tool_ = false;
  if (program().has_tool) return;
  xmate::teach::Program adopted = program();
  // A PATH is joints only: a tool that does not match cannot make it go elsewhere, so a refusal
  // (the program has poses but no tool) leaves the program as it is.
  if (!adoptRobotTool(adopted).empty() || !adopted.has_tool) return;
  path_has_tool_ = true;
  path_tool_ = adopted.tool;
  path_load_ = adopted.load;
}

void ProgramPanel::takeArmSamples(const xmate::arm::ArmSample* samples, int count) {
  if (!path_recorder_ || count <= 0) return;
  path_recorder_->add(samples, size_t(count));
  if (const xmate::arm::Arm* arm = session().arm()) dropped_now_ = arm->samplesDropped();
  for (int i = 0; i < count; ++i)
    if (trace_counter_++ % trace_every_ == 0) recording_trace_.push_back(samples[i].tcp_position);
  if (path_recorder_->sessionChanged()) {
    stopPathRecording(tr("the controller began a new session"));
    return;
  }
  showRecordingState();
  publishOverlay();
}

bool ProgramPanel::refusedWhileRecording(const QString& action) {
  if (!isRecordingPath()) return false;
  showStatus(tr("%1: a path is being recorded — press Stop recording path (F9) first.").arg(action), true);
  return true;
}

uint64_t ProgramPanel::lostSinceStart() const {
  if (!path_recorder_) return 0;
  // A sample the ring dropped is also a gap in the cycles the recorder saw: the larger of the two
  // counts every lost cycle once.
  return std::max<uint64_t>(path_recorder_->lostCycles(), dropped_now_ - dropped_at_start_);
}

void ProgramPanel::showRecordingState() {
  if (!path_recorder_) return;
  record_state_->setText(tr("Recording path: %1 s, %2 samples, %3. Press Stop recording path (F9) when done.")
                             .arg(path_recorder_->seconds(), 0, 'f', 1)
                             .arg(groupDigits(path_recorder_->samples()), lostText(lostSinceStart())));
}

void ProgramPanel::stopPathRecording(const QString& why) {
  if (!path_recorder_) return;
  const uint64_t lost = lostSinceStart();
  const std::unique_ptr<xmate::teach::PathRecorder> recorder = std::move(path_recorder_);
  recording_trace_.clear();
  updateRecordButton();
  const QString ended = why.isEmpty() ? QString() : tr("The path recording ended: %1. ").arg(why);
  xmate::teach::PathRecorder::Result result;
  try {
    result = recorder->finish();
  } catch (const std::exception& e) {
    record_state_->setText(tr("No path recorded."));
    note(ended + tr("No path recorded: %1").arg(sentence(QString::fromStdString(e.what()))), true);
    updateButtons();
    publishOverlay();
    return;
  }
  const int row = selectedRow() >= 0 ? selectedRow() + 1 : model_->count();
  if (!program().has_tool && path_has_tool_) {  // the first recording of the program: its tool
    xmate::teach::Program adopted = program();
    adopted.has_tool = true;
    adopted.tool = path_tool_;
    adopted.load = path_load_;
    model_->setProgram(adopted);
  }
  Instruction in;
  in.type = InstructionType::kPath;
  in.name = model_->nextName(ProgramModel::namePrefix(InstructionType::kPath)).toStdString();
  in.path = result.path;
  in.speed = 1.0;  // as demonstrated
  model_->insert(row, in);
  selectRow(row);

  const xmate::teach::PathSummary summary = xmate::teach::summarizePath(in.path, *program().robot, program().tool);
  const QString name = QString::fromStdString(in.name);
  record_state_->setText(tr("Recorded %1.").arg(name));
  note(ended + tr("Recorded path \"%1\": %2 s, %3 m of TCP path, %4 samples at %5 Hz; %6 cycles recorded, %7; "
                  "%8 s of rest trimmed. It is instruction %9.")
                   .arg(name)
                   .arg(summary.duration, 0, 'f', 1)
                   .arg(summary.tcp_length, 0, 'f', 2)
                   .arg(groupDigits(summary.samples), QString::number(in.path.rate_hz, 'g', 6),
                        groupDigits(result.recorded), lostText(std::max<uint64_t>(lost, result.lost_cycles)))
                   .arg(result.trimmed_start + result.trimmed_end, 0, 'f', 1)
                   .arg(row + 1),
       false);
  updateButtons();
}

QStringList ProgramPanel::instructionResults(const xmate::teach::RunReport& report) const {
  using xmate::teach::InstructionStatus;
  QStringList lines;
  for (size_t i = 0; i < report.instructions.size() && i < size_t(model_->count()); ++i) {
    const xmate::teach::InstructionReport& r = report.instructions[i];
    const Instruction& in = model_->instruction(int(i));
    switch (r.status) {
      case InstructionStatus::kNotRun: lines << tr("not run"); continue;
      case InstructionStatus::kRunning: lines << tr("running"); continue;
      case InstructionStatus::kFailed: lines << tr("failed: %1").arg(QString::fromStdString(r.message)); continue;
      case InstructionStatus::kStopped:
      case InstructionStatus::kDone: break;
    }
    QString line = r.status == InstructionStatus::kStopped ? tr("stopped after %1 s").arg(r.duration, 0, 'f', 1)
                                                           : tr("done in %1 s").arg(r.duration, 0, 'f', 1);
    if (in.type == InstructionType::kPath) {
      if (r.lead_in > 0) line += tr(" after %1 s to its start").arg(r.lead_in, 0, 'f', 1);
      line += tr("; within %1 mrad (%2 mm at the TCP) of the demonstrated path; ")
                  .arg(r.path_joint_deviation * 1e3, 0, 'f', 2)
                  .arg(r.path_tcp_deviation * 1e3, 0, 'f', 2);
      line += r.slowest_pace < 0.995 ? tr("slowed to %1 % at %2 s of the path (%3 % of it slower than asked)")
                                           .arg(std::lround(r.slowest_pace * 100))
                                           .arg(r.slowest_at, 0, 'f', 1)
                                           .arg(std::lround(r.slowed_share * 100))
                                     : tr("not slowed");
    } else if (xmate::teach::isMotion(in.type)) {
      line += tr("; tracking within %1 mm").arg(r.max_tcp_error * 1e3, 0, 'f', 2);
    }
    lines << line;
  }
  return lines;
}

void ProgramPanel::reportPaths(const xmate::teach::RunReport& report) {
  double joint = 0, tcp = 0, slowest = 1;
  int paths = 0;
  for (size_t i = 0; i < report.instructions.size() && i < size_t(model_->count()); ++i) {
    if (model_->instruction(int(i)).type != InstructionType::kPath) continue;
    const xmate::teach::InstructionReport& r = report.instructions[i];
    ++paths;
    joint = std::max(joint, r.path_joint_deviation);
    tcp = std::max(tcp, r.path_tcp_deviation);
    slowest = std::min(slowest, r.slowest_pace);
    session().reportEvent(Session::EventLevel::kInfo,
                          title() + QStringLiteral(": ") +
                              tr("%1: %2.").arg(QString::fromStdString(xmate::teach::describe(program(), i)),
                                                model_->result(int(i))));
  }
  if (paths == 0) return;
  const QString slowed = slowest < 0.995 ? tr("slowed to %1 % of the asked pace where the robot's limits required")
                                               .arg(std::lround(slowest * 100))
                                         : tr("not slowed");
  const QString which = paths == 1 ? tr("The path was") : tr("The %1 paths were").arg(paths);
  showStatus(statusLine()->text() + QLatin1Char(' ') +
                 tr("%1 followed within %2 mrad (%3 mm at the TCP), %4.")
                     .arg(which)
                     .arg(joint * 1e3, 0, 'f', 2)
                     .arg(tcp * 1e3, 0, 'f', 2)
                     .arg(slowed),
             false);
}

}  // namespace rci::ui
