// SPDX-License-Identifier: Apache-2.0
// Lamp: a small round indicator (on/off, with a colour for "on") used by the panels for motor
// power, DI levels, stop states and error bits. Its state is the Qt property "on" (tests read it).
#pragma once

#include <QColor>
#include <QWidget>

namespace rci::ui {

class Lamp : public QWidget {
  Q_OBJECT
  Q_PROPERTY(bool on READ isOn WRITE setOn)
 public:
  explicit Lamp(const QColor& on_color, QWidget* parent = nullptr);
  bool isOn() const { return on_; }
  void setOn(bool on);
  QSize sizeHint() const override;

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  QColor on_color_;
  bool on_ = false;
};

// Colours shared by the panels.
inline QColor lampGreen() { return QColor(46, 170, 70); }
inline QColor lampRed() { return QColor(210, 45, 45); }
inline QColor lampAmber() { return QColor(235, 160, 20); }

}  // namespace rci::ui
