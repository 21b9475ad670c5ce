// SPDX-License-Identifier: Apache-2.0
// Program panel: teach by recording waypoints (button, F9, DI trigger) as
// MOVEJ / MOVEL / MOVEC or a demonstrated path as PATH, edit the instruction list, go to a waypoint, run / pause / resume / step /
// stop the program with the teach executor (teach/executor.h) through Session::runArmMotion, open and
// save program files, and show the waypoints and the planned path in the 3D view (programOverlay).
#pragma once

#include <QFutureWatcher>
#include <QString>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "panels/panel_base.h"
#include "session/session.h"
#include "teach/executor.h"
#include "teach/path.h"
#include "teach/preflight.h"
#include "teach/program.h"

class QAction;
class QCheckBox;
class QComboBox;
class QLabel;
class QListWidget;
class QProgressBar;
class QPushButton;
class QSlider;
class QSpinBox;
class QTableView;

namespace rci::ui {

class ProgramModel;

class ProgramPanel : public PanelBase {
  Q_OBJECT
 public:
  ProgramPanel(Session& session, QWidget* parent);
  ~ProgramPanel() override;

  // The answers the panel needs from the user, as functions so tests (and scripted use) can avoid
  // modal dialogs. The defaults show QFileDialog / QMessageBox.
  enum class UnsavedChoice { kSave, kDiscard, kCancel };
  struct Dialogs {
    std::function<QString()> open_path;            // "" = cancelled
    std::function<QString(const QString&)> save_path;  // argument: suggested path; "" = cancelled
    std::function<UnsavedChoice()> unsaved;
  };
  void setDialogs(Dialogs dialogs);

  // For the window's close (and Open / New): if the program has unsaved changes, asks whether to
  // save them. True when it is fine to go on (saved, discarded or nothing to save); false when the
  // user cancelled or the save failed.
  bool maybeSaveProgram();

  // File operations without dialogs (the buttons use them after asking). Errors go to the status line.
  bool openFile(const QString& path);
  bool saveFile(const QString& path);
  void newProgram();

  bool isModified() const { return modified_; }
  const QString& filePath() const { return path_; }
  const xmate::teach::Program& program() const;
  // The report of the last run or go-to (outcome kIdle before the first).
  const xmate::teach::RunReport& lastReport() const { return last_report_; }
  bool isRunning() const { return running_; }
  // True between the start and the stop of a path recording (Move type PATH). GUI thread.
  bool isRecordingPath() const { return path_recorder_ != nullptr; }
  // True while the pre-flight behind the planned path and the problem list runs on its worker.
  bool isTracing() const;

 protected:
  void refresh(const LiveState& live) override;
  void sessionOpened() override;
  void sessionClosed() override;
  void commandDone(const QString& action, bool ok, const QString& message) override;
  bool event(QEvent* event) override;

 private:
  // Layout (program_panel.cpp): the file row and the Run bar stay in view; Teach and the
  // instruction list scroll below them (the window does not wrap this panel in a scroll area).
  QWidget* buildFileRow();
  QWidget* buildTeachGroup();
  QWidget* buildListGroup();
  QLayout* buildEditRows(QWidget* group);
  QLayout* buildLogicEditor(QWidget* group);
  void sizeListColumns();
  QWidget* buildRunGroup();
  QWidget* buildEditorArea();
  void letBodyFill();
  void attachShortcut();

