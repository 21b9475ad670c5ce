// SPDX-License-Identifier: Apache-2.0
// test_program_gui: the Program panel driven through its widgets against the session's embedded
// lock-step simulator -- drag the arm with injected forces, record J / L / C (via + target) with the
// button, F9 and a DI trigger, save, reopen, go to, replay to within 1e-4 rad / 0.1 mm, pause and
// resume mid-move, step and stop, a pre-flight refusal naming the instruction, list editing and the
// unsaved-changes prompt.
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QVBoxLayout>

#include <cmath>

#include "panels/lamp.h"
#include "panels/program_panel.h"
#include "session/session.h"
#include "state_compare.h"
#include "teach/program_io.h"
#include "teach/recording.h"
#include "window/parts.h"
#include "window_driver.h"

using namespace rci::ui;
using xmate::teach::InstructionType;
using xmate::teach::RunState;

namespace {

constexpr int kWaitMs = 30000;  // a safety net for a loaded machine, not a timing claim
constexpr double kJointTolerance = 1e-4;     // rad
constexpr double kPositionTolerance = 1e-4;  // m

using rci_test::anyError;
using rci_test::distance;
using rci_test::maxAbsDiff;

}  // namespace

class TestProgramGui : public QObject {
  Q_OBJECT

 private:
  template <class T>
  T* find(const QString& name) {
    return rci::ui::test::WindowDriver(host_).find<T>(name);
  }
  void click(const QString& name) { QVERIFY2(rci::ui::test::WindowDriver(host_).click(name), qPrintable(name)); }
  QString text(const QString& name) { return find<QLabel>(name)->text(); }
  const RCI::robot::RobotState& state() { return session_->live().state; }
  int rows() { return find<QTableView>(QStringLiteral("program.list"))->model()->rowCount(); }
  QString cell(int row, int column) {
    auto* model = find<QTableView>(QStringLiteral("program.list"))->model();
    return model->data(model->index(row, column)).toString();
  }
  void selectRow(int row) {
    auto* list = find<QTableView>(QStringLiteral("program.list"));
    list->selectRow(row);
  }
  void setRecordType(int index) { find<QComboBox>(QStringLiteral("program.recordType"))->setCurrentIndex(index); }
  bool atRest() {
    double speed = 0;
    for (double v : state().dq_m) speed = std::max(speed, std::abs(v));
    return speed < 1e-5;
  }
  // Pulls the TCP with `force` (N, base frame) until it moved `metres`, lets go and waits for rest.
  void dragBy(const std::array<double, 3>& force, double metres) {
    const auto start = state().toolTobase_pos_m;
    session_->simulator()->setExternalWrench({force[0], force[1], force[2], 0, 0, 0});
    QTRY_VERIFY_WITH_TIMEOUT(distance(state().toolTobase_pos_m, start) > metres, kWaitMs);
    session_->simulator()->setExternalWrench({0, 0, 0, 0, 0, 0});
    QTRY_VERIFY_WITH_TIMEOUT(atRest(), kWaitMs);
  }
  // The run ended and the arm came to rest (a run ends once the arm is within 5e-5 rad of its last
  // command and slower than 2e-3 rad/s; the checks here are finer).
  void waitRunEnd() {
    QTRY_VERIFY_WITH_TIMEOUT(!panel_->isRunning(), 3 * kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(!session_->live().motion_running, kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(atRest(), kWaitMs);
  }
  // Writes a program file directly (the file format is core's; the panel opens it as a user would).
  QString writeProgram(const QString& name, const xmate::teach::Program& program) {
    const QString path = dir_.filePath(name);
    xmate::teach::saveProgram(path.toStdString(), program);
    return path;
  }
  void openThroughButton(const QString& path) {
    open_path_ = path;
    click(QStringLiteral("program.open"));
    QCOMPARE(panel_->filePath(), path);
  }
  xmate::teach::Target jointTarget(std::array<double, 7> q) {
    xmate::teach::Target t;
    t.has_q = true;
    t.q = q;
    return t;
  }

  QTemporaryDir settings_dir_;
  QTemporaryDir dir_;
  Session* session_ = nullptr;
  QWidget* host_ = nullptr;
  ProgramPanel* panel_ = nullptr;
  std::vector<PanelSpec> panels_;
  QString open_path_, save_path_;
  ProgramPanel::UnsavedChoice unsaved_choice_ = ProgramPanel::UnsavedChoice::kCancel;
  int prompts_ = 0;

 private slots:
  void initTestCase();
  void cleanupTestCase();
  void panelAndNames();
  void teachSaveReopenReplay();
  void pauseAndResumeMidMove();
  void unreachableTargetRefusedBeforeMoving();
  void stepThenStop();
  void diTriggerRecords();
  void listEditing();
  void unsavedChangesPrompt();
  void anotherToolRefusesTeaching();
  void programOfAnotherModelShowsOneProblem();
};

void TestProgramGui::initTestCase() {
  QStandardPaths::setTestModeEnabled(true);
  QVERIFY(settings_dir_.isValid() && dir_.isValid());
  QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settings_dir_.path());
  QSettings(QStringLiteral("RCI Studio"), QStringLiteral("rci-studio")).clear();
  session_ = new Session;
  host_ = new QWidget;
  panels_ = createPanels(*session_, host_);
  auto* layout = new QVBoxLayout(host_);
  for (const auto& p : panels_) layout->addWidget(p.widget);
  host_->show();
  host_->activateWindow();
  QVERIFY(QTest::qWaitForWindowActive(host_));
  panel_ = host_->findChild<ProgramPanel*>(QStringLiteral("panel.program"));
  QVERIFY(panel_);
  // No modal dialogs: the panel asks these functions instead.
  panel_->setDialogs({[this] { return open_path_; }, [this](const QString&) { return save_path_; },
                      [this] {
                        ++prompts_;
                        return unsaved_choice_;
                      }});

  SessionTarget target;
  target.kind = SessionTarget::Kind::kSimulator;
  target.type = xmate::XMATE7_PRO;
  target.lockstep = true;
  QSignalSpy failed(session_, &Session::openFailed);
  session_->open(target);
  QTRY_VERIFY_WITH_TIMEOUT(session_->isOpen() || failed.count() > 0, kWaitMs);
  QVERIFY2(session_->isOpen(), failed.isEmpty() ? "" : qPrintable(failed.first().first().toString()));
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().has_state, kWaitMs);
  click(QStringLiteral("power.on"));
  QTRY_VERIFY_WITH_TIMEOUT(find<Lamp>(QStringLiteral("power.lamp"))->isOn(), kWaitMs);
}

