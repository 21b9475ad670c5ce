// MessageLog: the Messages dock -- session events and failed commands, each with a time stamp;
// failures in red. Connects itself to a Session.
#pragma once

#include <QWidget>

class QListWidget;

namespace rci::ui {

class Session;

class MessageLog : public QWidget {
  Q_OBJECT
 public:
  MessageLog(Session& session, QWidget* parent = nullptr);

  void addInfo(const QString& text);
  void addError(const QString& text);
  int count() const;
  QString text(int row) const;

 private:
  void add(const QString& text, bool error);
  QListWidget* list_ = nullptr;
};

}  // namespace rci::ui
