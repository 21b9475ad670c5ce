// SPDX-License-Identifier: Apache-2.0
// test_event_log: the Messages dock as the event log -- repeats coalesce into one row with "(×N)",
// rows filter by severity, selected rows copy (Ctrl+C and Copy), every event goes to the rotating
// log file under $XDG_STATE_HOME/rci-studio (a temporary folder here), an unwritable folder is said
// once; and a session on the embedded lock-step simulator going through power on, hand guiding, a
// collision, a refused command and the recovery leaves all of it in the log and the file.
#include <QApplication>
#include <QClipboard>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QListWidget>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include "gui_test_support.h"
#include "session/session.h"
#include "window/log_file.h"
#include "window/message_log.h"

using namespace rci::ui;
using rci::ui::test::lockstepSimulator;

namespace {

constexpr int kWaitMs = 20000;  // a safety net for a loaded machine, not a timing claim

QString readAll(const QString& path) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) return {};
  return QString::fromUtf8(file.readAll());
}

}  // namespace

class TestEventLog : public QObject {
  Q_OBJECT

 private:
  QListWidget* list() const { return log_->findChild<QListWidget*>(QStringLiteral("log.list")); }
  // Runs one command the way a panel does and waits for its result.
  bool runCommand(const QString& label, std::function<void(xmate::Robot&)> job) {
    QSignalSpy finished(session_, &Session::commandFinished);
    session_->run(label, std::move(job));
    return QTest::qWaitFor([&] { return finished.count() > 0; }, kWaitMs);
  }
  int rowsWith(const QString& needle) const {
    int n = 0;
    for (int row = 0; row < log_->count(); ++row)
      if (log_->text(row).contains(needle)) ++n;
    return n;
  }

  QTemporaryDir state_dir_;
  QTemporaryDir settings_dir_;
  Session* session_ = nullptr;
  MessageLog* log_ = nullptr;

 private slots:
  void initTestCase();
  void cleanupTestCase();
  void logFileUnderStateFolder();
  void coalescesRepeats();
  void filtersBySeverity();
  void copiesSelectedRows();
  void writesTheFile();
  void logFileRotates();
  void unwritableFolderSaidOnce();
  void sessionEventsAreLogged();
};

void TestEventLog::initTestCase() {
  QStandardPaths::setTestModeEnabled(true);
  QVERIFY(state_dir_.isValid() && settings_dir_.isValid());
  QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settings_dir_.path());
  qputenv("XDG_STATE_HOME", state_dir_.path().toUtf8());
  session_ = new Session;
  log_ = new MessageLog(*session_);
  log_->resize(700, 400);
  log_->show();
}

void TestEventLog::cleanupTestCase() {
  delete log_;
  delete session_;
}

void TestEventLog::logFileUnderStateFolder() {
  QCOMPARE(log_->logFilePath(), QDir(state_dir_.path()).filePath(QStringLiteral("rci-studio/rci-studio.log")));
  qunsetenv("XDG_STATE_HOME");
  QCOMPARE(LogFile::defaultFolder(), QDir::homePath() + QStringLiteral("/.local/state/rci-studio"));
  qputenv("XDG_STATE_HOME", state_dir_.path().toUtf8());
}

void TestEventLog::coalescesRepeats() {
  const int before = log_->count();
  for (int i = 0; i < 5; ++i) log_->addWarning(QStringLiteral("Guard stop active"));
  QCOMPARE(log_->count(), before + 1);
  const int row = log_->find(QStringLiteral("Guard stop active"));
  QVERIFY(row >= 0);
  QCOMPARE(log_->repeats(row), 5);
  QVERIFY2(log_->text(row).endsWith(QStringLiteral("(×5)")), qPrintable(log_->text(row)));
  QVERIFY2(QRegularExpression(QStringLiteral(R"(^\d\d:\d\d:\d\d\.\d{3}  Warning  Guard stop active)"))
               .match(log_->text(row))
               .hasMatch(),
           qPrintable(log_->text(row)));
  // Interleaved with another event it still joins its row; another severity is another event.
  log_->addInfo(QStringLiteral("Guard stop released"));
  log_->addWarning(QStringLiteral("Guard stop active"));
  QCOMPARE(log_->count(), before + 2);
  QCOMPARE(log_->repeats(row), 6);
  log_->addError(QStringLiteral("Guard stop active"));
  QCOMPARE(log_->count(), before + 3);
  QCOMPARE(log_->level(log_->count() - 1), MessageLog::Level::kError);
}

