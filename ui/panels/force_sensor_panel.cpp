// SPDX-License-Identifier: Apache-2.0
// Force sensor panel (force_sensor_panel.h): the wrench from LiveState::force (the session's healthy,
// recent readings), the sensor's status word, silence and rate from the client's lock-free getters.
// The zero is this display's own: the sensor and hand guiding are left alone.
#include "panels/force_sensor_panel.h"

#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

#include "ft/netft.h"
#include "net/clock.h"
#include "panels/fields.h"
#include "panels/lamp.h"
#include "session/session.h"

namespace rci::ui {

// A horizontal bar from the centre: right for positive values, left for negative, amber beyond
// full scale. GUI thread.
class WrenchBar : public QWidget {
 public:
  WrenchBar(double full_scale, QWidget* parent) : QWidget(parent), full_scale_(full_scale) {
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
  }
  void setValue(double value, bool valid) {
    if (value == value_ && valid == valid_) return;
    value_ = value;
    valid_ = valid;
    update();
  }
  QSize sizeHint() const override { return {120, fontMetrics().height()}; }
  QSize minimumSizeHint() const override { return {60, fontMetrics().height()}; }

 protected:
  void paintEvent(QPaintEvent*) override {
    QPainter p(this);
    const QRectF r = QRectF(rect()).adjusted(0.5, 2.5, -0.5, -2.5);
    p.setPen(palette().color(QPalette::Mid));
    p.setBrush(palette().color(QPalette::Base));
    p.drawRect(r);
    const double centre = r.center().x();
    p.drawLine(QPointF(centre, r.top()), QPointF(centre, r.bottom()));
    if (!valid_) return;
    const double share = std::clamp(value_ / full_scale_, -1.0, 1.0);
    const bool beyond = std::abs(value_) > full_scale_;
    const double end = centre + share * (r.width() / 2.0);
    p.setPen(Qt::NoPen);
    p.setBrush(beyond ? lampAmber() : QColor(60, 120, 200));
    p.drawRect(QRectF(QPointF(std::min(centre, end), r.top() + 1), QPointF(std::max(centre, end), r.bottom() - 1)));
  }