  // Teaching and editing (program_panel.cpp).
  void record();
  // Checks shared by every recording: a robot state, no run, a program for this model (an empty
  // one switches to it). False (and the reason shown) when recording may not start.
  bool mayRecord();
  // Before a pose is taught: the first one records the robot's tool and load in the program; later
  // ones need the robot's TCP to match it. False (and the reason shown) when it does not.
  bool teachWithRobotTool(const QString& action);
  // teach::adoptTool with the robot's tool and load (an xMate's; identity and none on a KUKA) and
  // its measured TCP now: "" when `adopted` may be recorded into (its tool adopted if it had none).
  std::string adoptRobotTool(xmate::teach::Program& adopted) const;
  void cancelPendingVia();
  // Shows text in the status line and writes it to the event log (Messages dock), the file's full
  // path as the detail: what was taught, opened and saved is on record.
  void note(const QString& text, bool error, const QString& path = QString());
  void resetDiTrigger();
  void addLogic();
  void applyLogic();
  // The logic editor's values as an instruction; false (with the reason shown) if they are refused.
  bool logicFromEditor(size_t row, xmate::teach::Instruction& in);
  void showSelectedLogic();  // loads a selected WAIT / SET_DO / WAIT_DI into the logic editor
  void logicTypeChanged();
  void touchUp(bool via);  // the selected move's target, or a MOVEC's via point
  void moveSelected(int delta);
  int selectedRow() const;
  void selectRow(int row);
  void programEdited();
  void updateTitle();
  void updateButtons();
  bool haveLiveState() const;
  // The arm's pose now as a waypoint (joints, TCP; an xMate's arm angle too).
  xmate::teach::Target livePose() const;
  // The DI-trigger list: the connected arm's inputs (the xMate's when none is connected).
  void fillDiTrigger();
  // The Record button's text for the move type and whether a path is being recorded.
  void updateRecordButton();

  // Recording a demonstrated path (program_panel_path.cpp).
  void startPathRecording();
  // Ends the recording: the path becomes a PATH instruction after the selection (or the operator is
  // told why not); `why` is said in the message when the recording ended without the operator.
  void stopPathRecording(const QString& why = QString());
  // Every sample of the arm's stream while recording (Session::armSamplesArrived).
  void takeArmSamples(const xmate::arm::ArmSample* samples, int count);
  void showRecordingState();
  // While a path is being recorded, says so for `action` ("New", "Run", ...) and returns true.
  bool refusedWhileRecording(const QString& action);
  // Cycles lost so far: the larger of the recorder's gaps and what the arm's sample ring dropped since the start.
  uint64_t lostSinceStart() const;
  // The tool a PATH records in a program that has none yet (adoptTool); never refuses.
  void adoptToolForPath();
  // The last run's result of each instruction, in words, for the list's tooltips and the event log
  // (program_panel_path.cpp: a PATH's deviation and slow-down).
  QStringList instructionResults(const xmate::teach::RunReport& report) const;
  // After a finished run: each PATH's result in the event log, and the largest deviation and
  // slow-down of them in the status line.
  void reportPaths(const xmate::teach::RunReport& report);

  // Files (program_panel_files.cpp).
  void openClicked();
  bool saveClicked();
  bool saveAsClicked();
  void newClicked();

  // Running (program_panel_run.cpp).
  void runClicked();
  void stepClicked();
  void pauseClicked();
  void resumeClicked();
  void stopClicked();
  void gotoClicked();
  void startRun(const xmate::teach::Program& program, bool single_step, const QString& action);
  xmate::teach::ExecutorOptions executorOptions() const;
  xmate::teach::TraceOptions traceOptions() const;
  void runFinished(const QString& label, bool ok, const QString& message);
  void showReport(const xmate::teach::RunReport& report);
  // The pre-flight's problems (red) and what it announces (a PATH's move to its start).
  void showProblems(const std::vector<xmate::teach::Problem>& problems,
                    const std::vector<xmate::teach::Problem>& notices = {});
  // The 3D view: the planned path of the last trace, then the path being recorded.
  void publishOverlay();
  void updateProgress();
  void resetRunDisplay();  // after New / Open: no run of this program yet
  // The overlay's waypoints at once; its planned path and the pre-flight problems from a trace on a
  // worker thread (it plans every motion, too slow for the GUI thread at every edit). One trace at a
  // time: a request while one runs traces the newest program and pose after it.
  void updateOverlay();
  // requireRobot's refusal when the program was taught for another model than the robot's (or the
  // chosen target's), else "".
  std::string otherModelProblem() const;
  void startTrace();
  void traceFinished();
  // Each tick: traces again when the arm rests away from where the last trace started, or its
  // measured TCP moved there (another tool set).
  void followRobot(const LiveState& live);
  std::array<double, 7> currentQ() const;