void TestProgramGui::cleanupTestCase() {
  delete host_;
  delete session_;
}

void TestProgramGui::panelAndNames() {
  bool docked_left = false;
  for (const auto& p : panels_)
    if (p.id == QStringLiteral("panel.program")) docked_left = p.area == Qt::LeftDockWidgetArea && p.title == "Program";
  QVERIFY(docked_left);
  const char* names[] = {"program.record", "program.recordType", "program.recordSpeed", "program.diTrigger",
                         "program.recordState", "program.list", "program.run", "program.pause", "program.resume",
                         "program.stop", "program.step", "program.speed", "program.progress", "program.save",
                         "program.saveAs", "program.open", "program.new", "program.goto", "program.touchup", "program.touchupVia",
                         "program.delete", "program.up", "program.down", "program.duplicate", "program.logicType",
                         "program.logicSignal", "program.logicValue", "program.logicMs", "program.addLogic", "program.applyLogic",
                         "program.problems", "program.file", "program.runState", "program.status"};
  for (const char* name : names) QVERIFY2(host_->findChild<QWidget*>(QLatin1String(name)), name);
  auto* speed = find<QSlider>(QStringLiteral("program.speed"));
  QCOMPARE(speed->minimum(), 10);
  QCOMPARE(speed->maximum(), 100);
}

