// SPDX-License-Identifier: Apache-2.0
// IO panel: DO switches send setDO through the session; DI lamps show the polled inputs.
#include "panels/io_panel.h"

#include <QCheckBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>

#include <algorithm>
#include <stdexcept>

#include "panels/lamp.h"
#include "session/session.h"

namespace rci::ui {
namespace {

const char* const kSignalNames[6] = {"0_0", "0_1", "0_2", "0_3", "1_0", "1_1"};

}  // namespace

IoPanel::IoPanel(Session& session, QWidget* parent) : PanelBase(session, QStringLiteral("io"), tr("IO"), parent) {
  setNeeds(uint32_t(xmate::arm::Capability::kDigitalIo));
  auto* outs = new QGroupBox(tr("Digital outputs"), this);
  auto* out_grid = new QGridLayout(outs);
  auto* ins = new QGroupBox(tr("Digital inputs"), this);
  auto* in_grid = new QGridLayout(ins);
  for (int i = 0; i < 6; ++i) {
    const QString name = QStringLiteral("DO") + QLatin1String(kSignalNames[i]);
    auto* box = new QCheckBox(name, outs);
    box->setSizePolicy(QSizePolicy::Maximum, QSizePolicy::Fixed);  // the whole widget is clickable
    box->setObjectName(QStringLiteral("io.do%1").arg(i));
    box->setToolTip(tr("Switch output %1").arg(name));
    out_grid->addWidget(box, i / 3, i % 3);
    outputs_[i] = box;
    addSendWidget(box);
    // clicked (not toggled): only the user's clicks send, not the display updates.
    connect(box, &QCheckBox::clicked, this, [this, i](bool on) { setOutput(i, on); });

    const QString in_name = QStringLiteral("DI") + QLatin1String(kSignalNames[i]);
    auto* lamp = new Lamp(lampGreen(), ins);
    lamp->setObjectName(QStringLiteral("io.di%1").arg(i));
    lamp->setToolTip(tr("Level of input %1 (read about 5 times a second)").arg(in_name));
    auto* cell = new QHBoxLayout;  // lamp and name, in the same columns as the outputs
    cell->addWidget(lamp);
    cell->addWidget(new QLabel(in_name, ins), 1);
    in_grid->addLayout(cell, i / 3, i % 3);
    inputs_[i] = lamp;
  }
  for (int c = 0; c < 3; ++c) {
    out_grid->setColumnStretch(c, 1);
    in_grid->setColumnStretch(c, 1);
  }
  body()->addWidget(outs);
  body()->addWidget(ins);
}

void IoPanel::setOutput(int index, bool on) {
  const auto signal = static_cast<RCI::robot::DOSIGNAL>(index);
  const QString name = outputs_[index]->text();
  ++pending_[index];
  send(tr("%1 %2").arg(name, on ? tr("on") : tr("off")),
       [signal, on](xmate::Robot& r) {
         if (!r.setDO(signal, on)) throw std::runtime_error("the controller refused the output change");
       },
       [this, index, on] { session().recordDigitalOutput(index, on); });
}

void IoPanel::commandDone(const QString& action, bool, const QString&) {
  // The switch follows live().digital_out again once no change of that output is outstanding;
  // after a refusal that puts it back where the output really is.
  for (int i = 0; i < 6; ++i)
    if (action.startsWith(outputs_[i]->text() + QLatin1Char(' '))) pending_[i] = std::max(0, pending_[i] - 1);
}

void IoPanel::refresh(const LiveState& live) {
  for (int i = 0; i < 6; ++i) {
    inputs_[i]->setOn(live.digital_in[i]);
    if (pending_[i] == 0) outputs_[i]->setChecked(live.digital_out[i]);
  }
}

void IoPanel::sessionClosed() {
  pending_ = {};
  for (auto* lamp : inputs_) lamp->setOn(false);
}

}  // namespace rci::ui
