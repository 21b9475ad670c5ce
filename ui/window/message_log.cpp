// SPDX-License-Identifier: Apache-2.0
// The Messages dock: the event log's rows, coalescing, severity filter, copy, and the log file
// (message_log.h).
#include "window/message_log.h"

#include <QApplication>
#include <QClipboard>
#include <QComboBox>
#include <QCoreApplication>
#include <QEvent>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QScrollBar>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>

#include "text/operator_text.h"
#include "window/log_file.h"
#include "window/robot_events.h"

namespace rci::ui {
namespace {

constexpr int kMaxRows = 5000;       // older rows are dropped (the file keeps them)
constexpr int kCoalesceMs = 5000;    // the same event again within this time adds to its row
constexpr size_t kRecentRows = 8;    // how many of the newest rows a repeat may join
constexpr int kLevelRole = Qt::UserRole;
constexpr int kTextRole = Qt::UserRole + 1;
constexpr int kDetailRole = Qt::UserRole + 2;
constexpr int kCountRole = Qt::UserRole + 3;
constexpr int kFirstRole = Qt::UserRole + 4;
constexpr int kLastRole = Qt::UserRole + 5;

using Level = Session::EventLevel;

QString levelName(Level level) {
  switch (level) {
    case Level::kError: return QCoreApplication::translate("MessageLog", "Error");
    case Level::kWarning: return QCoreApplication::translate("MessageLog", "Warning");
    case Level::kInfo: break;
  }
  return QCoreApplication::translate("MessageLog", "Info");
}

// The file's severity column: fixed width, English, so a lab can grep it.
const char* fileLevel(Level level) {
  switch (level) {
    case Level::kError: return "ERROR";
    case Level::kWarning: return "WARN ";
    case Level::kInfo: break;
  }
  return "INFO ";
}

QColor levelColour(Level level) {
  switch (level) {
    case Level::kError: return QColor(0xc6, 0x28, 0x28);
    case Level::kWarning: return QColor(0xb2, 0x6a, 0x00);
    case Level::kInfo: break;
  }
  return QColor();
}

QString oneLine(QString text) { return text.replace(QLatin1Char('\n'), QStringLiteral(" / ")); }

Level levelOf(const QListWidgetItem* item) { return Level(item->data(kLevelRole).toInt()); }

// Copies selected rows on Ctrl+C (the view alone would copy only the current row's text).
class CopyKeyFilter : public QObject {
 public:
  CopyKeyFilter(const MessageLog* log, QObject* parent) : QObject(parent), log_(log) {}
  bool eventFilter(QObject* watched, QEvent* event) override {
    if (event->type() == QEvent::KeyPress && static_cast<QKeyEvent*>(event)->matches(QKeySequence::Copy)) {
      log_->copySelection();
      return true;
    }
    return QObject::eventFilter(watched, event);
  }

 private:
  const MessageLog* log_;
};

}  // namespace

QString MessageLog::defaultLogFolder() { return LogFile::defaultFolder(); }

MessageLog::MessageLog(Session& session, QWidget* parent, const QString& log_folder)
    : QWidget(parent), session_(session) {
  list_ = new QListWidget(this);
  list_->setObjectName(QStringLiteral("log.list"));
  list_->setAlternatingRowColors(true);
  list_->setWordWrap(true);
  list_->setSelectionMode(QAbstractItemView::ExtendedSelection);
  list_->installEventFilter(new CopyKeyFilter(this, this));

  filter_ = new QComboBox(this);
  filter_->setObjectName(QStringLiteral("log.filter"));
  filter_->addItem(tr("All messages"), int(Level::kInfo));
  filter_->addItem(tr("Warnings and errors"), int(Level::kWarning));
  filter_->addItem(tr("Errors only"), int(Level::kError));
  filter_->setToolTip(tr("Show only messages at least this severe"));
  connect(filter_, &QComboBox::currentIndexChanged, this,
          [this] { setMinimumLevel(Level(filter_->currentData().toInt())); });
  auto* copy = new QPushButton(tr("Copy"), this);
  copy->setObjectName(QStringLiteral("log.copy"));
  copy->setToolTip(tr("Copy the selected messages (all shown ones if none is selected); Ctrl+C in the list"));
  connect(copy, &QPushButton::clicked, this, [this] { copySelection(); });
  auto* clear = new QPushButton(tr("Clear"), this);
  clear->setObjectName(QStringLiteral("log.clear"));
  clear->setToolTip(tr("Remove all messages from this list (the log file keeps them)"));
  connect(clear, &QPushButton::clicked, this, [this] { clearRows(); });
  file_label_ = new QLabel(this);
  file_label_->setObjectName(QStringLiteral("log.file"));
  file_label_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  file_label_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);

