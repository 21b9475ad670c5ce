// Safety panel: ESTOP / GSTOP state, the 20 error bits of RobotState by name (active ones
// highlighted, with their remedy), and "Recover errors" (automaticErrorRecovery).
#pragma once

#include <array>
#include <cstdint>

#include "client/error_bits.h"
#include "panels/panel_base.h"

class QLabel;

namespace rci::ui {

class Lamp;

class SafetyPanel : public PanelBase {
  Q_OBJECT
 public:
  SafetyPanel(Session& session, QWidget* parent);

 protected:
  void refresh(const LiveState& live) override;
  void sessionClosed() override;

 private:
  void showErrors(uint32_t mask);

  Lamp* estop_ = nullptr;
  Lamp* gstop_ = nullptr;
  QLabel* mode_ = nullptr;
  std::array<Lamp*, xmate::client::kErrorBitCount> bit_lamps_{};
  std::array<QLabel*, xmate::client::kErrorBitCount> bit_labels_{};
  QLabel* details_ = nullptr;
  uint32_t shown_mask_ = ~0u;
};

}  // namespace rci::ui