void TestEventLog::filtersBySeverity() {
  log_->addInfo(QStringLiteral("filter: info"));
  log_->addWarning(QStringLiteral("filter: warning"));
  log_->addError(QStringLiteral("filter: error"));
  const int info = log_->find(QStringLiteral("filter: info"));
  const int warning = log_->find(QStringLiteral("filter: warning"));
  const int error = log_->find(QStringLiteral("filter: error"));
  auto* combo = log_->findChild<QComboBox*>(QStringLiteral("log.filter"));
  QVERIFY(combo);
  combo->setCurrentIndex(combo->findData(int(MessageLog::Level::kError)));
  QVERIFY(!log_->rowShown(info) && !log_->rowShown(warning) && log_->rowShown(error));
  combo->setCurrentIndex(combo->findData(int(MessageLog::Level::kWarning)));
  QVERIFY(!log_->rowShown(info) && log_->rowShown(warning) && log_->rowShown(error));
  log_->addInfo(QStringLiteral("filter: later info"));  // new rows obey the filter too
  QVERIFY(!log_->rowShown(log_->count() - 1));
  log_->setMinimumLevel(MessageLog::Level::kInfo);
  QCOMPARE(combo->currentData().toInt(), int(MessageLog::Level::kInfo));
  QVERIFY(log_->rowShown(info) && log_->rowShown(log_->count() - 1));
}

void TestEventLog::copiesSelectedRows() {
  log_->addInfo(QStringLiteral("copy: first"));
  log_->addWarning(QStringLiteral("copy: second"));
  log_->addError(QStringLiteral("copy: third"), QStringLiteral("the raw detail"));
  list()->clearSelection();
  list()->item(log_->find(QStringLiteral("copy: first")))->setSelected(true);
  list()->item(log_->find(QStringLiteral("copy: third")))->setSelected(true);
  QApplication::clipboard()->clear();
  list()->setFocus();
  QTest::keyClick(list(), Qt::Key_C, Qt::ControlModifier);
  const QString copied = QApplication::clipboard()->text();
  QVERIFY2(copied.contains(QStringLiteral("copy: first")) && copied.contains(QStringLiteral("copy: third")), qPrintable(copied));
  QVERIFY2(!copied.contains(QStringLiteral("copy: second")), qPrintable(copied));
  QVERIFY2(copied.contains(QStringLiteral("the raw detail")), qPrintable(copied));
  QVERIFY(copied.indexOf(QStringLiteral("copy: first")) < copied.indexOf(QStringLiteral("copy: third")));
  // The Copy button: the selection, or every shown row when nothing is selected.
  list()->clearSelection();
  QApplication::clipboard()->clear();
  QTest::mouseClick(log_->findChild<QPushButton*>(QStringLiteral("log.copy")), Qt::LeftButton);
  const QString all = QApplication::clipboard()->text();
  QVERIFY2(all.contains(QStringLiteral("copy: second")) && all.contains(QStringLiteral("Guard stop active")), qPrintable(all));
}

void TestEventLog::writesTheFile() {
  log_->addError(QStringLiteral("file: something failed"), QStringLiteral("startMove: the controller refused"));
  log_->flushLogFile();
  const QString text = readAll(log_->logFilePath());
  QVERIFY2(!text.isEmpty(), qPrintable(log_->logFilePath()));
  QVERIFY(text.contains(QStringLiteral("RCI Studio")));
  const QRegularExpression line(QStringLiteral(
      R"(\d{4}-\d\d-\d\d \d\d:\d\d:\d\d\.\d{3}  ERROR  file: something failed  \| detail: startMove: the controller refused)"));
  QVERIFY2(line.match(text).hasMatch(), qPrintable(text));
  QVERIFY2(text.contains(QStringLiteral("WARN   Guard stop active")), qPrintable(text));
  // The coalesced repeats are in the file too, counted.
  QVERIFY2(text.contains(QStringLiteral("Guard stop active (repeated 5 more times")), qPrintable(text));
}

void TestEventLog::logFileRotates() {
  QTemporaryDir dir;
  QVERIFY(dir.isValid());
  {
    LogFile file(dir.path(), nullptr, 300, 2);
    for (int i = 0; i < 100; ++i) file.append(QStringLiteral("line %1 of the rotation test ......").arg(i, 3));
    file.flush();
    QVERIFY(QFile::exists(file.path()));
    QVERIFY(QFile::exists(file.path() + QStringLiteral(".1")));
    QVERIFY(QFile::exists(file.path() + QStringLiteral(".2")));
    QVERIFY(!QFile::exists(file.path() + QStringLiteral(".3")));
    QVERIFY(QFileInfo(file.path()).size() < 300);
    // The newest line is in the current file, the one before it rotated into .1.
    QVERIFY(readAll(file.path()).contains(QStringLiteral("line  99")));
    QVERIFY(!readAll(file.path() + QStringLiteral(".2")).contains(QStringLiteral("line  99")));
  }
}

void TestEventLog::unwritableFolderSaidOnce() {
  QTemporaryDir dir;
  QVERIFY(dir.isValid());
  QFile blocker(dir.filePath(QStringLiteral("not-a-folder")));
  QVERIFY(blocker.open(QIODevice::WriteOnly));
  blocker.close();
  MessageLog log(*session_, nullptr, blocker.fileName() + QStringLiteral("/rci-studio"));
  QTRY_VERIFY_WITH_TIMEOUT(log.find(QStringLiteral("cannot be written")) >= 0, kWaitMs);
  log.addInfo(QStringLiteral("after the failure"));
  log.addInfo(QStringLiteral("and again"));
  log.flushLogFile();
  QCoreApplication::processEvents();
  int said = 0;
  for (int row = 0; row < log.count(); ++row) said += log.text(row).contains(QStringLiteral("cannot be written")) ? 1 : 0;
  QCOMPARE(said, 1);
  QCOMPARE(log.level(log.find(QStringLiteral("cannot be written"))), MessageLog::Level::kWarning);
}

