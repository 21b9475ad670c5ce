// SPDX-License-Identifier: Apache-2.0
// test_path_gui: teach by demonstration through the Program panel's widgets against the
// session's embedded lock-step xMate simulator -- drag the arm with a varying external force while
// recording a PATH (button, F9, DI trigger), check what the table, the 3D overlay and the status say,
// replay it at 100 %, 50 % and 10 % of the demonstrated pace, refuse a recording where nothing moved,
// and keep what was recorded when the connection closes mid-recording; then the same recording and
// replay on the built-in KUKA simulator, guided through the Hand guiding panel.
#include <QComboBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QVBoxLayout>

#include <cmath>

#include "gui_test_support.h"
#include "panels/lamp.h"
#include "panels/program_model.h"
#include "panels/program_panel.h"
#include "session/session.h"
#include "guide/admittance.h"
#include "sim/krc_server.h"
#include "teach/program.h"
#include "window/parts.h"
#include "window_driver.h"

using namespace rci::ui;
using xmate::teach::InstructionType;
using xmate::teach::RunState;

namespace {

constexpr int kWaitMs = 60000;            // a safety net for a loaded machine, not a timing claim
constexpr int kRecordPath = 3;            // the Move type combo's data for PATH
constexpr double kPathTolerance = 1e-3;   // rad: the target for the replayed joints

}  // namespace

class TestPathGui : public QObject {
  Q_OBJECT

