// SPDX-License-Identifier: Apache-2.0
// IO panel: the six digital outputs (switches, setDO) and the six digital inputs (lamps, live).
#pragma once

#include <array>

#include "panels/panel_base.h"

class QCheckBox;

namespace rci::ui {

class Lamp;

class IoPanel : public PanelBase {
  Q_OBJECT
 public:
  IoPanel(Session& session, QWidget* parent);

 protected:
  void refresh(const LiveState& live) override;
  void sessionClosed() override;
  void commandDone(const QString& action, bool ok, const QString& message) override;

 private:
  void setOutput(int index, bool on);

  std::array<QCheckBox*, 6> outputs_{};
  std::array<Lamp*, 6> inputs_{};
  std::array<int, 6> pending_{};  // DO commands of each output not yet answered
};

}  // namespace rci::ui