void TestProgramGui::teachSaveReopenReplay() {
  // Hand guiding through the Drag panel: Cartesian, translation only.
  auto* type = find<QComboBox>(QStringLiteral("drag.type"));
  find<QComboBox>(QStringLiteral("drag.space"))->setCurrentIndex(1);
  type->setCurrentIndex(type->findData(1));
  click(QStringLiteral("drag.start"));
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().sim.dragging, kWaitMs);

  // J: the button.
  dragBy({0, 25, 0}, 0.05);
  const RCI::robot::RobotState wp1 = state();
  setRecordType(0);
  click(QStringLiteral("program.record"));
  QCOMPARE(rows(), 1);
  // L: F9 anywhere in the window.
  dragBy({0, 0, -25}, 0.05);
  const RCI::robot::RobotState wp2 = state();
  setRecordType(1);
  QTest::keyClick(host_, Qt::Key_F9);
  QCOMPARE(rows(), 2);
  // C: via, then target.
  dragBy({25, 0, 0}, 0.04);
  setRecordType(2);
  click(QStringLiteral("program.record"));
  QCOMPARE(rows(), 2);
  QVERIFY2(text(QStringLiteral("program.recordState")).contains(QStringLiteral("via")),
           qPrintable(text(QStringLiteral("program.recordState"))));
  dragBy({0, -25, 0}, 0.04);
  const RCI::robot::RobotState wp4 = state();
  click(QStringLiteral("program.record"));
  QCOMPARE(rows(), 3);
  QCOMPARE(cell(0, 1), QStringLiteral("MOVEJ"));
  QCOMPARE(cell(1, 1), QStringLiteral("MOVEL"));
  QCOMPARE(cell(2, 1), QStringLiteral("MOVEC"));
  QCOMPARE(cell(0, 2), QStringLiteral("P1"));
  QCOMPARE(cell(2, 2), QStringLiteral("P3"));
  QVERIFY(panel_->isModified());
  QVERIFY(text(QStringLiteral("program.file")).contains(QStringLiteral("modified")));
  // The 3D view gets the waypoints (J, L, via, target) and a planned path.
  QCOMPARE(int(session_->programOverlay().waypoints.size()), 4);
  // The path comes from the pre-flight trace, which runs on a worker thread.
  QTRY_VERIFY_WITH_TIMEOUT(!panel_->isTracing() && !session_->programOverlay().path.empty(), kWaitMs);
  QCOMPARE(session_->programOverlay().selected, 3);
  QCOMPARE(find<QListWidget>(QStringLiteral("program.problems"))->count(), 0);
  click(QStringLiteral("drag.stop"));
  QTRY_VERIFY_WITH_TIMEOUT(!session_->live().sim.dragging, kWaitMs);

  // Save (no file yet: Save asks for a name), start over, reopen.
  save_path_ = dir_.filePath(QStringLiteral("taught.json"));
  click(QStringLiteral("program.save"));
  QVERIFY2(QFileInfo::exists(save_path_), qPrintable(text(QStringLiteral("program.status"))));
  QVERIFY(!panel_->isModified());
  QCOMPARE(text(QStringLiteral("program.file")), QStringLiteral("taught.json"));
  click(QStringLiteral("program.new"));
  QCOMPARE(prompts_, 0);  // nothing unsaved
  QCOMPARE(rows(), 0);
  openThroughButton(save_path_);
  QCOMPARE(rows(), 3);
  QCOMPARE(panel_->program().instructions[2].type, InstructionType::kMoveC);

  // Go to the L waypoint first, then run the whole program from there.
  selectRow(1);
  click(QStringLiteral("program.goto"));
  QTRY_VERIFY_WITH_TIMEOUT(panel_->isRunning() || panel_->lastReport().outcome != RunState::kIdle, kWaitMs);
  waitRunEnd();
  QVERIFY2(panel_->lastReport().outcome == RunState::kFinished, panel_->lastReport().message.c_str());
  QVERIFY(distance(panel_->lastReport().instructions[0].pose, wp2.toolTobase_pos_m) < kPositionTolerance);

  click(QStringLiteral("program.run"));
  QVERIFY(panel_->isRunning());
  waitRunEnd();
  const xmate::teach::RunReport& report = panel_->lastReport();
  QVERIFY2(report.outcome == RunState::kFinished, report.message.c_str());
  QCOMPARE(int(report.instructions.size()), 3);
  QVERIFY(maxAbsDiff(report.instructions[0].q, wp1.q) < kJointTolerance);
  QVERIFY(distance(report.instructions[0].pose, wp1.toolTobase_pos_m) < kPositionTolerance);
  QVERIFY(distance(report.instructions[1].pose, wp2.toolTobase_pos_m) < kPositionTolerance);
  QVERIFY(distance(report.instructions[2].pose, wp4.toolTobase_pos_m) < kPositionTolerance);
  QVERIFY(distance(state().toolTobase_pos_m, wp4.toolTobase_pos_m) < kPositionTolerance);
  QVERIFY(!anyError(state()));
  QCOMPARE(find<QProgressBar>(QStringLiteral("program.progress"))->value(), 1000);
  QCOMPARE(text(QStringLiteral("program.runState")), QStringLiteral("finished"));
}

