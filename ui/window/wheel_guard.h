// SPDX-License-Identifier: Apache-2.0
// The scroll-wheel guard: the wheel scrolls the panel under the pointer instead of changing a spin
// box, slider or combo box the user has not clicked into (once it has the focus, the wheel works on it).
#pragma once

#include <QObject>

class QWheelEvent;
class QWidget;

namespace rci::ui {

// An application-wide event filter. Spin boxes, sliders (not scroll bars) and combo boxes get
// Qt::StrongFocus instead of Qt::WheelFocus, so a wheel turn over them no longer focuses them; a
// wheel event over one without the focus goes to the enclosing scroll areas instead.
class WheelGuard : public QObject {
  Q_OBJECT
 public:
  explicit WheelGuard(QObject* parent = nullptr);
  bool eventFilter(QObject* watched, QEvent* event) override;
};

// Installs one WheelGuard on the application (again: no effect) and fixes the focus policy of the
// widgets that already exist. Call after the QApplication is made.
void installWheelGuard();

// The spin box, slider or combo box that w is (or is part of), or nullptr.
QWidget* wheelGuardedWidget(QWidget* w);

}  // namespace rci::ui
