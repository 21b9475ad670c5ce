// SPDX-License-Identifier: Apache-2.0
// PanelBase: command routing, status line, settings and session hooks shared by the panels.
#include "panels/panel_base.h"

#include <QDoubleSpinBox>
#include <QSettings>
#include <QVBoxLayout>

#include "panels/fields.h"
#include "session/session.h"
#include "text/operator_text.h"

namespace rci::ui {

PanelBase::PanelBase(Session& session, const QString& key, const QString& title, QWidget* parent)
    : QWidget(parent), session_(session), key_(key), title_(title) {
  setObjectName(QStringLiteral("panel.") + key);
  auto* outer = new QVBoxLayout(this);
  outer->setContentsMargins(8, 8, 8, 8);
  outer->setSpacing(8);
  body_ = new QVBoxLayout;
  body_->setSpacing(8);
  outer->addLayout(body_);
  outer->addStretch(1);
  status_ = new MessageLine(key + QStringLiteral(".status"), this);
  outer->addWidget(status_);

  // All signals below are emitted on the GUI thread (Session queues its workers' results there).
  connect(&session_, &Session::commandFinished, this, &PanelBase::onCommandFinished);
  connect(&session_, &Session::tick, this, [this] {
    updateMotionWidgets();
    if (session_.isOpen()) refresh(session_.live());
  });
  connect(&session_, &Session::opened, this, [this] {
    updateSendWidgets();
    sessionOpened();
  });
  // While the session re-opens a silent controller, nothing can be sent.
  connect(&session_, &Session::reconnecting, this, [this] { updateSendWidgets(); });
  connect(&session_, &Session::reconnected, this, [this] { updateSendWidgets(); });
  connect(&session_, &Session::closed, this, [this](const QString&) {
    pending_.clear();
    updateSendWidgets();
    sessionClosed();
  });
}

const xmate::model::RobotSpec& PanelBase::spec() const { return session_.spec(); }

bool PanelBase::appliesTo(Session& session) const {
  const xmate::arm::Arm* arm = session.arm();
  return arm != nullptr && (arm->capabilities() & needs_) == needs_;
}

bool PanelBase::isOpen() const { return session_.isOpen(); }

void PanelBase::send(const QString& action, std::function<void(xmate::Robot&)> job,
                     std::function<void()> on_success) {
  const QString label = title_ + QStringLiteral(": ") + action;
  if (!session_.isOpen()) {
    showStatus(action + QStringLiteral(": not connected -- connect to a robot or the simulator first."), true);
    return;
  }
  if (session_.isReconnecting()) {
    showStatus(action + tr(": not sent -- the connection is being re-established; try again when the status bar "
                           "shows the robot again."),
               true);
    return;
  }
  pending_.push_back({label, std::move(on_success)});
  showStatus(action + QStringLiteral(" ..."), false);
  session_.run(label, std::move(job));
}

void PanelBase::showStatus(const QString& text, bool error, const QString& detail) {
  if (error)
    status_->showError(text);
  else
    status_->showInfo(text);
  status_->setToolTip(detail);
}

void PanelBase::showFailure(const QString& action, const QString& message) {
  const text::OperatorMessage m = text::failure(message, text::viewOf(session_));
  showStatus(tr("%1 failed: %2").arg(action, m.line()), true, message);
}

void PanelBase::addSendWidget(QWidget* widget) {
  send_widgets_.append(widget);
  widget->setEnabled(session_.isOpen() && !session_.isReconnecting());
}

void PanelBase::addMotionWidget(QWidget* widget) {
  motion_widgets_.append(widget);
  motion_widgets_usable_ = session_.isOpen() && !session_.isReconnecting() && !session_.live().stopping;
  widget->setEnabled(motion_widgets_usable_);
}

void PanelBase::updateSendWidgets() {
  const bool usable = session_.isOpen() && !session_.isReconnecting();
  for (auto* w : send_widgets_) w->setEnabled(usable);
  updateMotionWidgets();
}

// Every display tick: only a change of the state touches the widgets.
void PanelBase::updateMotionWidgets() {
  const bool usable = session_.isOpen() && !session_.isReconnecting() && !session_.live().stopping;
  if (usable == motion_widgets_usable_) return;
  motion_widgets_usable_ = usable;
  for (auto* w : motion_widgets_) w->setEnabled(usable);
}

void PanelBase::saveValue(const QString& name, const QVariant& value) const {
  QSettings settings(QStringLiteral("RCI Studio"), QStringLiteral("rci-studio"));
  settings.beginGroup(key_);
  settings.setValue(name, value);
}

QVariant PanelBase::loadValue(const QString& name, const QVariant& fallback) const {
  QSettings settings(QStringLiteral("RCI Studio"), QStringLiteral("rci-studio"));
  settings.beginGroup(key_);
  return settings.value(name, fallback);
}

void PanelBase::saveFields(const QList<QDoubleSpinBox*>& fields) const {
  QSettings settings(QStringLiteral("RCI Studio"), QStringLiteral("rci-studio"));
  settings.beginGroup(key_);
  for (auto* f : fields) settings.setValue(f->objectName(), f->value());
}

void PanelBase::loadFields(const QList<QDoubleSpinBox*>& fields) const {
  QSettings settings(QStringLiteral("RCI Studio"), QStringLiteral("rci-studio"));
  settings.beginGroup(key_);
  for (auto* f : fields) {
    bool ok = false;
    const double v = settings.value(f->objectName()).toDouble(&ok);
    if (ok) f->setValue(v);
  }
}

void PanelBase::refresh(const LiveState&) {}
void PanelBase::sessionOpened() {}
void PanelBase::sessionClosed() {}
void PanelBase::commandDone(const QString&, bool, const QString&) {}

void PanelBase::onCommandFinished(const QString& label, bool ok, const QString& message) {
  const QString prefix = title_ + QStringLiteral(": ");
  if (!label.startsWith(prefix)) return;
  const QString action = label.mid(prefix.size());
  std::function<void()> on_success;
  for (auto it = pending_.begin(); it != pending_.end(); ++it) {
    if (it->label != label) continue;
    on_success = std::move(it->on_success);
    pending_.erase(it);
    break;
  }
  if (ok) {
    showStatus(action + QStringLiteral(": done."), false);
    if (on_success) on_success();
  } else {
    showFailure(action, message);
  }
  commandDone(action, ok, message);
}

}  // namespace rci::ui
