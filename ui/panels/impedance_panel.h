// SPDX-License-Identifier: Apache-2.0
// Impedance panel: joint stiffness (setJointImpedance), Cartesian stiffness (setCartesianImpedance)
// and the desired wrench of Cartesian impedance mode (setCartImpDesiredTau).
#pragma once

#include <QList>
#include <QString>

#include <array>
#include <string>

#include "model/parameter_checks.h"
#include "panels/panel_base.h"

class QDoubleSpinBox;
class QGroupBox;
class QLabel;

namespace rci::ui {

class MessageLine;

class ImpedancePanel : public PanelBase {
  Q_OBJECT
 public:
  ImpedancePanel(Session& session, QWidget* parent);

 protected:
  void sessionOpened() override;

 private:
  // One editor group: its fields, message line and Apply button.
  struct Editor {
    QList<QDoubleSpinBox*> fields;
    QList<QLabel*> labels;
    MessageLine* message = nullptr;
  };
  QGroupBox* makeEditor(Editor& editor, const QString& title, const QString& prefix, const QStringList& labels,
                        double min, double max, const QStringList& units, const QString& apply_tip);
  // Shows the check result on the editor; true when the values may be sent.
  // Marks the refused field and says why (false), or clears the marks and saves the fields (true).
  bool accept(Editor& editor, const xmate::model::ParameterProblem& error);
  void showModel();
  void applyJoint();
  void applyCartesian();
  void applyWrench();

  Editor joint_, cartesian_, wrench_;
};

}  // namespace rci::ui
