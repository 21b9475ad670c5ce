// SPDX-License-Identifier: Apache-2.0
// RSI panel (rsi_panel.h): the RSI session's state from LiveState::rsi, the context and Ethernet
// config from Session::rsiArm(), the start pose from its joint stream, the technology values from
// the link's newest <Rob>. Everything is read on the GUI thread through lock-free getters.
#include "panels/rsi_panel.h"

#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QHeaderView>
#include <QLabel>
#include <QEvent>
#include <QRegularExpression>
#include <QToolButton>
#include <QTreeWidget>
#include <QTreeWidgetItemIterator>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <map>

#include "arm/rsi_arm.h"
#include "panels/fields.h"
#include "panels/lamp.h"
#include "rsi/codec.h"
#include "rsi/config.h"
#include "arm/joint_stream.h"
#include "rsi/link.h"
#include "rsi/session_monitor.h"
#include "session/session.h"

namespace rci::ui {
namespace {

QLabel* wrapped(const QString& text, QWidget* parent, const QString& name = QString()) {
  auto* label = new QLabel(text, parent);
  label->setWordWrap(true);
  if (!name.isEmpty()) label->setObjectName(name);
  return label;
}

QString qs(const std::string& s) { return QString::fromStdString(s); }

// Degrees as the operator typed them in RSI Visual (no float noise: 90, -2.5).
QString degrees(double rad) {
  const double deg = std::round(rad * kDegPerRad * 1e4) / 1e4;
  return QString::number(deg, 'g', 8) + QChar(0x00B0);
}

// A context's parameters in a few lines: runs such as LowerLimA1..LowerLimA6 with one value become
// "LowerLimA1-6 = -90".
QStringList condensedParameters(const xmate::rsi::Object& object) {
  static const QRegularExpression numbered(QStringLiteral("^(.*\\D)(\\d+)$"));
  QStringList out;
  const auto& params = object.parameters;
  for (size_t i = 0; i < params.size();) {
    const QString name = qs(params[i].name);
    const QString value = qs(params[i].value);
    const QRegularExpressionMatch m = numbered.match(name);
    size_t j = i + 1;
    if (m.hasMatch()) {
      const QString stem = m.captured(1);
      int last = m.captured(2).toInt();
      while (j < params.size()) {
        const QRegularExpressionMatch n = numbered.match(qs(params[j].name));
        if (!n.hasMatch() || n.captured(1) != stem || n.captured(2).toInt() != last + 1 || qs(params[j].value) != value)
          break;
        last = n.captured(2).toInt();
        ++j;
      }
      if (j - i > 1) {
        out << QStringLiteral("%1%2-%3 = %4").arg(stem, m.captured(2)).arg(last).arg(value);
        i = j;
        continue;
      }
    }
    out << QStringLiteral("%1 = %2").arg(name, value);
    i = j;
  }
  return out;
}

// "GEARTORQUE1 (6), STATUS1, DIGIN1 (8)": which objects feed this one, in wiring order.
QString feeders(const xmate::rsi::Object& object) {
  QStringList order;
  std::map<QString, int> count;
  for (const xmate::rsi::Input& in : object.inputs) {
    const QString from = qs(in.out_object);
    if (count[from]++ == 0) order << from;
  }
  QStringList parts;
  for (const QString& from : order)
    parts << (count[from] > 1 ? QStringLiteral("%1 (%2)").arg(from).arg(count[from]) : from);
  return parts.join(QStringLiteral(", "));
}

// Sizes a tree to its visible rows, so that it never scrolls inside the dock's own scroll area.
void fitHeight(QTreeWidget* tree) {
  int rows = 0;
  for (QTreeWidgetItemIterator it(tree); *it; ++it) {
    bool visible = true;
    for (QTreeWidgetItem* p = (*it)->parent(); p != nullptr; p = p->parent())
      if (!p->isExpanded()) {
        visible = false;
        break;
      }
    if (visible) ++rows;
  }
  const int hinted = tree->topLevelItemCount() > 0 ? tree->sizeHintForRow(0) : -1;  // uniform row heights
  const int row = hinted > 0 ? hinted : tree->fontMetrics().height() + 4;
  const int header = tree->isHeaderHidden() ? 0 : tree->header()->sizeHint().height();
  tree->setFixedHeight(std::max(1, rows) * row + header + 2 * tree->frameWidth() + 4);
}

// A tree that sizes itself again when it is shown or its font or style changes (a tree in a hidden
// section or dock is not polished yet: its rows' height is known only once it shows).
class FittedTree : public QTreeWidget {
 public:
  using QTreeWidget::QTreeWidget;