  auto* buttons = new QHBoxLayout;
  buttons->addWidget(filter_);
  buttons->addWidget(file_label_, 1);
  buttons->addWidget(copy);
  buttons->addWidget(clear);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(6, 6, 6, 6);
  layout->addWidget(list_);
  layout->addLayout(buttons);

  repeat_timer_ = new QTimer(this);
  repeat_timer_->setInterval(1000);
  connect(repeat_timer_, &QTimer::timeout, this, [this] { flushRepeats(false); });
  repeat_timer_->start();

  if (!log_folder.isEmpty()) {
    // The writer thread reports a failure once; the row is added on the GUI thread.
    file_ = std::make_unique<LogFile>(log_folder, [this](const QString& why) {
      QMetaObject::invokeMethod(this, [this, why] { logFileFailed(why); }, Qt::QueuedConnection);
    });
    file_label_->setText(tr("Log file: %1").arg(file_->path()));
    file_label_->setToolTip(tr("Every message is also written to %1 (rotated at 1 MB, three old files kept)")
                                .arg(file_->path()));
    const QString version = QCoreApplication::applicationVersion();
    file_->append(QStringLiteral("%1  INFO   ---- RCI Studio%2 started ----")
                      .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss.zzz")),
                           version.isEmpty() ? QString() : QStringLiteral(" ") + version));
  }
  connectSession(session);
}

MessageLog::~MessageLog() { flushRepeats(true); }

void MessageLog::connectSession(Session& session) {
  connect(&session, &Session::opened, this, [this, &session] { addInfo(tr("Connected to %1").arg(session.target().describe())); });
  connect(&session, &Session::openFailed, this, [this, &session](const QString& reason) {
    addError(text::connectFailure(session.target().describe(), reason), reason);
  });
  connect(&session, &Session::closed, this, [this](const QString& reason) {
    if (reason.isEmpty()) addInfo(tr("Disconnected"));
    else addError(reason);
  });
  connect(&session, &Session::reconnecting, this, [this](const QString& reason) { addWarning(reason); });
  connect(&session, &Session::reconnected, this, [this, &session] { addInfo(tr("Reconnected to %1").arg(session.target().describe())); });
  connect(&session, &Session::commandStarted, this, [this](const QString& label) { addInfo(tr("%1 — sent").arg(label)); });
  connect(&session, &Session::commandFinished, this, &MessageLog::commandFinished);
  connect(&session, &Session::motionStarted, this, [this](const QString& label) { addInfo(tr("%1 — started").arg(label)); });
  connect(&session, &Session::motionFinished, this, [this, &session](const QString& label, bool ok, const QString& message) {
    if (ok) {
      addInfo(tr("%1 — ended").arg(label));
      return;
    }
    const text::OperatorMessage m = text::failure(message, text::viewOf(session));
    addError(tr("%1 — failed: %2").arg(label, m.line()), message);
  });
  connect(&session, &Session::eventReported, this, [this](Level level, const QString& text, const QString& detail) {
    add(level, text, detail);
  });
  auto* watcher = new RobotEventWatcher(session, this);
  connect(watcher, &RobotEventWatcher::event, this, [this](Level level, const QString& text, const QString& detail) {
    add(level, text, detail);
  });
}

