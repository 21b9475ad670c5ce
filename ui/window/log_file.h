// SPDX-License-Identifier: Apache-2.0
// LogFile: the event log on disk -- lines appended to <folder>/rci-studio.log by a background
// thread (the GUI never waits on the disk), rotated at about 1 MB with a few old files kept
// (rci-studio.log.1 is the newest of them).
#pragma once

#include <QString>

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace rci::ui {

class LogFile {
 public:
  // on_error is called once, on the writer thread, with why the folder or file cannot be written;
  // lines are dropped from then on.
  LogFile(const QString& folder, std::function<void(const QString&)> on_error, int64_t rotate_bytes = 1 << 20,
          int keep = 3);
  ~LogFile();  // writes what is queued, then stops the thread
  LogFile(const LogFile&) = delete;
  LogFile& operator=(const LogFile&) = delete;

  // Queues one line (without its newline). Any thread; returns at once.
  void append(const QString& line);
  // Waits until every line queued so far is on disk (or dropped). For tests and shutdown.
  void flush();
  QString path() const { return path_; }

  // $XDG_STATE_HOME/rci-studio, or ~/.local/state/rci-studio when it is not set.
  static QString defaultFolder();

 private:
  void run();
  bool writeBatch(const std::vector<QString>& lines);
  bool open();
  void rotate();
  void fail(const QString& why);

  QString folder_, path_;
  std::function<void(const QString&)> on_error_;
  int64_t rotate_bytes_;
  int keep_;
  // Hand-off: queue_ and the counters under mutex_; the writer waits on wake_, flush() on written_cv_.
  std::mutex mutex_;
  std::condition_variable wake_, written_cv_;
  std::vector<QString> queue_;
  uint64_t queued_ = 0, written_ = 0;
  bool stopping_ = false;
  // Writer thread only:
  struct Output;
  Output* out_ = nullptr;
  bool failed_ = false;
  std::thread thread_;
};

}  // namespace rci::ui