 protected:
  void showEvent(QShowEvent* event) override {
    QTreeWidget::showEvent(event);
    fitHeight(this);
  }
  void changeEvent(QEvent* event) override {
    QTreeWidget::changeEvent(event);
    if (event->type() == QEvent::FontChange || event->type() == QEvent::StyleChange) fitHeight(this);
  }
};

QTreeWidget* makeTree(const QStringList& headers, const QString& name, QWidget* parent) {
  auto* tree = new FittedTree(parent);
  tree->setObjectName(name);
  tree->setColumnCount(int(headers.size()));
  tree->setHeaderLabels(headers);
  tree->setUniformRowHeights(true);
  tree->setRootIsDecorated(true);
  tree->setSelectionMode(QAbstractItemView::NoSelection);
  tree->setFocusPolicy(Qt::NoFocus);
  tree->setEditTriggers(QAbstractItemView::NoEditTriggers);
  tree->setTextElideMode(Qt::ElideRight);
  tree->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  tree->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  tree->header()->setStretchLastSection(true);
  tree->header()->setSectionsMovable(false);
  tree->setMinimumWidth(200);
  QObject::connect(tree, &QTreeWidget::itemExpanded, tree, [tree] { fitHeight(tree); });
  QObject::connect(tree, &QTreeWidget::itemCollapsed, tree, [tree] { fitHeight(tree); });
  return tree;
}

const char* const kAxes[6] = {"A1", "A2", "A3", "A4", "A5", "A6"};

}  // namespace

RsiPanel::RsiPanel(Session& session, QWidget* parent) : PanelBase(session, QStringLiteral("rsi"), tr("RSI"), parent) {
  addSection(QStringLiteral("state"), tr("Session"), makeState(), true);
  addSection(QStringLiteral("limits"), tr("Correction limits and start pose"), makeLimits(), true);
  addSection(QStringLiteral("files"), tr("Files and address"), makeFiles(), true);
  addSection(QStringLiteral("objects"), tr("Context objects"), makeObjects(), true);
  addSection(QStringLiteral("channels"), tr("Values exchanged each cycle"), makeChannels(), false);
  addSection(QStringLiteral("tech"), tr("Technology values and messages"), makeTech(), true);
  if (isOpen())
    sessionOpened();
  else
    sessionClosed();
}

bool RsiPanel::appliesTo(Session& session) const { return session.rsiArm() != nullptr; }

QWidget* RsiPanel::addSection(const QString& name, const QString& title, QWidget* content, bool open_by_default) {
  auto* section = new QWidget(this);
  auto* layout = new QVBoxLayout(section);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(2);
  auto* header = new QToolButton(section);
  header->setObjectName(QStringLiteral("rsi.section.") + name);
  header->setText(title);
  header->setCheckable(true);
  header->setAutoRaise(true);
  header->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
  header->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
  header->setToolTip(tr("Show or hide this section"));
  QFont font = header->font();
  font.setBold(true);
  header->setFont(font);
  layout->addWidget(header);
  content->setParent(section);
  content->setContentsMargins(14, 0, 0, 4);
  layout->addWidget(content);
  auto show = [header, content](bool open) {
    header->setArrowType(open ? Qt::DownArrow : Qt::RightArrow);
    content->setVisible(open);
  };
  const bool open = loadValue(QStringLiteral("open.") + name, open_by_default).toBool();
  header->setChecked(open);
  show(open);
  connect(header, &QToolButton::toggled, this, [this, name, show](bool on) {
    show(on);
    saveValue(QStringLiteral("open.") + name, on);
  });
  body()->addWidget(section);
  if (name == QLatin1String("objects")) objects_header_ = header;
  return section;
}

QWidget* RsiPanel::makeState() {
  auto* box = new QWidget(this);
  auto* grid = new QGridLayout(box);
  grid->setContentsMargins(0, 0, 0, 0);
  grid->setVerticalSpacing(3);
  lamp_ = new Lamp(lampGreen(), box);
  lamp_->setObjectName(QStringLiteral("rsi.lamp"));
  lamp_->setToolTip(tr("On while the robot runs RSI and sends to this PC every cycle"));
  state_ = wrapped(QString(), box, QStringLiteral("rsi.state"));
  grid->addWidget(lamp_, 0, 0, Qt::AlignTop);
  grid->addWidget(state_, 0, 1, 1, 2);
  int row = 1;
  auto addRow = [&](const QString& title, const QString& name, const QString& tip) {
    auto* caption = wrapped(title, box);
    auto* value = new QLabel(box);
    value->setObjectName(name);
    value->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    caption->setToolTip(tip);
    value->setToolTip(tip);
    grid->addWidget(caption, row, 1);
    grid->addWidget(value, row, 2);
    ++row;
    return value;
  };
  cycle_ = addRow(tr("Cycle"), QStringLiteral("rsi.cycle"),
                  tr("How often the robot sends its values and waits for this PC's answer (4 ms or 12 ms), "
                     "as the robot's clock shows it"));
  delay_ = addRow(tr("Late answers the robot counted (Delay)"), QStringLiteral("rsi.delay"),
                  tr("Answers of this PC that reached the robot too late in this RSI session, as the robot counts "
                     "them"));
  in_a_row_ = addRow(tr("Late in a row"), QStringLiteral("rsi.inARow"),
                     tr("Late answers in a row, against the number at which the robot stops RSI (its ETHERNET "
                        "object's Timeout)"));
  late_answers_ = addRow(tr("Answers this PC sent late"), QStringLiteral("rsi.lateAnswers"),
                         tr("Answers this PC sent more than a cycle after the robot's values arrived, in this RSI "
                            "session"));
  answer_p99_ = addRow(tr("Answer time (99 % within)"), QStringLiteral("rsi.answerP99"),
                       tr("How long this PC took to answer, over the last 250 cycles: 99 % of the answers were "
                          "sent within this time. It must stay well under the cycle."));
  refused_ = wrapped(QString(), box, QStringLiteral("rsi.refused"));
  refused_->setStyleSheet(QStringLiteral("color: #b02020;"));
  refused_->hide();
  grid->addWidget(refused_, row, 1, 1, 2);
  grid->setColumnStretch(1, 1);
  return box;
}

QWidget* RsiPanel::makeFiles() {
  auto* box = new QWidget(this);
  auto* form = new QFormLayout(box);
  form->setContentsMargins(0, 0, 0, 0);
  form->setRowWrapPolicy(QFormLayout::WrapLongRows);
  context_file_ = wrapped(QString(), box, QStringLiteral("rsi.contextFile"));
  context_file_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  config_file_ = wrapped(QString(), box, QStringLiteral("rsi.configFile"));
  config_file_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  listen_ = wrapped(QString(), box, QStringLiteral("rsi.listen"));
  listen_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  form->addRow(tr("RSI context:"), context_file_);
  form->addRow(tr("Ethernet config:"), config_file_);
  form->addRow(tr("This PC listens on:"), listen_);
  return box;
}

QWidget* RsiPanel::makeLimits() {
  auto* box = new QWidget(this);
  auto* layout = new QVBoxLayout(box);
  layout->setContentsMargins(0, 0, 0, 0);
  limits_note_ = wrapped(tr("How far this PC may move each axis from where RSI was switched on, as set in the "
                            "context (RSI Visual); the robot holds an axis at its limit."),
                         box, QStringLiteral("rsi.limitsNote"));
  layout->addWidget(limits_note_);
  auto* grid = new QGridLayout;
  grid->setHorizontalSpacing(10);
  grid->setVerticalSpacing(1);
  const QStringList headers = {tr("Axis"), tr("Lower"), tr("Upper"), tr("At RSI start")};
  for (int c = 0; c < headers.size(); ++c) {
    auto* h = new QLabel(QStringLiteral("<b>%1</b>").arg(headers[c]), box);
    h->setAlignment(c == 0 ? Qt::AlignLeft : Qt::AlignRight);
    grid->addWidget(h, 0, c);
  }
  grid->itemAtPosition(0, 3)->widget()->setToolTip(
      tr("Where each axis was when RSI was switched on: the corrections and their limits count from here"));
  for (int i = 0; i < 6; ++i) {
    grid->addWidget(new QLabel(QLatin1String(kAxes[i]), box), i + 1, 0);
    auto make = [&](const QString& name, int column) {
      auto* label = new QLabel(QStringLiteral("-"), box);
      label->setObjectName(name.arg(i + 1));
      label->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
      grid->addWidget(label, i + 1, column);
      return label;
    };
    lower_[size_t(i)] = make(QStringLiteral("rsi.lower%1"), 1);
    upper_[size_t(i)] = make(QStringLiteral("rsi.upper%1"), 2);
    start_[size_t(i)] = make(QStringLiteral("rsi.start%1"), 3);
  }
  grid->setColumnStretch(1, 1);
  grid->setColumnStretch(2, 1);
  grid->setColumnStretch(3, 1);
  layout->addLayout(grid);
  timeout_ = wrapped(QString(), box, QStringLiteral("rsi.timeout"));
  layout->addWidget(timeout_);
  return box;
}

QWidget* RsiPanel::makeObjects() {
  objects_ = makeTree({tr("Object"), tr("Type"), tr("Settings")}, QStringLiteral("rsi.objects"), this);
  objects_->setToolTip(tr("The RSI context's objects, as in RSI Visual; open one for all its settings"));
  return objects_;
}

QWidget* RsiPanel::makeChannels() {
  channels_ = makeTree({tr("Value"), tr("Type"), tr("Channel")}, QStringLiteral("rsi.channels"), this);
  channels_->setToolTip(tr("What the robot sends to this PC and what this PC answers, each cycle, as the "
                           "Ethernet config lists them"));
  return channels_;
}

QWidget* RsiPanel::makeTech() {
  auto* box = new QWidget(this);
  auto* layout = new QVBoxLayout(box);
  layout->setContentsMargins(0, 0, 0, 0);
  tech_ = wrapped(QString(), box, QStringLiteral("rsi.tech"));
  tech_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  messages_ = wrapped(QString(), box, QStringLiteral("rsi.messages"));
  layout->addWidget(tech_);
  layout->addWidget(messages_);
  return box;
}

void RsiPanel::sessionOpened() {
  xmate::arm::RsiArm* arm = session().rsiArm();
  if (arm == nullptr) {
    sessionClosed();
    return;
  }
  showFiles(*arm);
  showLimits(*arm);
  showObjects(*arm);
  showChannels(*arm);
  shown_tech_.clear();
  showTech(*arm, session().live());
  state_->setText(tr("Waiting for the robot ..."));
}

void RsiPanel::sessionClosed() {
  lamp_->setOn(false);
  state_->setText(tr("Not connected to a KUKA robot."));
  state_->setStyleSheet(QString());
  for (QLabel* l : {cycle_, delay_, in_a_row_, late_answers_, answer_p99_}) l->setText(QStringLiteral("-"));
  refused_->hide();
  context_file_->clear();
  config_file_->clear();
  listen_->clear();
  for (size_t i = 0; i < 6; ++i) {
    lower_[i]->setText(QStringLiteral("-"));
    upper_[i]->setText(QStringLiteral("-"));
    start_[i]->setText(QStringLiteral("-"));
  }
  timeout_->clear();
  objects_->clear();
  channels_->clear();
  fitHeight(objects_);
  fitHeight(channels_);
  objects_header_->setText(tr("Context objects"));
  tech_->clear();
  messages_->clear();
  shown_tech_.clear();
}

void RsiPanel::showFiles(xmate::arm::RsiArm& arm) {
  const QFileInfo context(qs(arm.context().path));
  context_file_->setText(context.fileName());
  context_file_->setToolTip(context.absoluteFilePath());
  const xmate::rsi::EthernetConfig& config = arm.ethernetConfig();
  const QFileInfo file(qs(config.path));
  config_file_->setText(file.fileName());
  config_file_->setToolTip(file.absoluteFilePath());

  const xmate::rsi::LinkOptions& options = arm.link().options();
  QString ip = qs(options.bind_ip);
  if (ip.isEmpty()) ip = config.ip_is_placeholder ? tr("every address of this PC") : qs(config.ip);
  const uint16_t port = arm.link().port();
  QString text = QStringLiteral("%1, port %2").arg(ip).arg(port);
  const QString named = config.ip_is_placeholder ? QString() : qs(config.ip);
  if ((!named.isEmpty() && named != ip) || port != config.port)
    text += tr(" (the Ethernet config names %1, port %2)")
                .arg(named.isEmpty() ? tr("any address") : named)
                .arg(config.port);
  QStringList facts;
  facts << tr("Datagram type: %1").arg(qs(config.sentype));
  if (config.only_send) facts << tr("The robot expects no answers (ONLYSEND)");
  listen_->setText(text);
  listen_->setToolTip(facts.join(QLatin1Char('\n')));
}

void RsiPanel::showLimits(xmate::arm::RsiArm& arm) {
  const xmate::rsi::AxisCorrectionLimits& limits = arm.stream().limits();
  for (size_t i = 0; i < 6; ++i) {
    lower_[i]->setText(degrees(limits.lower[i]));
    upper_[i]->setText(degrees(limits.upper[i]));
    lower_[i]->setToolTip(tr("Set by %1").arg(qs(limits.lower_by[i])));
    upper_[i]->setToolTip(tr("Set by %1").arg(qs(limits.upper_by[i])));
    start_[i]->setText(QStringLiteral("-"));
  }
  int timeout = 100;
  QString by = tr("the ETHERNET object's Timeout");
  if (const xmate::rsi::Object* ethernet = arm.context().ethernet()) {
    by = tr("%1's Timeout").arg(qs(ethernet->id));
    try {
      timeout = int(xmate::rsi::numberParameter(arm.context(), *ethernet, "Timeout", 100));
    } catch (const std::exception&) {
    }
  }
  timeout_->setText(tr("The robot stops RSI after %1 late answers in a row (%2).").arg(timeout).arg(by));
}

void RsiPanel::showObjects(xmate::arm::RsiArm& arm) {
  objects_->clear();
  const xmate::rsi::Context& context = arm.context();
  const QString file = QFileInfo(qs(context.path)).fileName();
  for (const xmate::rsi::Object& object : context.objects) {
    const QStringList params = condensedParameters(object);
    auto* item = new QTreeWidgetItem(objects_, {qs(object.id), qs(object.type), params.join(QStringLiteral(", "))});
    QStringList tip;
    tip << QStringLiteral("%1 (%2), %3 line %4").arg(qs(object.id), qs(object.type), file).arg(object.line);
    tip << params;
    const QString fed = feeders(object);
    if (!fed.isEmpty()) tip << tr("Inputs from %1").arg(fed);
    for (int c = 0; c < 3; ++c) item->setToolTip(c, tip.join(QLatin1Char('\n')));
    for (const QString& p : params) {
      auto* child = new QTreeWidgetItem(item, {p});
      child->setFirstColumnSpanned(true);
      child->setToolTip(0, p);
    }
    if (!fed.isEmpty()) {
      auto* child = new QTreeWidgetItem(item, {tr("Inputs from %1").arg(fed)});
      child->setFirstColumnSpanned(true);
      child->setToolTip(0, child->text(0));
    }
  }
  for (int c = 0; c < 2; ++c) objects_->resizeColumnToContents(c);
  objects_header_->setText(tr("Context objects (%1)").arg(context.objects.size()));
  fitHeight(objects_);
}

void RsiPanel::showChannels(xmate::arm::RsiArm& arm) {
  channels_->clear();
  const xmate::rsi::EthernetConfig& config = arm.ethernetConfig();
  auto addGroup = [this](const QString& title, const QString& tip, const std::vector<xmate::rsi::Channel>& channels,
                         bool receive) {
    auto* group = new QTreeWidgetItem(channels_, {title.arg(channels.size())});
    group->setFirstColumnSpanned(true);
    group->setToolTip(0, tip);
    for (const xmate::rsi::Channel& c : channels) {
      const QString index = c.internal() ? tr("built in") : QString::number(c.index);
      auto* item = new QTreeWidgetItem(group, {qs(c.tag), QLatin1String(xmate::rsi::toString(c.type)), index});
      QString item_tip = tr("%1, line %2 of the Ethernet config").arg(qs(c.tag)).arg(c.line);
      if (!c.internal())
        item_tip += receive ? tr("\nGoes to output %1 of the ETHERNET object").arg(c.index)
                            : tr("\nComes from input %1 of the ETHERNET object").arg(c.index);
      if (receive && c.hold_on) item_tip += tr("\nThe robot keeps its last value when an answer is late");
      for (int col = 0; col < 3; ++col) item->setToolTip(col, item_tip);
    }
    group->setExpanded(true);
  };
  addGroup(tr("From the robot (%1)"), tr("What the robot sends to this PC each cycle (the config's SEND)"),
           config.send, false);
  addGroup(tr("To the robot (%1)"), tr("What this PC answers each cycle (the config's RECEIVE)"), config.receive, true);
  for (int c = 0; c < 3; ++c) channels_->resizeColumnToContents(c);
  fitHeight(channels_);

  // Messages: RSI carries text only from the PC to the smartPAD (DEF_EStr) and in STRING values.
  QStringList lines;
  const bool estr = std::any_of(config.receive.begin(), config.receive.end(),
                                [](const xmate::rsi::Channel& c) { return c.element == "EStr"; });
  if (estr)
    lines << tr("Messages to the smartPAD (DEF_EStr): the Ethernet config lets this PC send one; this window sends "
                "none.");
  QStringList texts;
  for (const xmate::rsi::Channel& c : config.send)
    if (c.type == xmate::rsi::ValueType::kString) texts << qs(c.tag);
  if (!texts.isEmpty())
    lines << tr("The robot sends text in %1; this window cannot show text values.")
                 .arg(texts.join(QStringLiteral(", ")));
  lines << tr("The robot's own messages (RSI stopped, a limit reached) show on its smartPAD, not here.");
  messages_->setText(lines.join(QLatin1Char('\n')));
}

// DEF_Tech: C1x the robot sends (read from its newest values), T2x this PC sends (the link does not
// report them back; the built-in simulator says what it received).
void RsiPanel::showTech(xmate::arm::RsiArm& arm, const LiveState& live) {
  const xmate::rsi::EthernetConfig& config = arm.ethernetConfig();
  QStringList lines;
  xmate::rsi::RobSample rob;
  const bool have_rob = arm.link().latest(rob);
  for (const xmate::rsi::Channel& c : config.send) {
    if (c.element != "Tech") continue;
    QStringList values;
    for (const std::string& a : xmate::rsi::builtInAttributes(c)) {
      const int slot = arm.link().slot("Tech", a);
      const bool known = have_rob && slot >= 0 && size_t(slot) < rob.count;
      values << QStringLiteral("%1 %2").arg(qs(a), known ? QString::number(rob.values[size_t(slot)], 'g', 6)
                                                         : QStringLiteral("-"));
    }
    lines << tr("From the robot (%1): %2").arg(qs(c.tag), values.join(QStringLiteral(", ")));
  }
  for (const xmate::rsi::Channel& c : config.receive) {
    if (c.element != "Tech") continue;
    if (live.kuka_simulated && (c.attribute.empty() || c.attribute == "T2")) {
      QStringList values;
      for (size_t k = 0; k < live.krc.tech_t2.size(); ++k)
        values << QStringLiteral("T2%1 %2").arg(k + 1).arg(live.krc.tech_t2[k], 0, 'g', 6);
      lines << tr("To the robot (%1), as the simulated controller received them: %2")
                   .arg(qs(c.tag), values.join(QStringLiteral(", ")));
    } else {
      lines << tr("To the robot (%1): this window cannot show what this PC sends in them.").arg(qs(c.tag));
    }
  }
  if (lines.isEmpty()) lines << tr("The Ethernet config exchanges no technology values (DEF_Tech).");
  const QString text = lines.join(QLatin1Char('\n'));
  if (text == shown_tech_) return;
  shown_tech_ = text;
  tech_->setText(text);
}

void RsiPanel::refresh(const LiveState& live) {
  xmate::arm::RsiArm* arm = session().rsiArm();
  if (arm == nullptr) return;
  const xmate::rsi::SessionStatus& s = live.rsi;
  lamp_->setOn(s.phase == xmate::rsi::SessionPhase::kRunning);
  state_->setText(qs(xmate::rsi::describe(s)));
  const QString colour = s.phase == xmate::rsi::SessionPhase::kStopped ? QStringLiteral("color: #b02020;") : QString();
  if (state_->styleSheet() != colour) state_->setStyleSheet(colour);  // a style sheet re-polishes: only on change
  const bool seen = s.phase != xmate::rsi::SessionPhase::kWaiting || s.session > 0;
  cycle_->setText(s.cycle_ms > 0 ? tr("%1 ms").arg(s.cycle_ms) : QStringLiteral("-"));
  delay_->setText(seen ? QString::number(s.delay, 'g', 12) : QStringLiteral("-"));
  in_a_row_->setText(seen ? tr("%1 of %2").arg(s.late_in_a_row).arg(s.timeout) : QStringLiteral("-"));
  late_answers_->setText(seen ? QString::number(s.late_answers) : QStringLiteral("-"));
  answer_p99_->setText(s.answer_p99_ms > 0 ? tr("%1 ms").arg(s.answer_p99_ms, 0, 'f', 2) : QStringLiteral("-"));

  const xmate::rsi::LinkCounters counters = arm->link().counters();
  if (counters.rejected > 0) {
    refused_->setText(tr("%1 datagrams from the robot could not be read (the last: %2). Check that the robot runs "
                         "this context and Ethernet config.")
                          .arg(counters.rejected)
                          .arg(QString::fromUtf8(arm->link().lastReason())));
    refused_->show();
  } else {
    refused_->hide();
  }

  xmate::arm::StreamState stream;
  const bool have = arm->stream().state(stream) && stream.session > 0;
  for (size_t i = 0; i < 6; ++i)
    start_[i]->setText(have ? QStringLiteral("%1%2").arg(stream.q_on[i] * kDegPerRad, 0, 'f', 1).arg(QChar(0x00B0))
                            : QStringLiteral("-"));
  showTech(*arm, live);
}

}  // namespace rci::ui
