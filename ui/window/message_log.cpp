// The Messages dock (message_log.h).
#include "window/message_log.h"

#include <QDateTime>
#include <QHBoxLayout>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

#include "session/session.h"

namespace rci::ui {
namespace {

constexpr int kMaxLines = 2000;

}  // namespace

MessageLog::MessageLog(Session& session, QWidget* parent) : QWidget(parent) {
  list_ = new QListWidget(this);
  list_->setObjectName(QStringLiteral("log.list"));
  list_->setAlternatingRowColors(true);
  list_->setWordWrap(true);
  list_->setSelectionMode(QAbstractItemView::ExtendedSelection);
  auto* clear = new QPushButton(tr("Clear"), this);
  clear->setObjectName(QStringLiteral("log.clear"));
  clear->setToolTip(tr("Remove all messages"));
  connect(clear, &QPushButton::clicked, list_, &QListWidget::clear);

  auto* buttons = new QHBoxLayout;
  buttons->addStretch();
  buttons->addWidget(clear);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(6, 6, 6, 6);
  layout->addWidget(list_);
  layout->addLayout(buttons);

  connect(&session, &Session::opened, this, [this, &session] { addInfo(tr("Connected to %1").arg(session.target().describe())); });
  connect(&session, &Session::openFailed, this, [this](const QString& reason) { addError(reason); });
  connect(&session, &Session::closed, this, [this](const QString& reason) {
    if (reason.isEmpty()) addInfo(tr("Disconnected"));
    else addError(reason);
  });
  connect(&session, &Session::reconnecting, this, [this](const QString& reason) { addError(reason); });
  connect(&session, &Session::reconnected, this, [this, &session] { addInfo(tr("Reconnected to %1").arg(session.target().describe())); });
  connect(&session, &Session::commandFinished, this, [this](const QString& label, bool ok, const QString& message) {
    if (!ok) addError(tr("%1 failed: %2").arg(label, message));
  });
  connect(&session, &Session::motionStarted, this, [this](const QString& label) { addInfo(tr("%1 started").arg(label)); });
  connect(&session, &Session::motionFinished, this, [this](const QString& label, bool ok, const QString& message) {
    if (ok) addInfo(tr("%1 finished").arg(label));
    else addError(tr("%1 failed: %2").arg(label, message));
  });
}

void MessageLog::addInfo(const QString& text) { add(text, false); }
void MessageLog::addError(const QString& text) { add(text, true); }
int MessageLog::count() const { return list_->count(); }
QString MessageLog::text(int row) const { return list_->item(row)->text(); }

void MessageLog::add(const QString& text, bool error) {
  const QString stamp = QDateTime::currentDateTime().toString(QStringLiteral("HH:mm:ss"));
  auto* item = new QListWidgetItem(QStringLiteral("%1   %2").arg(stamp, text), list_);
  if (error) item->setForeground(QColor(0xc6, 0x28, 0x28));
  item->setToolTip(text);
  while (list_->count() > kMaxLines) delete list_->takeItem(0);
  list_->scrollToBottom();
}

}  // namespace rci::ui
