// SPDX-License-Identifier: Apache-2.0
// PanelBase: what every dock panel shares -- the session, sending commands through Session::run()
// with the result shown in the panel's status line, settings persistence (QSettings group per
// panel), the robot model in use, and the refresh on each display tick.
#pragma once

#include <QList>
#include <QString>
#include <QVariant>
#include <QWidget>

#include <deque>
#include <functional>

#include <xmate/robot.h>

#include "arm/arm.h"
#include "model/robot_spec.h"

class QAbstractButton;
class QDoubleSpinBox;
class QVBoxLayout;

namespace rci::ui {

class Session;
struct LiveState;
class MessageLine;

class PanelBase : public QWidget {
  Q_OBJECT
 public:
  // key: the settings group and objectName prefix ("power"); title: shown to the user ("Power").
  PanelBase(Session& session, const QString& key, const QString& title, QWidget* parent);
  const QString& key() const { return key_; }
  const QString& title() const { return title_; }
  // Whether the panel applies to the open session: the window hides its dock otherwise (a KUKA has
  // no controller-side safety settings, an xMate no RSI). Default: the arm has every capability
  // given to setNeeds(); panels that need something else (a simulator) override it. GUI thread.
  virtual bool appliesTo(Session& session) const;

 protected:
  // The arm capabilities this panel needs (none by default: it applies to both families).
  void setNeeds(xmate::arm::Capabilities needs) { needs_ = needs; }
  Session& session() const { return session_; }
  // The model of the open session (or of the target about to be opened).
  const xmate::model::RobotSpec& spec() const;
  int dof() const { return spec().dof; }
  bool isOpen() const;

  // The panel's body: add group boxes here; the status line stays at the bottom.
  QVBoxLayout* body() const { return body_; }
  // Queues job on the command worker as "<title>: <action>". The status line says it is pending,
  // then done or why it failed; on success on_success runs on the GUI thread.
  void send(const QString& action, std::function<void(xmate::Robot&)> job, std::function<void()> on_success = {});
  // Shows a line in the status line (errors in red); detail, if any, is its tooltip.
  void showStatus(const QString& text, bool error, const QString& detail = QString());
  // "<action> failed: <what happened and what to press>" for a failed command's message, in
  // operator words (text/operator_text.h); the message itself is the tooltip.
  void showFailure(const QString& action, const QString& message);
  MessageLine* statusLine() const { return status_; }

  // Widgets enabled only while a session is open (buttons that send).
  void addSendWidget(QWidget* widget);
  // Buttons that start a motion or hand guiding: as send widgets, and disabled too while the arm is
  // still coming to rest after a stop (LiveState::stopping).
  void addMotionWidget(QWidget* widget);

  // Settings of this panel (organisation "RCI Studio", application "rci-studio", group key()).
  void saveValue(const QString& name, const QVariant& value) const;
  QVariant loadValue(const QString& name, const QVariant& fallback) const;
  // Each field under its objectName.
  void saveFields(const QList<QDoubleSpinBox*>& fields) const;
  void loadFields(const QList<QDoubleSpinBox*>& fields) const;

  // Hooks: each display tick (session open), after a session opened (model may have changed),
  // after it closed, after a command of this panel finished.
  virtual void refresh(const LiveState& live);
  virtual void sessionOpened();
  virtual void sessionClosed();
  virtual void commandDone(const QString& action, bool ok, const QString& message);

 private:
  void onCommandFinished(const QString& label, bool ok, const QString& message);
  void updateSendWidgets();
  void updateMotionWidgets();

  struct Pending {
    QString label;
    std::function<void()> on_success;
  };
  Session& session_;
  QString key_, title_;
  QVBoxLayout* body_ = nullptr;
  MessageLine* status_ = nullptr;
  QList<QWidget*> send_widgets_;
  QList<QWidget*> motion_widgets_;
  bool motion_widgets_usable_ = false;
  xmate::arm::Capabilities needs_ = 0;
  std::deque<Pending> pending_;
};

}  // namespace rci::ui
