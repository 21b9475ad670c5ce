// SPDX-License-Identifier: Apache-2.0
// Filters panel: the three command low-pass cut-offs (setFilters): joint, Cartesian, torque.
// Values outside 10-100 Hz are sent with a warning; outside the allowed range they are refused.
#pragma once

#include <QList>

#include "panels/panel_base.h"

class QDoubleSpinBox;

namespace rci::ui {

class MessageLine;

class FiltersPanel : public PanelBase {
  Q_OBJECT
 public:
  FiltersPanel(Session& session, QWidget* parent);

 private:
  void apply();
  QString recommendationWarning() const;

  QList<QDoubleSpinBox*> fields_;  // joint, Cartesian, torque
  MessageLine* message_ = nullptr;
};

}  // namespace rci::ui