  ProgramModel* model_ = nullptr;
  ProgramOverlay overlay_;  // what the 3D view shows of the program
  std::vector<std::array<double, 3>> planned_path_;  // the last trace's TCP path (m)
  QFutureWatcher<xmate::teach::ProgramTrace>* trace_watcher_ = nullptr;
  bool trace_again_ = false;
  // Where the last trace started (joints, measured TCP): the trace follows the robot once it rests
  // somewhere else or its tool changes (followRobot).
  std::array<double, 7> traced_q_{};
  std::array<double, 16> traced_tcp_{};
  std::array<double, 7> followed_q_{};  // the joints at the previous display tick
  QString path_;
  bool modified_ = false;
  Dialogs dialogs_;

  // Teach
  QComboBox* record_type_ = nullptr;
  QSpinBox* record_speed_ = nullptr;
  QPushButton* record_ = nullptr;
  QComboBox* di_trigger_ = nullptr;
  QLabel* record_state_ = nullptr;
  QAction* record_action_ = nullptr;
  QWidget* shortcut_host_ = nullptr;
  bool have_via_ = false;
  xmate::teach::Target via_;
  bool last_di_ = false;
  bool di_known_ = false;

  // Path recording: the recorder while recording (null otherwise), the arm's drop counter when it
  // started (and last seen), the TCP trace shown in the 3D view (one point per kTracePeriod).
  std::unique_ptr<xmate::teach::PathRecorder> path_recorder_;
  uint64_t dropped_at_start_ = 0;
  uint64_t dropped_now_ = 0;
  std::vector<std::array<double, 3>> recording_trace_;
  size_t trace_every_ = 1;     // samples per trace point
  size_t trace_counter_ = 0;
  bool path_has_tool_ = false; // the tool adopted when the recording started (adoptTool)
  std::array<double, 16> path_tool_{};
  xmate::teach::Payload path_load_;

  // List
  QLabel* file_label_ = nullptr;
  QTableView* list_ = nullptr;
  QComboBox* logic_type_ = nullptr;
  QComboBox* logic_signal_ = nullptr;
  QCheckBox* logic_value_ = nullptr;
  QSpinBox* logic_ms_ = nullptr;
  QLabel* logic_ms_label_ = nullptr;
  QPushButton* apply_logic_ = nullptr;
  QPushButton* touch_via_ = nullptr;
  QList<QPushButton*> edit_buttons_;   // need a selection, disabled while running
  QList<QPushButton*> live_buttons_;   // need a selection and the robot's state (touch-up, go to)
  QPushButton* touch_ = nullptr;       // Touch up: a move to a taught target only (not a PATH)

  // Run
  QPushButton* run_ = nullptr;
  QPushButton* step_ = nullptr;
  QPushButton* pause_ = nullptr;
  QPushButton* resume_ = nullptr;
  QPushButton* stop_ = nullptr;
  QSlider* speed_ = nullptr;
  QLabel* speed_label_ = nullptr;
  QProgressBar* progress_ = nullptr;
  QLabel* run_state_ = nullptr;
  QListWidget* problems_ = nullptr;
  QLabel* problems_label_ = nullptr;

  // The executor and the result of its run are shared with the motion worker's job, so they outlive
  // the panel if it is destroyed mid-run.
  struct RunSlot {
    xmate::teach::Executor executor;
    xmate::teach::RunReport report;
  };
  std::shared_ptr<RunSlot> run_slot_ = std::make_shared<RunSlot>();
  QString run_label_;      // the runArmMotion label of the running job ("" when none)
  bool running_ = false;
  bool goto_run_ = false;  // the running job is a go-to (its progress is not the program's)
  xmate::teach::RunReport last_report_;
};

// The window's close hook: asks the Program panel under root (if any) to save unsaved changes.
// False when the user cancelled (the window should stay open). The window may declare the same
// function in window/parts.h to avoid including this header.
bool maybeSaveProgram(QWidget* root);

}  // namespace rci::ui