void TestEventLog::sessionEventsAreLogged() {
  QSignalSpy failed(session_, &Session::openFailed);
  session_->open(lockstepSimulator());
  QTRY_VERIFY_WITH_TIMEOUT(session_->isOpen() || failed.count() > 0, kWaitMs);
  QVERIFY(session_->isOpen());
  QTRY_VERIFY_WITH_TIMEOUT(log_->find(QStringLiteral("Connected to Simulator")) >= 0, kWaitMs);
  QTRY_VERIFY_WITH_TIMEOUT(log_->find(QStringLiteral("Robot: Idle")) >= 0, kWaitMs);

  QVERIFY(runCommand(QStringLiteral("Power: power on"), [](xmate::Robot& r) { r.setMotorPower(1); }));
  QVERIFY(log_->find(QStringLiteral("Power: power on — sent")) >= 0);
  QVERIFY(log_->find(QStringLiteral("Power: power on — done")) >= 0);
  QTRY_VERIFY_WITH_TIMEOUT(log_->find(QStringLiteral("Motors on")) >= 0, kWaitMs);

  QVERIFY(runCommand(QStringLiteral("Drag: start guiding"), [](xmate::Robot& r) { r.startDrag(1, 3); }));
  QTRY_VERIFY_WITH_TIMEOUT(log_->find(QStringLiteral("Hand guiding started")) >= 0, kWaitMs);
  QVERIFY(runCommand(QStringLiteral("Drag: stop guiding"), [](xmate::Robot& r) { r.stopDrag(); }));
  QTRY_VERIFY_WITH_TIMEOUT(log_->find(QStringLiteral("Hand guiding stopped")) >= 0, kWaitMs);

  // A hard push on the held arm: a collision, the motors switch off.
  QTRY_VERIFY_WITH_TIMEOUT(session_->live().state.robot_mode == RCI::robot::RobotMode::kIdle, kWaitMs);
  session_->simulator()->setExternalWrench({250, 0, 0, 0, 0, 0});
  QTRY_VERIFY_WITH_TIMEOUT(log_->find(QStringLiteral("Robot reports: Collision detected")) >= 0, kWaitMs);
  const int collision = log_->find(QStringLiteral("Robot reports: Collision detected"));
  QCOMPARE(log_->level(collision), MessageLog::Level::kError);
  QVERIFY2(log_->text(collision).contains(QStringLiteral("press Recover in the Safety panel")), qPrintable(log_->text(collision)));
  QTRY_VERIFY_WITH_TIMEOUT(log_->find(QStringLiteral("Motors off")) >= 0, kWaitMs);
  session_->simulator()->setExternalWrench({0, 0, 0, 0, 0, 0});

  QVERIFY(runCommand(QStringLiteral("Safety: recover errors"), [](xmate::Robot& r) { r.automaticErrorRecovery(); }));
  QTRY_VERIFY_WITH_TIMEOUT(log_->find(QStringLiteral("Errors cleared: ")) >= 0, kWaitMs);
  QVERIFY(log_->text(log_->find(QStringLiteral("Errors cleared: "))).contains(QStringLiteral("Collision detected")));

  // Refused with the motors off: the log says which button helps, not the library's words.
  QVERIFY(runCommand(QStringLiteral("Drag: start guiding"), [](xmate::Robot& r) { r.startDrag(1, 3); }));
  const int refused = log_->find(QStringLiteral("Drag: start guiding — failed"));
  QVERIFY(refused >= 0);
  QVERIFY2(log_->text(refused).contains(QStringLiteral("The motors are off. Press Power on in the Power panel.")),
           qPrintable(log_->text(refused)));
  QVERIFY2(!log_->text(refused).contains(QStringLiteral("setMotorPower")), qPrintable(log_->text(refused)));

  log_->flushLogFile();
  const QString text = readAll(log_->logFilePath());
  for (const char* event : {"Connected to Simulator", "Power: power on — done", "Motors on", "Hand guiding started",
                            "Hand guiding stopped", "ERROR  Robot reports: Collision detected", "Motors off",
                            "Safety: recover errors — done", "Errors cleared: ",
                            "The motors are off. Press Power on"})
    QVERIFY2(text.contains(QString::fromUtf8(event)), event);
  session_->close();
  QTRY_VERIFY_WITH_TIMEOUT(log_->find(QStringLiteral("Disconnected")) >= 0, kWaitMs);
}

QTEST_MAIN(TestEventLog)
#include "test_event_log.moc"