void TestProgramGui::pauseAndResumeMidMove() {
  // One long joint-1 move, opened from a file; paused once it is under way, then resumed.
  xmate::teach::Program program;
  std::array<double, 7> goal = state().q;
  goal[0] += goal[0] > 0 ? -1.5 : 1.5;
  program.instructions.push_back(xmate::teach::moveJ(jointTarget(goal), 0.1, "far"));
  openThroughButton(writeProgram(QStringLiteral("long.json"), program));
  auto* progress = find<QProgressBar>(QStringLiteral("program.progress"));
  // At a 10 % override the move lasts long enough (in simulated time) for the display ticks to
  // catch it under way however fast the lock-step simulator runs; full speed again after resume.
  auto* override = find<QSlider>(QStringLiteral("program.speed"));
  override->setValue(10);
  QCOMPARE(text(QStringLiteral("program.speedLabel")), QStringLiteral("10 %"));
  click(QStringLiteral("program.run"));
  QTRY_VERIFY_WITH_TIMEOUT(progress->value() > 20 || !panel_->isRunning(), kWaitMs);
  QVERIFY2(panel_->isRunning(), "the move ended before it could be paused");
  QVERIFY2(progress->text().startsWith(QStringLiteral("Instruction 1 of 1")), qPrintable(progress->text()));
  click(QStringLiteral("program.pause"));
  QTRY_COMPARE_WITH_TIMEOUT(text(QStringLiteral("program.runState")), QStringLiteral("paused"), kWaitMs);
  QTRY_VERIFY_WITH_TIMEOUT(atRest(), kWaitMs);
  const int paused_at = progress->value();
  QVERIFY(paused_at < 1000);
  const auto q_paused = state().q;
  QTest::qWait(300);
  QVERIFY(maxAbsDiff(state().q, q_paused) < 1e-6);  // holds while paused
  QVERIFY(find<QPushButton>(QStringLiteral("program.resume"))->isEnabled());
  click(QStringLiteral("program.resume"));
  override->setValue(100);
  waitRunEnd();
  const xmate::teach::RunReport& report = panel_->lastReport();
  QVERIFY2(report.outcome == RunState::kFinished, report.message.c_str());
  QVERIFY(maxAbsDiff(report.instructions[0].q, goal) < kJointTolerance);
  QVERIFY(!anyError(state()));
}

void TestProgramGui::unreachableTargetRefusedBeforeMoving() {
  // Instruction 2 asks for a TCP 3 m away.
  xmate::teach::Program program;
  const xmate::teach::Target here = xmate::teach::targetFromState(state(), xmate::XMATE7_PRO);
  xmate::teach::Target far = here;
  far.has_q = false;
  far.pose[3] = 3.0;
  program.instructions.push_back(xmate::teach::moveJ(here, 0.3, "here"));
  program.instructions.push_back(xmate::teach::moveL(far, 0.3, "far"));
  openThroughButton(writeProgram(QStringLiteral("unreachable.json"), program));
  QTRY_VERIFY_WITH_TIMEOUT(atRest(), kWaitMs);
  const auto q_before = state().q;
  click(QStringLiteral("program.run"));
  waitRunEnd();
  QCOMPARE(panel_->lastReport().outcome, RunState::kRefused);
  auto* problems = find<QListWidget>(QStringLiteral("program.problems"));
  QVERIFY(problems->count() >= 1);
  QVERIFY2(problems->item(0)->text().startsWith(QStringLiteral("instruction 2")), qPrintable(problems->item(0)->text()));
  QVERIFY(text(QStringLiteral("program.status")).contains(QStringLiteral("refused")));
  // Nothing was commanded (the arm may still settle by far less than the reach tolerance).
  for (const auto& i : panel_->lastReport().instructions)
    QCOMPARE(i.status, xmate::teach::InstructionStatus::kNotRun);
  const double moved = maxAbsDiff(state().q, q_before);
  QVERIFY2(moved < 1e-5, qPrintable(QStringLiteral("the arm moved %1 rad although the run was refused").arg(moved)));
}