void MessageLog::commandFinished(const QString& label, bool ok, const QString& message) {
  if (ok) {
    addInfo(tr("%1 — done").arg(label));
    return;
  }
  const text::OperatorMessage m = text::failure(message, text::viewOf(session_));
  addError(tr("%1 — failed: %2").arg(label, m.line()), message);
}

void MessageLog::addInfo(const QString& text, const QString& detail) { add(Level::kInfo, text, detail); }
void MessageLog::addWarning(const QString& text, const QString& detail) { add(Level::kWarning, text, detail); }
void MessageLog::addError(const QString& text, const QString& detail) { add(Level::kError, text, detail); }

void MessageLog::add(Level level, const QString& text, const QString& detail) {
  const QDateTime now = QDateTime::currentDateTime();
  if (coalesce(level, text, now)) return;
  appendRow(level, text, detail, now);
  writeFile(now, level, text, detail);
}

// The same event again shortly after: its row counts it instead of a new row.
bool MessageLog::coalesce(Level level, const QString& text, const QDateTime& now) {
  for (Recent& recent : recent_) {
    QListWidgetItem* item = recent.item;
    if (levelOf(item) != level || item->data(kTextRole).toString() != text) continue;
    if (recent.last.msecsTo(now) > kCoalesceMs) continue;
    recent.last = now;
    ++recent.unwritten;
    item->setData(kCountRole, item->data(kCountRole).toInt() + 1);
    item->setData(kLastRole, now);
    showRow(item);
    return true;
  }
  return false;
}

void MessageLog::appendRow(Level level, const QString& text, const QString& detail, const QDateTime& now) {
  QScrollBar* bar = list_->verticalScrollBar();
  const bool at_bottom = bar->value() >= bar->maximum() - 2;
  auto* item = new QListWidgetItem(list_);
  item->setData(kLevelRole, int(level));
  item->setData(kTextRole, text);
  item->setData(kDetailRole, detail);
  item->setData(kCountRole, 1);
  item->setData(kFirstRole, now);
  item->setData(kLastRole, now);
  if (const QColor colour = levelColour(level); colour.isValid()) item->setForeground(colour);
  showRow(item);
  item->setHidden(int(level) < filter_->currentData().toInt());

  recent_.push_back({item, now, 0});
  if (recent_.size() > kRecentRows) {
    writeRepeats(recent_.front());
    recent_.pop_front();
  }
  while (list_->count() > kMaxRows) delete list_->takeItem(0);
  if (at_bottom) list_->scrollToBottom();
}

void MessageLog::showRow(QListWidgetItem* item) const {
  const int count = item->data(kCountRole).toInt();
  const QDateTime first = item->data(kFirstRole).toDateTime();
  const QDateTime last = item->data(kLastRole).toDateTime();
  QString shown = QStringLiteral("%1  %2  %3")
                      .arg(first.toString(QStringLiteral("HH:mm:ss.zzz")), levelName(levelOf(item)),
                           item->data(kTextRole).toString());
  if (count > 1) shown += QStringLiteral("  (×%1)").arg(count);
  item->setText(shown);
  QString tip = first.toString(QStringLiteral("yyyy-MM-dd HH:mm:ss.zzz"));
  if (count > 1) tip += tr(", last at %1, %2 times").arg(last.toString(QStringLiteral("HH:mm:ss.zzz"))).arg(count);
  tip += QStringLiteral("\n") + item->data(kTextRole).toString();
  const QString detail = item->data(kDetailRole).toString();
  if (!detail.isEmpty() && detail != item->data(kTextRole).toString()) tip += tr("\n\nDetail: %1").arg(detail);
  item->setToolTip(tip);
}

