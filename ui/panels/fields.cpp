// SPDX-License-Identifier: Apache-2.0
// The panels' shared editor pieces: number fields, refusal marks, compact sizes, the inline message line.
#include "panels/fields.h"

#include <QAbstractButton>
#include <QComboBox>


namespace rci::ui {

QDoubleSpinBox* makeNumberField(const QString& name, double min, double max, int decimals, const QString& unit,
                                const QString& tooltip, QWidget* parent) {
  auto* field = new QDoubleSpinBox(parent);
  field->setObjectName(name);
  field->setDecimals(decimals);
  field->setRange(min, max);
  if (!unit.isEmpty()) field->setSuffix(QLatin1Char(' ') + unit);
  field->setToolTip(tooltip);
  field->setAccelerated(true);
  field->setKeyboardTracking(false);
  field->setAlignment(Qt::AlignRight);
  field->setMinimumWidth(90);
  return field;
}

void compactButton(QAbstractButton* button) {
  const int padding = 2 * button->fontMetrics().horizontalAdvance(QLatin1Char('M'));
  button->setMinimumWidth(button->fontMetrics().horizontalAdvance(button->text()) + padding);
}

void compactCombo(QComboBox* combo, int min_chars) {
  combo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  combo->setMinimumContentsLength(min_chars);
}

void markInvalid(QWidget* field, bool invalid) {
  if (!field) return;
  field->setProperty("invalid", invalid);
  field->setStyleSheet(invalid ? QStringLiteral("QAbstractSpinBox { border: 1px solid #d22d2d; "
                                                "background: #fdeaea; }")
                               : QString());
}

void clearInvalid(const QList<QDoubleSpinBox*>& fields) {
  for (auto* f : fields) markInvalid(f, false);
}

MessageLine::MessageLine(const QString& name, QWidget* parent) : QLabel(parent) {
  setObjectName(name);
  setWordWrap(true);
  setTextInteractionFlags(Qt::TextSelectableByMouse);
  clearMessage();
}

void MessageLine::showError(const QString& text) {
  setProperty("kind", QStringLiteral("error"));
  setStyleSheet(QStringLiteral("color: #b02020;"));
  setText(text);
  setVisible(true);
}

void MessageLine::showWarning(const QString& text) {
  setProperty("kind", QStringLiteral("warning"));
  setStyleSheet(QStringLiteral("color: #a06000;"));
  setText(text);
  setVisible(true);
}

void MessageLine::showInfo(const QString& text) {
  setProperty("kind", QStringLiteral("info"));
  setStyleSheet(QString());
  setText(text);
  setVisible(true);
}

void MessageLine::clearMessage() {
  setProperty("kind", QString());
  setText(QString());
  setVisible(false);
}

}  // namespace rci::ui
