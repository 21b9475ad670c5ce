// SPDX-License-Identifier: Apache-2.0
// Lamp: painting of the round indicator.
#include "panels/lamp.h"

#include <QPainter>

namespace rci::ui {

Lamp::Lamp(const QColor& on_color, QWidget* parent) : QWidget(parent), on_color_(on_color) {
  setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
}

void Lamp::setOn(bool on) {
  if (on == on_) return;
  on_ = on;
  update();
}

QSize Lamp::sizeHint() const { return {14, 14}; }

void Lamp::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  const QColor fill = on_ ? on_color_ : palette().color(QPalette::Window).darker(125);
  p.setPen(QPen(fill.darker(150), 1));
  p.setBrush(fill);
  const int d = qMin(width(), height()) - 2;
  p.drawEllipse(QRectF((width() - d) / 2.0, (height() - d) / 2.0, d, d));
}

}  // namespace rci::ui