 private:
  rci::ui::test::WindowDriver driver() { return rci::ui::test::WindowDriver(host_); }
  template <class T>
  T* find(const QString& name) {
    return driver().find<T>(name);
  }
  void click(const QString& name) { QVERIFY2(driver().click(name), qPrintable(name)); }
  QString text(const QString& name) { return driver().text(name); }
  QAbstractItemModel* model() { return find<QTableView>(QStringLiteral("program.list"))->model(); }
  int rows() { return model()->rowCount(); }
  QString cell(int row, int column, int role = Qt::DisplayRole) {
    return model()->data(model()->index(row, column), role).toString();
  }
  uint64_t cycle() { return session_->live().arm.sample.cycle; }
  // The xMate reports joint speeds; over RSI the joints must not have changed since the last look.
  bool atRest() {
    if (session_->target().isKuka()) {
      const std::array<double, 7> q = session_->live().arm.sample.q;
      double step = 0;
      for (size_t j = 0; j < 7; ++j) step = std::max(step, std::abs(q[j] - rest_q_[j]));
      rest_q_ = q;
      return step < 1e-5;
    }
    double speed = 0;
    for (double v : session_->live().state.dq_m) speed = std::max(speed, std::abs(v));
    return speed < 1e-5;
  }
  // Simulated time passes (cycles of the controller) while the window keeps processing events.
  void waitCycles(uint64_t cycles) {
    const uint64_t start = cycle();
    QTRY_VERIFY_WITH_TIMEOUT(cycle() >= start + cycles, kWaitMs);
  }
  void startDrag() {
    find<QComboBox>(QStringLiteral("drag.space"))->setCurrentIndex(1);  // Cartesian
    QVERIFY(driver().choose(QStringLiteral("drag.type"), 1));           // translation only
    click(QStringLiteral("drag.start"));
    QTRY_VERIFY_WITH_TIMEOUT(session_->live().sim.dragging, kWaitMs);
  }
  void stopDrag() {
    click(QStringLiteral("drag.stop"));
    QTRY_VERIFY_WITH_TIMEOUT(!session_->live().sim.dragging, kWaitMs);
  }
  // The demonstration: a force on the TCP that swells and fades along three axes over 2 s of
  // controller time (a curve, not a line), then lets go; returns once the arm is at rest.
  // On a KUKA the push goes to the simulated KRC's force sensor (the Hand guiding panel follows it).
  void pushAlongCurve() {
    const uint64_t start = cycle();
    const double cycle_s = session_->arm()->cycleSeconds();
    QElapsedTimer net;
    net.start();
    for (;;) {
      const double t = double(cycle() - start) * cycle_s;  // s of controller time
      if (t >= 2.0) break;
      const double pi = 3.141592653589793;
      setPush({20 * std::sin(pi * t), 30 * std::sin(pi * t / 2), -20 * std::sin(pi * t), 0, 0, 0});
      QTest::qWait(2);
      QVERIFY2(net.elapsed() < kWaitMs, "the simulator did not advance");
    }
    setPush({0, 0, 0, 0, 0, 0});
    QTRY_VERIFY_WITH_TIMEOUT(atRest(), kWaitMs);
  }
  void setPush(const std::array<double, 6>& wrench) {
    if (session_->kukaSimulator()) session_->kukaSimulator()->krc().setExternalWrench(wrench);
    else session_->simulator()->setExternalWrench(wrench);
  }
  void waitRunEnd() {
    QTRY_VERIFY_WITH_TIMEOUT(!panel_->isRunning(), 4 * kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(!session_->live().motion_running, kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(atRest(), kWaitMs);
  }
  void openSession() {
    QSignalSpy failed(session_, &Session::openFailed);
    SessionTarget target = rci::ui::test::lockstepSimulator();
    target.loopback = false;  // the test sets the inputs itself (the DI trigger)
    session_->open(target);
    QTRY_VERIFY_WITH_TIMEOUT(session_->isOpen() || failed.count() > 0, kWaitMs);
    QVERIFY2(session_->isOpen(), failed.isEmpty() ? "" : qPrintable(failed.first().first().toString()));
    QTRY_VERIFY_WITH_TIMEOUT(session_->live().has_state && session_->live().has_arm_state, kWaitMs);
    click(QStringLiteral("power.on"));
    QTRY_VERIFY_WITH_TIMEOUT(find<Lamp>(QStringLiteral("power.lamp"))->isOn(), kWaitMs);
  }

  QTemporaryDir settings_dir_;
  std::array<double, 7> rest_q_{};
  Session* session_ = nullptr;
  QWidget* host_ = nullptr;
  ProgramPanel* panel_ = nullptr;

 private slots:
  void initTestCase();
  void cleanupTestCase();
  void recordWithButtonThenReplayAtThreeSpeeds();
  void pathEditing();
  void f9TogglesAndARecordingWithoutMotionIsRefused();
  void diTriggerTogglesRecording();
  void closingTheConnectionKeepsTheRecording();
  void kukaRecordingThroughHandGuidingAndReplay();
};

void TestPathGui::initTestCase() {
  QVERIFY(settings_dir_.isValid());
  rci::ui::test::usePrivateSettings(settings_dir_.path());
  session_ = new Session;
  host_ = new QWidget;
  auto* layout = new QVBoxLayout(host_);
  for (const auto& p : createPanels(*session_, host_)) layout->addWidget(p.widget);
  host_->show();
  host_->activateWindow();
  QVERIFY(QTest::qWaitForWindowActive(host_));
  panel_ = host_->findChild<ProgramPanel*>(QStringLiteral("panel.program"));
  QVERIFY(panel_);
  panel_->setDialogs({[] { return QString(); }, [](const QString&) { return QString(); },
                      [] { return ProgramPanel::UnsavedChoice::kDiscard; }});
  openSession();
}

void TestPathGui::cleanupTestCase() {
  delete host_;
  delete session_;
}

void TestPathGui::recordWithButtonThenReplayAtThreeSpeeds() {
  startDrag();
  QVERIFY(driver().choose(QStringLiteral("program.recordType"), kRecordPath));
  QCOMPARE(text(QStringLiteral("program.record")), QStringLiteral("Start recording path (F9)"));
  click(QStringLiteral("program.record"));
  QVERIFY(panel_->isRecordingPath());
  QCOMPARE(text(QStringLiteral("program.record")), QStringLiteral("Stop recording path (F9)"));
  // Recording and running exclude each other; the move type stays while recording.
  QVERIFY(!find<QPushButton>(QStringLiteral("program.run"))->isEnabled());
  QVERIFY(!find<QPushButton>(QStringLiteral("program.step"))->isEnabled());
  QVERIFY(!find<QComboBox>(QStringLiteral("program.recordType"))->isEnabled());

  pushAlongCurve();
  QTRY_VERIFY_WITH_TIMEOUT(text(QStringLiteral("program.recordState")).contains(QStringLiteral("none lost")), kWaitMs);
  // The 3D view shows the TCP trace being recorded (one point per 10 ms of a ~2 s demonstration).
  QVERIFY2(session_->programOverlay().path.size() > 100,
           qPrintable(QString::number(session_->programOverlay().path.size())));

  click(QStringLiteral("program.record"));
  QVERIFY(!panel_->isRecordingPath());
  QCOMPARE(text(QStringLiteral("program.record")), QStringLiteral("Start recording path (F9)"));
  QCOMPARE(rows(), 1);
  const xmate::teach::Instruction& in = panel_->program().instructions[0];
  QCOMPARE(in.type, InstructionType::kPath);
  QCOMPARE(in.name, std::string("Path 1"));
  QCOMPARE(in.speed, 1.0);
  QVERIFY(in.path.q.size() >= 2);
  QVERIFY(in.path.duration() > 0);
  QVERIFY(panel_->program().has_tool);  // the first recording adopts the robot's tool
  const xmate::teach::PathSummary summary =
      xmate::teach::summarizePath(in.path, *panel_->program().robot, panel_->program().tool);
  QVERIFY2(summary.tcp_length > 0.02, qPrintable(QString::number(summary.tcp_length)));  // the push moved it
  const QString status = text(QStringLiteral("program.status"));
  qInfo("%s", qPrintable(status));
  QVERIFY2(status.startsWith(QStringLiteral("Recorded path \"Path 1\": ")) && status.contains(QStringLiteral("none lost")) &&
               status.contains(QStringLiteral("m of TCP path")) && status.contains(QStringLiteral("of rest trimmed")),
           qPrintable(status));
  // The table: type, name, speed as demonstrated and the summary.
  QCOMPARE(cell(0, ProgramModel::kType), QStringLiteral("PATH"));
  QCOMPARE(cell(0, ProgramModel::kName), QStringLiteral("Path 1"));
  QCOMPARE(cell(0, ProgramModel::kSpeed), QStringLiteral("100"));
  const QString details = cell(0, ProgramModel::kDetails);
  QVERIFY2(details.contains(QStringLiteral(" m TCP")) &&
               details.contains(QStringLiteral("%1 samples @ ").arg(in.path.q.size())),
           qPrintable(details));
  // The 3D view: the marker at the path's end, named, and the traced path (from the pre-flight).
  QCOMPARE(int(session_->programOverlay().waypoints.size()), 1);
  QCOMPARE(session_->programOverlay().labels[0], QStringLiteral("Path 1"));
  stopDrag();
  QTRY_VERIFY_WITH_TIMEOUT(!panel_->isTracing() && session_->programOverlay().path.size() > 1, kWaitMs);
  // The arm rests at the path's end: the pre-flight announces the move to its start (not a problem).
  auto* problems = find<QListWidget>(QStringLiteral("program.problems"));
  QTRY_COMPARE_WITH_TIMEOUT(problems->count(), 1, kWaitMs);
  QVERIFY2(problems->item(0)->text().startsWith(QStringLiteral("instruction 1 (PATH \"Path 1\"): first moves to the start of the path")),
           qPrintable(problems->item(0)->text()));
  QVERIFY(find<QPushButton>(QStringLiteral("program.run"))->isEnabled());

  // Replay through the Run button at 100, 50 and 10 % of the demonstrated pace, the speed edited in
  // the list. Each run starts at the path's end, so the executor first moves to its first sample.
  for (const double percent : {100.0, 50.0, 10.0}) {
    QVERIFY(model()->setData(model()->index(0, ProgramModel::kSpeed), percent));
    QCOMPARE(panel_->program().instructions[0].speed, percent / 100);
    click(QStringLiteral("program.run"));
    QVERIFY(panel_->isRunning());
    QVERIFY(!find<QPushButton>(QStringLiteral("program.record"))->isEnabled());  // no recording while running
    waitRunEnd();
    const xmate::teach::RunReport& report = panel_->lastReport();
    QVERIFY2(report.outcome == RunState::kFinished, report.message.c_str());
    QCOMPARE(int(report.instructions.size()), 1);
    const xmate::teach::InstructionReport& r = report.instructions[0];
    QVERIFY2(r.path_joint_deviation < kPathTolerance,
             qPrintable(QStringLiteral("at %1 %: %2 rad").arg(percent).arg(r.path_joint_deviation)));
    QVERIFY(r.duration > 0);
    QVERIFY(r.lead_in > 0);  // from the path's end back to its start
    // Slower asked, longer replay: at least the demonstrated duration over the speed.
    QVERIFY2(r.duration >= in.path.duration() / (percent / 100) * 0.99,
             qPrintable(QStringLiteral("%1 s at %2 %").arg(r.duration).arg(percent)));
    // The result in words: the row's tooltip and the status line.
    const QString tip = cell(0, ProgramModel::kDetails, Qt::ToolTipRole);
    QVERIFY2(tip.contains(QStringLiteral("Last run: done in")) && tip.contains(QStringLiteral("mrad")) &&
                 (tip.contains(QStringLiteral("not slowed")) || tip.contains(QStringLiteral("slowed to"))),
             qPrintable(tip));
    const QString done = text(QStringLiteral("program.status"));
    qInfo("%s", qPrintable(done));
    QVERIFY2(done.startsWith(QStringLiteral("Run finished in ")) && done.contains(QStringLiteral("The path was followed within")),
             qPrintable(done));
  }
}

// Name and speed edit like any motion's; the type does not change; duplicate names the copy as a
// path; touch-up is not offered; go to moves to the path's first sample.
void TestPathGui::pathEditing() {
  QCOMPARE(rows(), 1);
  auto* list = find<QTableView>(QStringLiteral("program.list"));
  QVERIFY(!(model()->flags(model()->index(0, ProgramModel::kType)) & Qt::ItemIsEditable));
  QVERIFY(!model()->setData(model()->index(0, ProgramModel::kType), QStringLiteral("MOVEJ")));
  QCOMPARE(panel_->program().instructions[0].type, InstructionType::kPath);
  QVERIFY(model()->setData(model()->index(0, ProgramModel::kName), QStringLiteral("wipe")));
  QCOMPARE(panel_->program().instructions[0].name, std::string("wipe"));
  QVERIFY(!model()->setData(model()->index(0, ProgramModel::kSpeed), 0.0));
  QVERIFY(!model()->setData(model()->index(0, ProgramModel::kSpeed), 101.0));
  list->selectRow(0);
  QVERIFY(!find<QPushButton>(QStringLiteral("program.touchup"))->isEnabled());
  QVERIFY(!find<QPushButton>(QStringLiteral("program.touchupVia"))->isEnabled());
  click(QStringLiteral("program.duplicate"));
  QCOMPARE(rows(), 2);
  QCOMPARE(cell(1, ProgramModel::kName), QStringLiteral("Path 1"));
  QCOMPARE(panel_->program().instructions[1].path.q.size(), panel_->program().instructions[0].path.q.size());
  click(QStringLiteral("program.up"));
  QCOMPARE(cell(0, ProgramModel::kName), QStringLiteral("Path 1"));
  click(QStringLiteral("program.delete"));
  QCOMPARE(rows(), 1);
  QCOMPARE(cell(0, ProgramModel::kName), QStringLiteral("wipe"));

  list->selectRow(0);
  click(QStringLiteral("program.goto"));
  QTRY_VERIFY_WITH_TIMEOUT(panel_->isRunning() || panel_->lastReport().outcome != RunState::kIdle, kWaitMs);
  waitRunEnd();
  QVERIFY2(panel_->lastReport().outcome == RunState::kFinished, panel_->lastReport().message.c_str());
  const auto& first = panel_->program().instructions[0].path.q.front();
  double off = 0;
  for (size_t j = 0; j < 7; ++j) off = std::max(off, std::abs(session_->live().arm.sample.q[j] - first[j]));
  QVERIFY2(off < 1e-3, qPrintable(QString::number(off)));
}

void TestPathGui::f9TogglesAndARecordingWithoutMotionIsRefused() {
  const int before = rows();
  QTest::keyClick(host_, Qt::Key_F9);
  QVERIFY(panel_->isRecordingPath());
  QTRY_VERIFY_WITH_TIMEOUT(text(QStringLiteral("program.recordState")).startsWith(QStringLiteral("Recording path")), kWaitMs);
  waitCycles(500);  // the arm rests (no hand guiding)
  QTest::keyClick(host_, Qt::Key_F9);
  QVERIFY(!panel_->isRecordingPath());
  QCOMPARE(rows(), before);  // nothing inserted
  const QString status = text(QStringLiteral("program.status"));
  QVERIFY2(status.startsWith(QStringLiteral("No path recorded: the arm did not move")), qPrintable(status));
  QVERIFY(find<QPushButton>(QStringLiteral("program.run"))->isEnabled());
}

void TestPathGui::diTriggerTogglesRecording() {
  auto* trigger = find<QComboBox>(QStringLiteral("program.diTrigger"));
  trigger->setCurrentIndex(trigger->findText(QStringLiteral("DI0_1")));
  session_->simulator()->setDigitalInput(1, true);  // rising edge: starts
  QTRY_VERIFY_WITH_TIMEOUT(panel_->isRecordingPath(), kWaitMs);
  session_->simulator()->setDigitalInput(1, false);
  QTRY_VERIFY_WITH_TIMEOUT(!session_->live().digital_in[1], kWaitMs);
  QVERIFY(panel_->isRecordingPath());  // a falling edge does nothing
  session_->simulator()->setDigitalInput(1, true);  // the next rising edge: stops
  QTRY_VERIFY_WITH_TIMEOUT(!panel_->isRecordingPath(), kWaitMs);
  session_->simulator()->setDigitalInput(1, false);
  trigger->setCurrentIndex(0);
}

// The session closes mid-recording: what was demonstrated until then becomes the PATH.
void TestPathGui::closingTheConnectionKeepsTheRecording() {
  const int before = rows();
  startDrag();
  click(QStringLiteral("program.record"));
  QVERIFY(panel_->isRecordingPath());
  pushAlongCurve();
  session_->close();
  QTRY_VERIFY_WITH_TIMEOUT(!panel_->isRecordingPath(), kWaitMs);
  QCOMPARE(rows(), before + 1);
  QCOMPARE(panel_->program().instructions.back().type, InstructionType::kPath);
  const QString status = text(QStringLiteral("program.status"));
  QVERIFY2(status.startsWith(QStringLiteral("The path recording ended: the connection closed. Recorded path")),
           qPrintable(status));
}

// The built-in KUKA simulator (RSI, 4 ms cycle): guide with the force sensor through the Hand
// guiding panel, record the path with the button, replay it.
void TestPathGui::kukaRecordingThroughHandGuidingAndReplay() {
  QSignalSpy failed(session_, &Session::openFailed);
  session_->open(rci::ui::test::kukaSimulator());
  QTRY_VERIFY_WITH_TIMEOUT(session_->isOpen() || failed.count() > 0, kWaitMs);
  QVERIFY2(session_->isOpen(), failed.isEmpty() ? "" : qPrintable(failed.first().first().toString()));
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().rsi.phase == xmate::rsi::SessionPhase::kRunning &&
                               session_->live().force_reading && session_->live().has_arm_state,
                           kWaitMs);
  click(QStringLiteral("program.new"));  // the xMate's program: discarded (the dialog answers so)
  QCOMPARE(rows(), 0);
  QVERIFY(driver().choose(QStringLiteral("guide.axes"), int(xmate::guide::GuideAxes::kTranslation)));
  click(QStringLiteral("guide.start"));
  QTRY_VERIFY_WITH_TIMEOUT(find<Lamp>(QStringLiteral("guide.lamp"))->isOn(), kWaitMs);

  QVERIFY(driver().choose(QStringLiteral("program.recordType"), kRecordPath));
  click(QStringLiteral("program.record"));
  QVERIFY(panel_->isRecordingPath());
  pushAlongCurve();
  click(QStringLiteral("program.record"));
  QCOMPARE(rows(), 1);
  const xmate::teach::Instruction& in = panel_->program().instructions[0];
  QCOMPARE(in.type, InstructionType::kPath);
  QVERIFY(in.path.q.size() >= 2 && in.path.duration() > 0);
  QVERIFY(in.path.rate_hz <= 250);  // at most the recording's own rate (4 ms cycle)
  const QString status = text(QStringLiteral("program.status"));
  qInfo("%s", qPrintable(status));
  QVERIFY2(status.startsWith(QStringLiteral("Recorded path \"Path 1\": ")) && status.contains(QStringLiteral("none lost")),
           qPrintable(status));
  click(QStringLiteral("guide.stop"));
  QTRY_VERIFY_WITH_TIMEOUT(!session_->live().motion_running, kWaitMs);

  click(QStringLiteral("program.run"));
  waitRunEnd();
  const xmate::teach::RunReport& report = panel_->lastReport();
  QVERIFY2(report.outcome == RunState::kFinished, report.message.c_str());
  QVERIFY2(report.instructions[0].path_joint_deviation < kPathTolerance,
           qPrintable(QString::number(report.instructions[0].path_joint_deviation)));
  qInfo("%s", qPrintable(text(QStringLiteral("program.status"))));
}

QTEST_MAIN(TestPathGui)
#include "test_path_gui.moc"
