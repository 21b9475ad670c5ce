// SPDX-License-Identifier: Apache-2.0
// MessageLog: the Messages dock, the window's event log -- connects, commands sent and their
// results, motions and program runs, robot mode, motors, hand guiding, stops and error bits, in
// operator words, each with a time stamp (hh:mm:ss.zzz) and a severity (coloured). Repeats within a
// few seconds become one row with "(×N)"; rows can be filtered by severity and copied (Ctrl+C, Copy).
// Every event also goes to a rotating log file (LogFile) under the user's state folder.
#pragma once

#include <QDateTime>
#include <QWidget>

#include <deque>
#include <memory>

#include "session/session.h"

class QComboBox;
class QLabel;
class QListWidget;
class QListWidgetItem;
class QTimer;

namespace rci::ui {

class LogFile;

class MessageLog : public QWidget {
  Q_OBJECT
 public:
  using Level = Session::EventLevel;

  // log_folder: where rci-studio.log goes (LogFile::defaultFolder() unless a test says otherwise);
  // empty: no file.
  MessageLog(Session& session, QWidget* parent = nullptr, const QString& log_folder = defaultLogFolder());
  ~MessageLog() override;

  void addInfo(const QString& text, const QString& detail = QString());
  void addWarning(const QString& text, const QString& detail = QString());
  void addError(const QString& text, const QString& detail = QString());
  void add(Level level, const QString& text, const QString& detail = QString());

  int count() const;                 // rows, shown or filtered out
  QString text(int row) const;       // as shown: "12:03:04.567  Error  Collision detected ... (×3)"
  Level level(int row) const;
  int repeats(int row) const;        // N of "(×N)", 1 for a single event
  bool rowShown(int row) const;      // false when the severity filter hides it
  // The row's text holding needle, or -1.
  int find(const QString& needle) const;
  // Shows only rows at least this severe.
  void setMinimumLevel(Level level);
  // The selected rows (all shown rows if none is selected) as text, one event per line.
  QString selectedText() const;
  void copySelection() const;
  // The log file ("" when none); flushLogFile() waits until every event so far is written.
  QString logFilePath() const;
  void flushLogFile();

  static QString defaultLogFolder();

 private:
  struct Recent {
    QListWidgetItem* item;
    QDateTime last;
    int unwritten = 0;  // repeats not yet in the file
  };
  void connectSession(Session& session);
  void commandFinished(const QString& label, bool ok, const QString& message);
  bool coalesce(Level level, const QString& text, const QDateTime& now);
  void appendRow(Level level, const QString& text, const QString& detail, const QDateTime& now);
  void showRow(QListWidgetItem* item) const;
  void writeFile(const QDateTime& when, Level level, const QString& text, const QString& detail);
  void writeRepeats(Recent& recent);
  void flushRepeats(bool all);
  void logFileFailed(const QString& why);
  void clearRows();

  Session& session_;
  QListWidget* list_ = nullptr;
  QComboBox* filter_ = nullptr;
  QLabel* file_label_ = nullptr;
  QTimer* repeat_timer_ = nullptr;
  std::deque<Recent> recent_;  // the newest rows, candidates for coalescing
  std::unique_ptr<LogFile> file_;
  bool file_failed_ = false;
};

}  // namespace rci::ui