void MessageLog::writeFile(const QDateTime& when, Level level, const QString& text, const QString& detail) {
  if (!file_ || file_failed_) return;
  QString line = QStringLiteral("%1  %2  %3")
                     .arg(when.toString(QStringLiteral("yyyy-MM-dd HH:mm:ss.zzz")), QLatin1String(fileLevel(level)),
                          oneLine(text));
  if (!detail.isEmpty() && detail != text) line += QStringLiteral("  | detail: ") + oneLine(detail);
  file_->append(line);
}

void MessageLog::writeRepeats(Recent& recent) {
  if (recent.unwritten == 0) return;
  QListWidgetItem* item = recent.item;
  writeFile(recent.last, levelOf(item),
            tr("%1 (repeated %2 more times since %3)")
                .arg(item->data(kTextRole).toString())
                .arg(recent.unwritten)
                .arg(item->data(kFirstRole).toDateTime().toString(QStringLiteral("HH:mm:ss.zzz"))),
            QString());
  recent.unwritten = 0;
}

// Repeats go to the file once their row stops collecting (all: now, e.g. when closing).
void MessageLog::flushRepeats(bool all) {
  const QDateTime now = QDateTime::currentDateTime();
  for (Recent& recent : recent_)
    if (all || recent.last.msecsTo(now) > kCoalesceMs) writeRepeats(recent);
}

void MessageLog::logFileFailed(const QString& why) {
  if (file_failed_) return;
  file_failed_ = true;
  file_label_->setText(tr("Log file: not written"));
  addWarning(tr("The event log cannot be written to %1 (%2): messages are kept in this window only.")
                 .arg(file_ ? file_->path() : QString(), why));
}

void MessageLog::clearRows() {
  flushRepeats(true);
  recent_.clear();
  list_->clear();
}

int MessageLog::count() const { return list_->count(); }
QString MessageLog::text(int row) const { return list_->item(row)->text(); }
MessageLog::Level MessageLog::level(int row) const { return levelOf(list_->item(row)); }
int MessageLog::repeats(int row) const { return list_->item(row)->data(kCountRole).toInt(); }
bool MessageLog::rowShown(int row) const { return !list_->item(row)->isHidden(); }

int MessageLog::find(const QString& needle) const {
  for (int row = 0; row < list_->count(); ++row)
    if (list_->item(row)->text().contains(needle)) return row;
  return -1;
}

void MessageLog::setMinimumLevel(Level level) {
  const int index = filter_->findData(int(level));
  if (index >= 0 && index != filter_->currentIndex()) {
    filter_->setCurrentIndex(index);  // comes back here through currentIndexChanged
    return;
  }
  for (int row = 0; row < list_->count(); ++row) {
    QListWidgetItem* item = list_->item(row);
    item->setHidden(int(levelOf(item)) < int(level));
  }
}

QString MessageLog::selectedText() const {
  QList<int> rows;
  for (const QListWidgetItem* item : list_->selectedItems())
    if (!item->isHidden()) rows << list_->row(item);
  if (rows.isEmpty()) {
    for (int row = 0; row < list_->count(); ++row)
      if (!list_->item(row)->isHidden()) rows << row;
  }
  std::sort(rows.begin(), rows.end());
  QStringList lines;
  for (int row : rows) {
    const QListWidgetItem* item = list_->item(row);
    lines << item->text();
    const QString detail = item->data(kDetailRole).toString();
    if (!detail.isEmpty() && detail != item->data(kTextRole).toString()) lines << QStringLiteral("    ") + oneLine(detail);
  }
  return lines.join(QLatin1Char('\n'));
}

void MessageLog::copySelection() const { QApplication::clipboard()->setText(selectedText()); }

QString MessageLog::logFilePath() const { return file_ ? file_->path() : QString(); }

void MessageLog::flushLogFile() {
  flushRepeats(true);
  if (file_) file_->flush();
}

}  // namespace rci::ui