 private:
  double full_scale_;
  double value_ = 0;
  bool valid_ = false;
};

namespace {

const char* const kNames[6] = {"Fx", "Fy", "Fz", "Tx", "Ty", "Tz"};
const char* const kKeys[6] = {"fx", "fy", "fz", "tx", "ty", "tz"};
constexpr double kForceScale = 100;  // N, the bars' full scale
constexpr double kTorqueScale = 10;  // Nm

QLabel* wrapped(const QString& text, QWidget* parent, const QString& name) {
  auto* label = new QLabel(text, parent);
  label->setWordWrap(true);
  label->setObjectName(name);
  return label;
}

// "17, 31" for the set bits of a status word.
QString setBits(uint32_t word) {
  QStringList bits;
  for (int b = 0; b < 32; ++b)
    if ((word >> b) & 1u) bits << QString::number(b);
  return bits.join(QStringLiteral(", "));
}

}  // namespace

ForceSensorPanel::ForceSensorPanel(Session& session, QWidget* parent)
    : PanelBase(session, QStringLiteral("force"), tr("Force sensor"), parent) {
  auto* top = new QGridLayout;
  lamp_ = new Lamp(lampGreen(), this);
  lamp_->setObjectName(QStringLiteral("force.lamp"));
  lamp_->setToolTip(tr("On while the sensor's readings arrive and it reports no problem"));
  state_ = wrapped(QString(), this, QStringLiteral("force.state"));
  top->addWidget(lamp_, 0, 0, Qt::AlignTop);
  top->addWidget(state_, 0, 1);
  address_ = wrapped(QString(), this, QStringLiteral("force.address"));
  address_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  top->addWidget(address_, 1, 1);
  rate_ = wrapped(QString(), this, QStringLiteral("force.rate"));
  rate_->setToolTip(tr("Readings per second over the last second, and readings lost on the way since connecting"));
  top->addWidget(rate_, 2, 1);
  top->setColumnStretch(1, 1);
  body()->addLayout(top);

  auto* grid = new QGridLayout;
  grid->setVerticalSpacing(2);
  for (int i = 0; i < 6; ++i) {
    const bool force = i < 3;
    auto* name = new QLabel(QLatin1String(kNames[i]), this);
    auto* value = new QLabel(QStringLiteral("-"), this);
    value->setObjectName(QStringLiteral("force.") + QLatin1String(kKeys[i]));
    value->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    value->setMinimumWidth(value->fontMetrics().horizontalAdvance(QStringLiteral("-0000.00 Nm")));
    auto* bar = new WrenchBar(force ? kForceScale : kTorqueScale, this);
    bar->setObjectName(QStringLiteral("force.bar.") + QLatin1String(kKeys[i]));
    const QString tip = force ? tr("%1: force along the sensor's %2 axis, N (the bar spans -%3 to %3 N)")
                                    .arg(QLatin1String(kNames[i]))
                                    .arg(QChar('x' + i))
                                    .arg(kForceScale)
                              : tr("%1: torque about the sensor's %2 axis, Nm (the bar spans -%3 to %3 Nm)")
                                    .arg(QLatin1String(kNames[i]))
                                    .arg(QChar('x' + i - 3))
                                    .arg(kTorqueScale);
    name->setToolTip(tip);
    value->setToolTip(tip);
    bar->setToolTip(tip);
    grid->addWidget(name, i, 0);
    grid->addWidget(value, i, 1);
    grid->addWidget(bar, i, 2);
    values_[size_t(i)] = value;
    bars_[size_t(i)] = bar;
  }
  grid->setColumnStretch(2, 1);
  body()->addLayout(grid);

  auto* buttons = new QHBoxLayout;
  bias_button_ = new QPushButton(tr("Bias (zero)"), this);
  bias_button_->setObjectName(QStringLiteral("force.bias"));
  bias_button_->setToolTip(tr("Make the reading now the zero of this display, e.g. after fitting a tool. Only this "
                              "display changes: hand guiding takes its own zero each time it starts, so keep "
                              "hands off the tool when you start it."));
  clear_button_ = new QPushButton(tr("Clear zero"), this);
  clear_button_->setObjectName(QStringLiteral("force.clearBias"));
  clear_button_->setToolTip(tr("Show the sensor's readings as it sends them again"));
  compactButton(bias_button_);
  compactButton(clear_button_);
  connect(bias_button_, &QPushButton::clicked, this, &ForceSensorPanel::bias);
  connect(clear_button_, &QPushButton::clicked, this, &ForceSensorPanel::clearBias);
  buttons->addWidget(bias_button_);
  buttons->addWidget(clear_button_);
  buttons->addStretch(1);
  body()->addLayout(buttons);
  bias_note_ = wrapped(QString(), this, QStringLiteral("force.biasNote"));
  body()->addWidget(bias_note_);

  if (isOpen())
    sessionOpened();
  else
    sessionClosed();
}

bool ForceSensorPanel::appliesTo(Session& session) const { return session.forceSensor() != nullptr; }

QString ForceSensorPanel::address() const {
  Session& s = session();
  if (s.kukaSimulator() != nullptr) return tr("the built-in simulator's sensor, on this PC");
  QString text = s.target().ft_sensor.trimmed();
  if (!text.isEmpty() && !text.contains(QLatin1Char(':'))) text += QStringLiteral(":%1").arg(xmate::ft::kDefaultPort);
  return text;
}

void ForceSensorPanel::sessionOpened() {
  biased_ = false;
  bias_ = {};
  have_reading_ = false;
  bias_note_->clear();
  if (session().forceSensor() == nullptr) {
    sessionClosed();
    return;
  }
  address_->setText(tr("Sensor: %1").arg(address()));
  state_->setText(tr("Waiting for the sensor's first reading ..."));
  state_->setStyleSheet(QString());
  rate_->clear();
  showValues();
}

void ForceSensorPanel::sessionClosed() {
  lamp_->setOn(false);
  state_->setText(tr("Not connected to a robot with a force sensor."));
  state_->setStyleSheet(QString());
  address_->clear();
  rate_->clear();
  have_reading_ = false;
  biased_ = false;
  bias_ = {};
  bias_note_->clear();
  showValues();
}

void ForceSensorPanel::bias() {
  if (!have_reading_) {
    showStatus(tr("Bias (zero): no reading from the sensor to take as the zero."), true);
    return;
  }
  bias_ = reading_;
  biased_ = true;
  bias_note_->setText(tr("Shown relative to the reading at the zero (Fx %1, Fy %2, Fz %3 N).")
                          .arg(bias_[0], 0, 'f', 1)
                          .arg(bias_[1], 0, 'f', 1)
                          .arg(bias_[2], 0, 'f', 1));
  showStatus(tr("Bias (zero): the reading now is the zero of this display."), false);
  showValues();
}

void ForceSensorPanel::clearBias() {
  biased_ = false;
  bias_ = {};
  bias_note_->clear();
  showStatus(tr("Clear zero: showing the sensor's readings as it sends them."), false);
  showValues();
}

void ForceSensorPanel::showValues() {
  for (size_t i = 0; i < 6; ++i) {
    const double v = reading_[i] - (biased_ ? bias_[i] : 0.0);
    values_[i]->setText(have_reading_ ? (i < 3 ? tr("%1 N").arg(v, 0, 'f', 1) : tr("%1 Nm").arg(v, 0, 'f', 2))
                                      : QStringLiteral("-"));
    values_[i]->setProperty("value", have_reading_ ? QVariant(v) : QVariant());
    bars_[i]->setValue(v, have_reading_);
  }
  bias_button_->setEnabled(have_reading_);
  clear_button_->setEnabled(biased_);
}

void ForceSensorPanel::refresh(const LiveState& live) {
  const xmate::ft::NetFtClient* sensor = session().forceSensor();
  if (sensor == nullptr) return;
  xmate::ft::Wrench newest;
  const bool ever = sensor->latest(newest);
  have_reading_ = live.force_reading;
  if (have_reading_) reading_ = live.force;
  lamp_->setOn(have_reading_);

  QString state;
  bool problem = true;
  const double silent_s = ever ? double(xmate::net::monotonicNs() - newest.received_ns) * 1e-9 : 0.0;
  if (have_reading_) {
    state = tr("Readings arrive.");
    problem = false;
  } else if (ever && newest.status != 0 && silent_s < 0.5) {
    state = tr("The sensor reports a problem (status word 0x%1; bits %2 set), so its readings are not shown. See "
               "the sensor's own web page for what it reports; switching the sensor off and on clears a passing "
               "fault.")
                .arg(newest.status, 8, 16, QLatin1Char('0'))
                .arg(setBits(newest.status));
  } else if (ever) {
    state = tr("No reading from the sensor for %1 s - check its cable and its address (%2), and that it is "
               "switched on.")
                .arg(silent_s, 0, 'f', 1)
                .arg(address());
  } else {
    state = tr("No reading from the sensor since connecting - check its cable and its address (%1), and that it "
               "is switched on.")
                .arg(address());
  }
  state_->setText(state);
  const QString colour = problem ? QStringLiteral("color: #b02020;") : QString();
  if (state_->styleSheet() != colour) state_->setStyleSheet(colour);  // a style sheet re-polishes: only on change

  const xmate::ft::NetFtStatistics stats = sensor->statistics();
  // The rate covers the last whole second: until there is one, the count so far.
  QString rate = stats.rate_hz > 0 ? tr("%1 readings per second, %2 lost").arg(stats.rate_hz, 0, 'f', 0).arg(stats.lost)
                                   : tr("%1 readings, %2 lost").arg(stats.records).arg(stats.lost);
  if (stats.malformed > 0) rate += tr(", %1 unreadable").arg(stats.malformed);
  rate_->setText(rate);
  showValues();
}

}  // namespace rci::ui
