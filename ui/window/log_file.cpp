// SPDX-License-Identifier: Apache-2.0
// The event log file (log_file.h): a writer thread appends queued lines and rotates the file.
#include "window/log_file.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

namespace rci::ui {

struct LogFile::Output {
  QFile file;
};

LogFile::LogFile(const QString& folder, std::function<void(const QString&)> on_error, int64_t rotate_bytes, int keep)
    : folder_(folder),
      path_(QDir(folder).filePath(QStringLiteral("rci-studio.log"))),
      on_error_(std::move(on_error)),
      rotate_bytes_(rotate_bytes),
      keep_(keep),
      out_(new Output) {
  thread_ = std::thread([this] { run(); });
}

LogFile::~LogFile() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_one();
  thread_.join();
  delete out_;
}

QString LogFile::defaultFolder() {
  QString base = qEnvironmentVariable("XDG_STATE_HOME");
  if (base.isEmpty() || !QDir::isAbsolutePath(base)) base = QDir::homePath() + QStringLiteral("/.local/state");
  return QDir(base).filePath(QStringLiteral("rci-studio"));
}

void LogFile::append(const QString& line) {
  {
    std::lock_guard lock(mutex_);
    queue_.push_back(line);
    ++queued_;
  }
  wake_.notify_one();
}

void LogFile::flush() {
  std::unique_lock lock(mutex_);
  const uint64_t target = queued_;
  written_cv_.wait(lock, [&] { return written_ >= target; });
}

void LogFile::run() {
  std::vector<QString> batch;
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
      if (queue_.empty() && stopping_) return;
      batch.swap(queue_);
    }
    writeBatch(batch);
    {
      std::lock_guard lock(mutex_);
      written_ += batch.size();
    }
    written_cv_.notify_all();
    batch.clear();
  }
}

bool LogFile::writeBatch(const std::vector<QString>& lines) {
  if (failed_) return false;
  if (!out_->file.isOpen() && !open()) return false;
  for (const QString& line : lines) {
    const QByteArray bytes = line.toUtf8() + '\n';
    if (out_->file.write(bytes) != bytes.size()) {
      fail(out_->file.errorString());
      return false;
    }
    if (out_->file.size() >= rotate_bytes_) rotate();
  }
  out_->file.flush();
  return true;
}

bool LogFile::open() {
  if (!QDir().mkpath(folder_)) {
    fail(QStringLiteral("cannot create the folder %1").arg(folder_));
    return false;
  }
  out_->file.setFileName(path_);
  if (!out_->file.open(QIODevice::WriteOnly | QIODevice::Append | QIODevice::Text)) {
    fail(out_->file.errorString());
    return false;
  }
  return true;
}

// rci-studio.log -> .1 -> .2 ... -> .keep (dropped).
void LogFile::rotate() {
  out_->file.close();
  QFile::remove(path_ + QStringLiteral(".%1").arg(keep_));
  for (int i = keep_ - 1; i >= 1; --i)
    QFile::rename(path_ + QStringLiteral(".%1").arg(i), path_ + QStringLiteral(".%1").arg(i + 1));
  QFile::rename(path_, path_ + QStringLiteral(".1"));
  open();
}

void LogFile::fail(const QString& why) {
  if (failed_) return;
  failed_ = true;
  out_->file.close();
  if (on_error_) on_error_(why);
}

}  // namespace rci::ui