void TestProgramGui::stepThenStop() {
  // Two short joint moves: Step runs the first and pauses; Stop ends the run before the second.
  xmate::teach::Program program;
  std::array<double, 7> q = state().q;
  q[3] += 0.1;
  program.instructions.push_back(xmate::teach::moveJ(jointTarget(q), 0.3, "a"));
  q[3] -= 0.2;
  program.instructions.push_back(xmate::teach::moveJ(jointTarget(q), 0.3, "b"));
  openThroughButton(writeProgram(QStringLiteral("two.json"), program));
  click(QStringLiteral("program.step"));
  QTRY_COMPARE_WITH_TIMEOUT(text(QStringLiteral("program.runState")), QStringLiteral("paused"), kWaitMs);
  QVERIFY(panel_->isRunning());
  QVERIFY(find<QPushButton>(QStringLiteral("program.step"))->isEnabled());
  click(QStringLiteral("program.stop"));
  waitRunEnd();
  const xmate::teach::RunReport& report = panel_->lastReport();
  QCOMPARE(report.outcome, RunState::kStopped);
  QCOMPARE(report.instructions[0].status, xmate::teach::InstructionStatus::kDone);
  QCOMPARE(report.instructions[1].status, xmate::teach::InstructionStatus::kNotRun);
  QVERIFY(!anyError(state()));
}

void TestProgramGui::diTriggerRecords() {
  click(QStringLiteral("program.new"));
  QCOMPARE(rows(), 0);
  auto* trigger = find<QComboBox>(QStringLiteral("program.diTrigger"));
  trigger->setCurrentIndex(trigger->findText(QStringLiteral("DI0_1")));
  setRecordType(0);
  session_->simulator()->setDigitalInput(1, true);  // rising edge: one waypoint
  QTRY_COMPARE_WITH_TIMEOUT(rows(), 1, kWaitMs);
  session_->simulator()->setDigitalInput(1, false);
  QTRY_VERIFY_WITH_TIMEOUT(!session_->live().digital_in[1], kWaitMs);
  QCOMPARE(rows(), 1);
  session_->simulator()->setDigitalInput(1, true);
  QTRY_COMPARE_WITH_TIMEOUT(rows(), 2, kWaitMs);
  session_->simulator()->setDigitalInput(1, false);
  trigger->setCurrentIndex(0);
  unsaved_choice_ = ProgramPanel::UnsavedChoice::kDiscard;
}

