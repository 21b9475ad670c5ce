// SPDX-License-Identifier: Apache-2.0
// Banner: a non-modal message strip above the 3D view (connection failures, refused input), with
// a close button. Never blocks the window like a modal dialog would.
#pragma once

#include <QFrame>

class QLabel;

namespace rci::ui {

class Banner : public QFrame {
  Q_OBJECT
 public:
  explicit Banner(QWidget* parent = nullptr);
  void showError(const QString& text);
  QString text() const;

 private:
  QLabel* label_ = nullptr;
};

}  // namespace rci::ui
