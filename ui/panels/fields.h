// SPDX-License-Identifier: Apache-2.0
// Small building blocks shared by the panels' editors: number fields with units and tooltips,
// the inline message line that says why a value was refused, the red mark on a refused field, and
// the compact sizes that let rows of buttons and combo boxes fit a narrow dock.
#pragma once

#include <QDoubleSpinBox>
#include <QLabel>
#include <QList>
#include <QString>

#include <string>

class QAbstractButton;
class QComboBox;

namespace rci::ui {

// A number field named name (the objectName tests find it by), range [min, max], unit as suffix.
QDoubleSpinBox* makeNumberField(const QString& name, double min, double max, int decimals, const QString& unit,
                                const QString& tooltip, QWidget* parent);

// Lets a button in a row of several shrink to its text (the style asks at least 80 px otherwise).
void compactButton(QAbstractButton* button);
// Lets a combo box with long entries shrink to about min_chars characters; its list still shows
// the entries in full.
void compactCombo(QComboBox* combo, int min_chars);

// Marks a field as refused (red frame) or clears the mark.
void markInvalid(QWidget* field, bool invalid);
void clearInvalid(const QList<QDoubleSpinBox*>& fields);

// The line under an editor: empty, an error (why a value was refused) or a warning (sent anyway).
class MessageLine : public QLabel {
  Q_OBJECT
 public:
  MessageLine(const QString& name, QWidget* parent);
  void showError(const QString& text);
  void showWarning(const QString& text);
  void showInfo(const QString& text);
  void clearMessage();
  // "error", "warning", "info" or "" (tests read the property "kind").
  QString kind() const { return property("kind").toString(); }
};

// Degrees <-> radians.
inline constexpr double kDegPerRad = 57.295779513082320876798;

}  // namespace rci::ui