void TestProgramGui::listEditing() {
  openThroughButton(save_path_);  // the taught J, L, C
  auto* model = find<QTableView>(QStringLiteral("program.list"))->model();
  // Reorder with the buttons.
  selectRow(0);
  QVERIFY(!find<QPushButton>(QStringLiteral("program.up"))->isEnabled());
  click(QStringLiteral("program.down"));
  QCOMPARE(cell(0, 2), QStringLiteral("P2"));
  QCOMPARE(cell(1, 2), QStringLiteral("P1"));
  click(QStringLiteral("program.up"));
  QCOMPARE(cell(0, 2), QStringLiteral("P1"));
  QVERIFY(panel_->isModified());
  // Duplicate and delete.
  click(QStringLiteral("program.duplicate"));
  QCOMPARE(rows(), 4);
  QCOMPARE(cell(1, 1), QStringLiteral("MOVEJ"));
  QCOMPARE(cell(1, 2), QStringLiteral("P4"));
  click(QStringLiteral("program.delete"));
  QCOMPARE(rows(), 3);
  QCOMPARE(cell(1, 2), QStringLiteral("P2"));
  // Touch-up of a MOVEC's via point (offered for MOVEC only).
  selectRow(0);
  QVERIFY(!find<QPushButton>(QStringLiteral("program.touchupVia"))->isEnabled());
  selectRow(2);
  const auto target_before = panel_->program().instructions[2].target.q;
  click(QStringLiteral("program.touchupVia"));
  QVERIFY(maxAbsDiff(panel_->program().instructions[2].via.q, state().q) < 1e-12);
  QCOMPARE(panel_->program().instructions[2].target.q, target_before);
  // Type and speed, as the editors would set them.
  QVERIFY(model->setData(model->index(0, 1), QStringLiteral("MOVEL")));
  QCOMPARE(panel_->program().instructions[0].type, InstructionType::kMoveL);
  QVERIFY(!model->setData(model->index(0, 1), QStringLiteral("MOVEC")));  // no via point
  QVERIFY(model->setData(model->index(2, 1), QStringLiteral("MOVEJ")));    // C drops its via
  QCOMPARE(panel_->program().instructions[2].type, InstructionType::kMoveJ);
  QVERIFY(model->setData(model->index(1, 3), 55.0));
  QCOMPARE(panel_->program().instructions[1].speed, 0.55);
  QVERIFY(!model->setData(model->index(1, 3), 150.0));
  // Touch-up: the selected target becomes the current pose.
  selectRow(1);
  click(QStringLiteral("program.touchup"));
  QVERIFY(maxAbsDiff(panel_->program().instructions[1].target.q, state().q) < 1e-12);
  // Logic instructions.
  auto* logic = find<QComboBox>(QStringLiteral("program.logicType"));
  logic->setCurrentIndex(logic->findText(QStringLiteral("WAIT_DI")));
  find<QSpinBox>(QStringLiteral("program.logicMs"))->setValue(0);
  click(QStringLiteral("program.addLogic"));  // a timeout of 0 is refused
  QCOMPARE(rows(), 3);
  QVERIFY(text(QStringLiteral("program.status")).contains(QStringLiteral("timeout_ms")));
  find<QSpinBox>(QStringLiteral("program.logicMs"))->setValue(2000);
  click(QStringLiteral("program.addLogic"));
  QCOMPARE(rows(), 4);
  QCOMPARE(cell(2, 1), QStringLiteral("WAIT_DI"));
  logic->setCurrentIndex(logic->findText(QStringLiteral("SET_DO")));
  click(QStringLiteral("program.addLogic"));
  QCOMPARE(cell(3, 1), QStringLiteral("SET_DO"));
  QCOMPARE(rows(), 5);
  // Editing a logic instruction in place: selecting it loads the editor, Apply changes it.
  auto* ms = find<QSpinBox>(QStringLiteral("program.logicMs"));
  auto* signal = find<QComboBox>(QStringLiteral("program.logicSignal"));
  selectRow(0);
  QVERIFY(!find<QPushButton>(QStringLiteral("program.applyLogic"))->isEnabled());
  selectRow(2);
  QCOMPARE(logic->currentText(), QStringLiteral("WAIT_DI"));
  QCOMPARE(ms->value(), 2000);
  ms->setValue(0);
  click(QStringLiteral("program.applyLogic"));  // refused: the instruction keeps its timeout
  QCOMPARE(panel_->program().instructions[2].timeout_ms, 2000);
  ms->setValue(1500);
  signal->setCurrentIndex(signal->findText(QStringLiteral("DI1_0")));
  find<QCheckBox>(QStringLiteral("program.logicValue"))->setChecked(false);
  click(QStringLiteral("program.applyLogic"));
  QCOMPARE(panel_->program().instructions[2].type, InstructionType::kWaitDi);
  QCOMPARE(panel_->program().instructions[2].timeout_ms, 1500);
  QCOMPARE(panel_->program().instructions[2].signal, xmate::teach::diIndex(xmate::model::RobotFamily::kXmate, "DI1_0"));
  QVERIFY(!panel_->program().instructions[2].value);
  QCOMPARE(rows(), 5);
  // The type can change too: WAIT_DI becomes a WAIT of 250 ms.
  logic->setCurrentIndex(logic->findText(QStringLiteral("WAIT")));
  ms->setValue(250);
  click(QStringLiteral("program.applyLogic"));
  QCOMPARE(panel_->program().instructions[2].type, InstructionType::kWait);
  QCOMPARE(panel_->program().instructions[2].ms, 250);
}

void TestProgramGui::unsavedChangesPrompt() {
  QVERIFY(panel_->isModified());  // from listEditing
  const int rows_before = rows();
  prompts_ = 0;
  unsaved_choice_ = ProgramPanel::UnsavedChoice::kCancel;
  click(QStringLiteral("program.new"));
  QCOMPARE(prompts_, 1);
  QCOMPARE(rows(), rows_before);  // cancelled: nothing lost
  QVERIFY(!panel_->maybeSaveProgram());
  unsaved_choice_ = ProgramPanel::UnsavedChoice::kDiscard;
  QVERIFY(panel_->maybeSaveProgram());
  // Save: written to the program's own file, then nothing is unsaved any more.
  unsaved_choice_ = ProgramPanel::UnsavedChoice::kSave;
  QVERIFY(panel_->maybeSaveProgram());
  QVERIFY(!panel_->isModified());
  QCOMPARE(int(xmate::teach::loadProgram(save_path_.toStdString()).instructions.size()), rows_before);
  prompts_ = 0;
  QVERIFY(panel_->maybeSaveProgram());
  QCOMPARE(prompts_, 0);
  // A bad file is refused with a message naming it; the program shown stays.
  const QString bad = dir_.filePath(QStringLiteral("bad.json"));
  QFile file(bad);
  QVERIFY(file.open(QIODevice::WriteOnly));
  file.write("{ \"format\": \"rci-program\", \"version\": 1, \"robot\": \"xmate7_pro\", \"instructions\": [ { \"type\": \"MOVEJ\" } ] }");
  file.close();
  open_path_ = bad;
  click(QStringLiteral("program.open"));
  QCOMPARE(rows(), rows_before);
  QVERIFY2(text(QStringLiteral("program.status")).contains(QStringLiteral("instruction 1")),
           qPrintable(text(QStringLiteral("program.status"))));
}

