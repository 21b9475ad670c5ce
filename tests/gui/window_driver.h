// SPDX-License-Identifier: Apache-2.0
// WindowDriver: drives widgets of a window by object name the way an operator does -- brings the
// dock that holds a widget to the front, clicks buttons, holds a button down, types a value into a
// field -- for the GUI tests of tests/gui.
#pragma once

#include <QAbstractButton>
#include <QAbstractSpinBox>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QTest>
#include <QWidget>

#include <cmath>

namespace rci::ui::test {

class WindowDriver {
 public:
  explicit WindowDriver(QWidget* root) : root_(root) {}

  template <class T>
  T* find(const QString& name) const {
    T* widget = root_->findChild<T*>(name);
    if (!widget) qWarning("no widget named %s", qPrintable(name));
    return widget;
  }

  // Raises every dock around the widget (docks are tabbed), so it is on screen like for a user.
  static void bringToFront(QWidget* widget) {
    for (QWidget* w = widget; w; w = w->parentWidget())
      if (auto* dock = qobject_cast<QDockWidget*>(w)) {
        dock->show();
        dock->raise();
      }
  }

  // Clicks an enabled button; false (with a warning) when it is missing or disabled.
  bool click(const QString& name) const {
    auto* button = find<QAbstractButton>(name);
    if (!button) return false;
    bringToFront(button);
    if (!button->isEnabled()) {
      qWarning("%s is disabled", qPrintable(name));
      return false;
    }
    QTest::mouseClick(button, Qt::LeftButton, {}, QPoint(button->width() / 2, button->height() / 2));
    return true;
  }

  // Presses a button and keeps it down until release() (hold-to-move buttons such as jog).
  bool press(const QString& name) const {
    auto* button = find<QAbstractButton>(name);
    if (!button || !button->isEnabled()) return false;
    bringToFront(button);
    QTest::mousePress(button, Qt::LeftButton, {}, QPoint(button->width() / 2, button->height() / 2));
    return true;
  }
  void release(const QString& name) const {
    if (auto* button = find<QAbstractButton>(name))
      QTest::mouseRelease(button, Qt::LeftButton, {}, QPoint(button->width() / 2, button->height() / 2));
  }

  // Clicks into a number field, selects its text, types the value and presses Enter.
  bool type(const QString& name, double value) const {
    auto* field = find<QDoubleSpinBox>(name);
    if (!field) return false;
    bringToFront(field);
    QTest::mouseClick(field, Qt::LeftButton, {}, QPoint(8, field->height() / 2));
    field->selectAll();
    QTest::keyClicks(field, QString::number(value, 'f', field->decimals()));
    QTest::keyClick(field, Qt::Key_Enter);
    return qAbs(field->value() - value) <= 0.5 * std::pow(10.0, -field->decimals());
  }

  // Picks the combo box entry whose data is `data` with the keyboard-free path a mouse user takes
  // (the popup's choice ends in setCurrentIndex).
  bool choose(const QString& name, const QVariant& data) const {
    auto* combo = find<QComboBox>(name);
    if (!combo) return false;
    bringToFront(combo);
    const int index = combo->findData(data);
    if (index < 0) return false;
    combo->setCurrentIndex(index);
    return true;
  }

  void check(const QString& name, bool on) const {
    auto* box = find<QCheckBox>(name);
    if (!box) return;
    bringToFront(box);
    if (box->isChecked() != on) QTest::mouseClick(box, Qt::LeftButton, {}, QPoint(6, box->height() / 2));
  }

  QString text(const QString& name) const {
    if (auto* label = root_->findChild<QLabel*>(name)) return label->text();
    if (auto* button = root_->findChild<QAbstractButton*>(name)) return button->text();
    qWarning("no label or button named %s", qPrintable(name));
    return {};
  }

 private:
  QWidget* root_;
};

}  // namespace rci::ui::test