// A KUKA program opened at an xMate: no preview of it on this arm, and one problem saying which
// robot it was taught for -- not what tracing its joints on this arm would say.
void TestProgramGui::programOfAnotherModelShowsOneProblem() {
  unsaved_choice_ = ProgramPanel::UnsavedChoice::kDiscard;
  xmate::teach::Program kuka;
  kuka.robot = xmate::model::findRobotSpec("kr6_r900_sixx");
  kuka.instructions.push_back(xmate::teach::moveJ(jointTarget({0, -1.2, 1.4, 0, 1.2, 0, 0}), 0.3, "K1"));
  openThroughButton(writeProgram(QStringLiteral("kuka.json"), kuka));
  QCOMPARE(rows(), 1);
  QTRY_VERIFY_WITH_TIMEOUT(find<QListWidget>(QStringLiteral("program.problems"))->count() == 1, kWaitMs);
  const QString problem = find<QListWidget>(QStringLiteral("program.problems"))->item(0)->text();
  QVERIFY2(problem.contains(QStringLiteral("taught for the KR 6 R900 sixx")) &&
               problem.contains(QStringLiteral("but the robot is the xMate")),
           qPrintable(problem));
  QVERIFY(session_->programOverlay().waypoints.empty());
  QVERIFY(session_->programOverlay().path.empty());
  click(QStringLiteral("program.new"));
  QTRY_COMPARE_WITH_TIMEOUT(find<QListWidget>(QStringLiteral("program.problems"))->count(), 0, kWaitMs);
}

// The first pose taught records the robot's tool in the program; with another tool on the robot,
// recording is refused (saying what to do in this window) and the pre-flight reports the program's
// poses; with the program's tool back, teaching goes on.
void TestProgramGui::anotherToolRefusesTeaching() {
  unsaved_choice_ = ProgramPanel::UnsavedChoice::kDiscard;
  click(QStringLiteral("program.new"));
  QCOMPARE(rows(), 0);
  QVERIFY(!panel_->program().has_tool);
  setRecordType(1);  // MOVEL: its pose depends on the tool
  click(QStringLiteral("program.record"));
  QCOMPARE(rows(), 1);
  QVERIFY(panel_->program().has_tool);
  QCOMPARE(panel_->program().tool, session_->robot()->toolFrame());

  auto setToolZ = [this](double z) {
    find<QDoubleSpinBox>(QStringLiteral("tool.z"))->setValue(z);
    click(QStringLiteral("tool.apply"));
    QTRY_COMPARE_WITH_TIMEOUT(session_->robot()->toolFrame()[11], z, kWaitMs);
  };
  setToolZ(0.1);
  QTRY_VERIFY_WITH_TIMEOUT(find<QListWidget>(QStringLiteral("program.problems"))->count() == 1, kWaitMs);
  const QString problem = find<QListWidget>(QStringLiteral("program.problems"))->item(0)->text();
  QVERIFY2(problem.contains(QStringLiteral("100.0 mm")) && problem.contains(QStringLiteral("Tool & payload panel")),
           qPrintable(problem));
  click(QStringLiteral("program.record"));
  QCOMPARE(rows(), 1);  // refused
  const QString status = text(QStringLiteral("program.status"));
  QVERIFY2(status.startsWith(QStringLiteral("Record: the robot's tool point is 100.0 mm")) &&
               status.contains(QStringLiteral("press New in the Program panel")),
           qPrintable(status));

  setToolZ(0);
  QTRY_VERIFY_WITH_TIMEOUT(find<QListWidget>(QStringLiteral("program.problems"))->count() == 0, kWaitMs);
  click(QStringLiteral("program.record"));
  QCOMPARE(rows(), 2);
}

QTEST_MAIN(TestProgramGui)
#include "test_program_gui.moc"
