// SPDX-License-Identifier: Apache-2.0
// Program panel: layout, recording waypoints (button, F9, DI trigger; C takes via then target; P
// starts and stops the recording of a path: program_panel_path.cpp), and editing the instruction
// list (reorder, delete, duplicate, type, speed, name, touch-up, logic insert/apply).
#include "panels/program_panel.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QEvent>
#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QSlider>
#include <QSpinBox>
#include <QStyledItemDelegate>
#include <QTableView>
#include <QVBoxLayout>

#include "panels/fields.h"
#include "panels/program_model.h"
#include "session/session.h"
#include "teach/program_io.h"
#include "teach/preflight.h"
#include "teach/recording.h"
#include "text/operator_text.h"

namespace rci::ui {

using xmate::teach::Instruction;
using xmate::teach::InstructionType;

namespace {

// Record types of the Teach group (combo data).
enum RecordKind { kRecordJ, kRecordL, kRecordC, kRecordPath };

// Type column: a combo with the types the instruction may become.
class TypeDelegate : public QStyledItemDelegate {
 public:
  using QStyledItemDelegate::QStyledItemDelegate;
  QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem&, const QModelIndex& index) const override {
    auto* model = qobject_cast<const ProgramModel*>(index.model());
    if (!model) return nullptr;
    const Instruction& in = model->instruction(index.row());
    auto* combo = new QComboBox(parent);
    for (auto t : {InstructionType::kMoveJ, InstructionType::kMoveL, InstructionType::kMoveC})
      if (t == in.type || ProgramModel::canChangeType(in, t)) combo->addItem(QLatin1String(xmate::teach::typeName(t)));
    return combo;
  }
  void setEditorData(QWidget* editor, const QModelIndex& index) const override {
    auto* combo = static_cast<QComboBox*>(editor);
    combo->setCurrentText(index.data(Qt::EditRole).toString());
  }
  void setModelData(QWidget* editor, QAbstractItemModel* model, const QModelIndex& index) const override {
    model->setData(index, static_cast<QComboBox*>(editor)->currentText(), Qt::EditRole);
  }
};

// Speed column: 1..100 %.
class SpeedDelegate : public QStyledItemDelegate {
 public:
  using QStyledItemDelegate::QStyledItemDelegate;
  QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem&, const QModelIndex&) const override {
    auto* spin = new QSpinBox(parent);
    spin->setRange(1, 100);
    spin->setSuffix(QStringLiteral(" %"));
    return spin;
  }
  void setEditorData(QWidget* editor, const QModelIndex& index) const override {
    static_cast<QSpinBox*>(editor)->setValue(qRound(index.data(Qt::EditRole).toDouble()));
  }
  void setModelData(QWidget* editor, QAbstractItemModel* model, const QModelIndex& index) const override {
    model->setData(index, double(static_cast<QSpinBox*>(editor)->value()), Qt::EditRole);
  }
};

QPushButton* makeButton(const QString& name, const QString& text, const QString& tip, QWidget* parent) {
  auto* b = new QPushButton(text, parent);
  b->setObjectName(name);
  b->setToolTip(tip);
  return b;
}

}  // namespace

ProgramPanel::ProgramPanel(Session& session, QWidget* parent)
    : PanelBase(session, QStringLiteral("program"), tr("Program"), parent) {
  model_ = new ProgramModel(this);
  body()->addWidget(buildFileRow());
  body()->addWidget(buildRunGroup());
  body()->addWidget(buildEditorArea(), 1);
  letBodyFill();
  setDialogs({});
  attachShortcut();

  connect(model_, &ProgramModel::edited, this, &ProgramPanel::programEdited);
  connect(list_->selectionModel(), &QItemSelectionModel::selectionChanged, this, [this] {
    showSelectedLogic();
    updateButtons();
    updateOverlay();
  });
  connect(&session, &Session::motionFinished, this, &ProgramPanel::runFinished);
  connect(&session, &Session::armSamplesArrived, this, &ProgramPanel::takeArmSamples);
  newProgram();
}

ProgramPanel::~ProgramPanel() {
  // The run's job holds its own reference to the executor: ask it to end; it finishes on its own.
  if (running_) run_slot_->executor.stop();
}

// The editor area takes the panel's spare height (PanelBase gives it to a stretch below the body).
void ProgramPanel::letBodyFill() {
  auto* outer = qobject_cast<QBoxLayout*>(layout());
  if (!outer) return;
  for (int i = 0; i < outer->count(); ++i) outer->setStretch(i, outer->itemAt(i)->layout() == body() ? 1 : 0);
}

// Teach and the instruction list, scrolling vertically under the Run bar; the list grows with the panel.
QWidget* ProgramPanel::buildEditorArea() {
  auto* area = new QScrollArea(this);
  area->setObjectName(QStringLiteral("program.scroll"));
  area->setWidgetResizable(true);
  area->setFrameShape(QFrame::NoFrame);
  auto* content = new QWidget(area);
  auto* layout = new QVBoxLayout(content);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(buildTeachGroup());
  layout->addWidget(buildListGroup(), 1);
  area->setWidget(content);
  return area;
}

QWidget* ProgramPanel::buildFileRow() {
  auto* box = new QWidget(this);
  auto* row = new QHBoxLayout(box);
  row->setContentsMargins(0, 0, 0, 0);
  file_label_ = new QLabel(box);
  file_label_->setObjectName(QStringLiteral("program.file"));
  file_label_->setToolTip(tr("The program file; \"modified\" until the changes are saved"));
  QFont bold = file_label_->font();
  bold.setBold(true);
  file_label_->setFont(bold);
  file_label_->setMinimumWidth(60);  // a long file name is cut, not widening the panel (full path in the tooltip)
  auto* new_button = makeButton(QStringLiteral("program.new"), tr("New"), tr("Start an empty program"), box);
  auto* open = makeButton(QStringLiteral("program.open"), tr("Open…"), tr("Open a program file (JSON)"), box);
  auto* save = makeButton(QStringLiteral("program.save"), tr("Save"), tr("Save the program to its file (asks for a name the first time)"), box);
  auto* save_as = makeButton(QStringLiteral("program.saveAs"), tr("Save as…"), tr("Save the program under a new name"), box);
  row->addWidget(file_label_, 1);
  for (auto* b : {new_button, open, save, save_as}) {
    compactButton(b);
    b->setFixedWidth(b->minimumWidth());  // the file name gets the rest of the row
    row->addWidget(b);
  }
  connect(new_button, &QPushButton::clicked, this, &ProgramPanel::newClicked);
  connect(open, &QPushButton::clicked, this, &ProgramPanel::openClicked);
  connect(save, &QPushButton::clicked, this, &ProgramPanel::saveClicked);
  connect(save_as, &QPushButton::clicked, this, &ProgramPanel::saveAsClicked);
  return box;
}

QWidget* ProgramPanel::buildTeachGroup() {
  auto* group = new QGroupBox(tr("Teach"), this);
  auto* grid = new QGridLayout(group);
  record_type_ = new QComboBox(group);
  record_type_->setObjectName(QStringLiteral("program.recordType"));
  record_type_->addItem(tr("J — joint move (MOVEJ)"), kRecordJ);
  record_type_->addItem(tr("L — straight line (MOVEL)"), kRecordL);
  record_type_->addItem(tr("C — arc (MOVEC): via, then target"), kRecordC);
  record_type_->addItem(tr("P — demonstrated path (PATH)"), kRecordPath);
  record_type_->setToolTip(tr("How the robot will move to the recorded waypoint; P records the path itself while you "
                              "guide the arm, and replays it as demonstrated"));
  compactCombo(record_type_, 14);
  record_speed_ = new QSpinBox(group);
  record_speed_->setObjectName(QStringLiteral("program.recordSpeed"));
  record_speed_->setRange(1, 100);
  record_speed_->setValue(loadValue(QStringLiteral("recordSpeed"), 30).toInt());
  record_speed_->setSuffix(QStringLiteral(" %"));
  record_speed_->setToolTip(tr("Speed of the recorded move: share of the robot's rated speed (1 to 100 %)"));
  record_ = makeButton(QStringLiteral("program.record"), tr("Record waypoint (F9)"),
                       tr("Record the robot's current joints, TCP pose and arm angle as a waypoint, inserted "
                          "after the selected instruction"),
                       group);
  di_trigger_ = new QComboBox(group);
  di_trigger_->setObjectName(QStringLiteral("program.diTrigger"));
  fillDiTrigger();
  di_trigger_->setToolTip(tr("Record a waypoint on each rising edge of this digital input (e.g. a button on the "
                             "tool)"));
  record_state_ = new QLabel(tr("Guide the arm by hand (Drag or Hand guiding panel) or jog it, then record."), group);
  record_state_->setObjectName(QStringLiteral("program.recordState"));
  record_state_->setWordWrap(true);
  grid->addWidget(new QLabel(tr("Move type"), group), 0, 0);
  grid->addWidget(record_type_, 0, 1, 1, 3);
  grid->addWidget(new QLabel(tr("Speed"), group), 1, 0);
  grid->addWidget(record_speed_, 1, 1);
  grid->addWidget(new QLabel(tr("DI trigger"), group), 1, 2, Qt::AlignRight);
  grid->addWidget(di_trigger_, 1, 3);
  grid->addWidget(record_, 2, 0, 1, 4);
  grid->addWidget(record_state_, 3, 0, 1, 4);
  grid->setColumnStretch(1, 1);
  grid->setColumnStretch(3, 1);

  record_action_ = new QAction(tr("Record waypoint"), this);
  record_action_->setObjectName(QStringLiteral("program.recordAction"));
  record_action_->setShortcut(QKeySequence(Qt::Key_F9));
  record_action_->setShortcutContext(Qt::ApplicationShortcut);
  connect(record_action_, &QAction::triggered, this, [this] {
    if (record_->isEnabled()) record();
  });
  connect(record_, &QPushButton::clicked, this, &ProgramPanel::record);
  connect(record_type_, &QComboBox::currentIndexChanged, this, &ProgramPanel::cancelPendingVia);
  connect(record_type_, &QComboBox::currentIndexChanged, this, &ProgramPanel::updateRecordButton);
  connect(di_trigger_, &QComboBox::currentIndexChanged, this, &ProgramPanel::resetDiTrigger);
  connect(record_speed_, &QSpinBox::valueChanged, this, [this](int v) { saveValue(QStringLiteral("recordSpeed"), v); });
  return group;
}

QWidget* ProgramPanel::buildListGroup() {
  auto* group = new QGroupBox(tr("Instructions"), this);
  auto* layout = new QVBoxLayout(group);
  list_ = new QTableView(group);
  list_->setObjectName(QStringLiteral("program.list"));
  list_->setModel(model_);
  list_->setSelectionBehavior(QAbstractItemView::SelectRows);
  list_->setSelectionMode(QAbstractItemView::SingleSelection);
  list_->setDragEnabled(true);
  list_->setAcceptDrops(true);
  list_->setDropIndicatorShown(true);
  list_->setDragDropMode(QAbstractItemView::InternalMove);
  list_->setDefaultDropAction(Qt::MoveAction);
  list_->verticalHeader()->hide();
  list_->setItemDelegateForColumn(ProgramModel::kType, new TypeDelegate(list_));
  list_->setItemDelegateForColumn(ProgramModel::kSpeed, new SpeedDelegate(list_));
  sizeListColumns();
  list_->setMinimumHeight(140);
  list_->setToolTip(tr("Double-click Type, Name or Speed to edit; drag rows to reorder"));
  layout->addWidget(list_, 1);
  layout->addLayout(buildEditRows(group));
  layout->addLayout(buildLogicEditor(group));
  return group;
}

// Fixed widths from the font for the short columns, so "WAIT_DI" and "100" always show in full;
// the details take the rest.
void ProgramPanel::sizeListColumns() {
  QHeaderView* header = list_->horizontalHeader();
  const QFontMetrics metrics = list_->fontMetrics();
  const int padding = metrics.horizontalAdvance(QLatin1Char('M')) + 4;  // cell and header margins
  auto fixed = [&](int column, const QString& widest) {
    const QString title = model_->headerData(column, Qt::Horizontal, Qt::DisplayRole).toString();
    const int text = std::max(metrics.horizontalAdvance(widest), header->fontMetrics().horizontalAdvance(title));
    header->setSectionResizeMode(column, QHeaderView::Fixed);
    header->resizeSection(column, text + padding);
  };
  fixed(ProgramModel::kIndex, QStringLiteral("000"));
  fixed(ProgramModel::kType, QStringLiteral("WAIT_DI"));
  fixed(ProgramModel::kSpeed, QStringLiteral("100"));
  header->setSectionResizeMode(ProgramModel::kName, QHeaderView::Interactive);
  header->resizeSection(ProgramModel::kName, metrics.horizontalAdvance(QStringLiteral("P0000")) + padding);
  header->setStretchLastSection(true);
  header->setHighlightSections(false);  // a bold title for the selected row's columns would no longer fit
}

// Two rows: reorder / copy / delete, then the moves that need the robot's pose.
QLayout* ProgramPanel::buildEditRows(QWidget* group) {
  auto* up = makeButton(QStringLiteral("program.up"), tr("Up"), tr("Move the selected instruction up"), group);
  auto* down = makeButton(QStringLiteral("program.down"), tr("Down"), tr("Move the selected instruction down"), group);
  auto* dup = makeButton(QStringLiteral("program.duplicate"), tr("Duplicate"), tr("Copy the selected instruction"), group);
  auto* del = makeButton(QStringLiteral("program.delete"), tr("Delete"), tr("Delete the selected instruction"), group);
  touch_ = makeButton(QStringLiteral("program.touchup"), tr("Touch up"),
                      tr("Replace the selected waypoint's target with the robot's current pose"), group);
  touch_via_ = makeButton(QStringLiteral("program.touchupVia"), tr("Touch up via"),
                          tr("Replace the selected MOVEC's via point with the robot's current pose"), group);
  auto* go = makeButton(QStringLiteral("program.goto"), tr("Go to"),
                        tr("Move to the selected waypoint (a path: its first sample) with a joint move (MOVEJ) at "
                           "no more than 20 % speed"),
                        group);
  auto* rows = new QGridLayout;
  int column = 0;
  for (auto* b : {up, down, dup, del}) {
    compactButton(b);
    rows->addWidget(b, 0, column++);
    edit_buttons_ << b;
  }
  column = 0;
  for (auto* b : {touch_, touch_via_, go}) {
    compactButton(b);
    rows->addWidget(b, 1, column++);
  }
  live_buttons_ << touch_ << go;
  connect(up, &QPushButton::clicked, this, [this] { moveSelected(-1); });
  connect(down, &QPushButton::clicked, this, [this] { moveSelected(+1); });
  connect(dup, &QPushButton::clicked, this, [this] {
    const int row = selectedRow();
    if (model_->duplicate(row)) selectRow(row + 1);
  });
  connect(del, &QPushButton::clicked, this, [this] {
    const int row = selectedRow();
    if (model_->remove(row)) selectRow(std::min(row, model_->count() - 1));
  });
  connect(touch_, &QPushButton::clicked, this, [this] { touchUp(false); });
  connect(touch_via_, &QPushButton::clicked, this, [this] { touchUp(true); });
  connect(go, &QPushButton::clicked, this, &ProgramPanel::gotoClicked);
  return rows;
}

// WAIT / SET_DO / WAIT_DI: type, signal and level on one row, the time and Insert / Apply below.
QLayout* ProgramPanel::buildLogicEditor(QWidget* group) {
  logic_type_ = new QComboBox(group);
  logic_type_->setObjectName(QStringLiteral("program.logicType"));
  logic_type_->addItem(QStringLiteral("WAIT"), int(InstructionType::kWait));
  logic_type_->addItem(QStringLiteral("SET_DO"), int(InstructionType::kSetDo));
  logic_type_->addItem(QStringLiteral("WAIT_DI"), int(InstructionType::kWaitDi));
  logic_type_->setToolTip(tr("WAIT: pause for a time; SET_DO: set a digital output; WAIT_DI: wait for a digital input"));
  logic_signal_ = new QComboBox(group);
  logic_signal_->setObjectName(QStringLiteral("program.logicSignal"));
  logic_value_ = new QCheckBox(tr("on"), group);
  logic_value_->setObjectName(QStringLiteral("program.logicValue"));
  logic_value_->setToolTip(tr("The level to set (SET_DO) or to wait for (WAIT_DI)"));
  logic_ms_label_ = new QLabel(group);
  logic_ms_ = new QSpinBox(group);
  logic_ms_->setObjectName(QStringLiteral("program.logicMs"));
  logic_ms_->setRange(0, 3600000);
  logic_ms_->setValue(500);
  logic_ms_->setSuffix(QStringLiteral(" ms"));
  auto* add = makeButton(QStringLiteral("program.addLogic"), tr("Insert"),
                         tr("Insert this instruction after the selected one"), group);
  apply_logic_ = makeButton(QStringLiteral("program.applyLogic"), tr("Apply"),
                            tr("Change the selected WAIT, SET_DO or WAIT_DI to these values"), group);
  compactButton(add);
  compactButton(apply_logic_);
  auto* grid = new QGridLayout;
  grid->addWidget(logic_type_, 0, 0);
  grid->addWidget(logic_signal_, 0, 1);
  grid->addWidget(logic_value_, 0, 2, 1, 2);
  grid->addWidget(logic_ms_label_, 1, 0, Qt::AlignRight);
  grid->addWidget(logic_ms_, 1, 1);
  grid->addWidget(add, 1, 2);
  grid->addWidget(apply_logic_, 1, 3);
  grid->setColumnStretch(1, 1);
  logicTypeChanged();
  connect(logic_type_, &QComboBox::currentIndexChanged, this, &ProgramPanel::logicTypeChanged);
  connect(add, &QPushButton::clicked, this, &ProgramPanel::addLogic);
  connect(apply_logic_, &QPushButton::clicked, this, &ProgramPanel::applyLogic);
  return grid;
}

QWidget* ProgramPanel::buildRunGroup() {
  auto* group = new QGroupBox(tr("Run"), this);
  auto* layout = new QVBoxLayout(group);
  auto* buttons = new QHBoxLayout;
  run_ = makeButton(QStringLiteral("program.run"), tr("Run"),
                    tr("Check the program (pre-flight), then run it from the first instruction"), group);
  step_ = makeButton(QStringLiteral("program.step"), tr("Step"),
                     tr("Run one instruction, then pause (starts a run if none is active)"), group);
  pause_ = makeButton(QStringLiteral("program.pause"), tr("Pause"), tr("Slow down smoothly and hold on the path"), group);
  resume_ = makeButton(QStringLiteral("program.resume"), tr("Resume"), tr("Continue the paused run to its end"), group);
  stop_ = makeButton(QStringLiteral("program.stop"), tr("Stop"), tr("Slow down smoothly and end the run"), group);
  for (auto* b : {run_, step_, pause_, resume_, stop_}) {
    compactButton(b);
    buttons->addWidget(b);
  }
  layout->addLayout(buttons);

  auto* form = new QFormLayout;
  auto* speed_row = new QHBoxLayout;
  speed_ = new QSlider(Qt::Horizontal, group);
  speed_->setObjectName(QStringLiteral("program.speed"));
  speed_->setRange(10, 100);
  speed_->setValue(loadValue(QStringLiteral("override"), 100).toInt());
  speed_->setToolTip(tr("Speed override: scales every move of the run, 10 to 100 % (changes apply smoothly while running)"));
  speed_label_ = new QLabel(group);
  speed_label_->setObjectName(QStringLiteral("program.speedLabel"));
  speed_label_->setMinimumWidth(speed_label_->fontMetrics().horizontalAdvance(QStringLiteral("100 %")) + 4);
  speed_label_->setText(QStringLiteral("%1 %").arg(speed_->value()));
  speed_row->addWidget(speed_, 1);
  speed_row->addWidget(speed_label_);
  form->addRow(tr("Override"), speed_row);
  progress_ = new QProgressBar(group);
  progress_->setObjectName(QStringLiteral("program.progress"));
  progress_->setRange(0, 1000);
  progress_->setValue(0);
  progress_->setFormat(tr("Idle"));
  progress_->setToolTip(tr("The instruction running and how much of it is done"));
  run_state_ = new QLabel(tr("Idle"), group);
  run_state_->setObjectName(QStringLiteral("program.runState"));
  run_state_->setToolTip(tr("The state of the run"));
  run_state_->setWordWrap(true);
  // The state beside the progress, one row less above the editor on a small screen.
  auto* progress_row = new QHBoxLayout;
  progress_row->addWidget(progress_, 3);
  progress_row->addWidget(run_state_, 2);
  form->addRow(tr("Progress"), progress_row);
  layout->addLayout(form);

  // The pre-flight problems show here, under Run, while there are any.
  problems_label_ = new QLabel(tr("Pre-flight problems (nothing moves while there are any):"), group);
  problems_label_->setWordWrap(true);
  layout->addWidget(problems_label_);
  problems_ = new QListWidget(group);
  problems_->setObjectName(QStringLiteral("program.problems"));
  problems_->setToolTip(tr("Double-click a problem to select its instruction"));
  problems_->setMaximumHeight(problems_->fontMetrics().lineSpacing() * 4 + 8);
  problems_->setWordWrap(true);
  layout->addWidget(problems_);
  problems_label_->hide();
  problems_->hide();

  connect(run_, &QPushButton::clicked, this, &ProgramPanel::runClicked);
  connect(step_, &QPushButton::clicked, this, &ProgramPanel::stepClicked);
  connect(pause_, &QPushButton::clicked, this, &ProgramPanel::pauseClicked);
  connect(resume_, &QPushButton::clicked, this, &ProgramPanel::resumeClicked);
  connect(stop_, &QPushButton::clicked, this, &ProgramPanel::stopClicked);
  connect(speed_, &QSlider::valueChanged, this, [this](int v) {
    speed_label_->setText(QStringLiteral("%1 %").arg(v));
    run_slot_->executor.setSpeedOverride(v / 100.0);
    saveValue(QStringLiteral("override"), v);
  });
  connect(problems_, &QListWidget::itemDoubleClicked, this, [this](QListWidgetItem* item) {
    selectRow(item->data(Qt::UserRole).toInt());
  });
  return group;
}

void ProgramPanel::attachShortcut() {
  // The F9 action lives on the panel and on its top-level window, so it works wherever the focus
  // is in the window, also while the Program dock is tabbed away (ApplicationShortcut needs one of
  // the action's widgets to be visible).
  if (!actions().contains(record_action_)) addAction(record_action_);
  QWidget* top = window();
  if (top == shortcut_host_) return;
  if (shortcut_host_) shortcut_host_->removeAction(record_action_);
  shortcut_host_ = top != this ? top : nullptr;
  if (shortcut_host_) shortcut_host_->addAction(record_action_);
}

bool ProgramPanel::event(QEvent* event) {
  if (event->type() == QEvent::ParentChange || event->type() == QEvent::Show) attachShortcut();
  if (event->type() == QEvent::ParentChange) updateTitle();
  return PanelBase::event(event);
}

bool ProgramPanel::haveLiveState() const { return isOpen() && session().live().has_arm_state; }

xmate::teach::Target ProgramPanel::livePose() const {
  const LiveState& live = session().live();
  // An xMate's state also carries the arm angle (7-axis redundancy); every arm has joints and TCP.
  return live.has_state ? xmate::teach::targetFromState(live.state, spec()) : xmate::teach::targetFromArm(live.arm, spec());
}

const xmate::teach::Program& ProgramPanel::program() const { return model_->program(); }

int ProgramPanel::selectedRow() const {
  const QModelIndexList rows = list_->selectionModel()->selectedRows();
  return rows.isEmpty() ? -1 : rows.first().row();
}

void ProgramPanel::selectRow(int row) {
  if (row < 0 || row >= model_->count()) {
    list_->selectionModel()->clearSelection();
    list_->selectionModel()->setCurrentIndex({}, QItemSelectionModel::Clear);
  } else {
    list_->selectionModel()->setCurrentIndex(model_->index(row, 0),
                                             QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    list_->scrollTo(model_->index(row, 0));
  }
  updateButtons();
}

void ProgramPanel::record() {
  if (record_type_->currentData().toInt() == kRecordPath) {
    if (isRecordingPath()) stopPathRecording();
    else startPathRecording();
    return;
  }
  if (!mayRecord()) return;
  if (!teachWithRobotTool(tr("Record"))) return;
  const xmate::teach::Target target = livePose();
  const int kind = record_type_->currentData().toInt();
  if (kind == kRecordC && !have_via_) {
    via_ = target;
    have_via_ = true;
    record_state_->setText(tr("MOVEC: via point recorded — guide the arm to the arc's end and record the target."));
    showStatus(tr("Via point recorded; waiting for the target."), false);
    return;
  }
  const double speed = record_speed_->value() / 100.0;
  const std::string name = model_->nextName().toStdString();
  const Instruction in = kind == kRecordJ   ? xmate::teach::moveJ(target, speed, name)
                         : kind == kRecordL ? xmate::teach::moveL(target, speed, name)
                                            : xmate::teach::moveC(via_, target, speed, name);
  have_via_ = false;
  record_state_->setText(tr("Recorded %1.").arg(QString::fromStdString(name)));
  const int row = selectedRow() >= 0 ? selectedRow() + 1 : model_->count();
  model_->insert(row, in);
  selectRow(row);
  note(tr("Recorded %1 (%2) as instruction %3.")
           .arg(QString::fromStdString(name), QLatin1String(xmate::teach::typeName(in.type)))
           .arg(row + 1),
       false);
}

bool ProgramPanel::mayRecord() {
  if (!haveLiveState()) {
    showStatus(tr("Record: no robot state — connect to a robot or the simulator first."), true);
    return false;
  }
  if (running_) {
    showStatus(tr("Record: a run is active — stop it first."), true);
    return false;
  }
  if (model_->count() > 0 && program().robot != &spec()) {
    showStatus(tr("Record: this program is for another robot model than the one connected — start a new "
                  "program (New) to teach this robot."),
               true);
    return false;
  }
  if (model_->count() == 0 && program().robot != &spec()) {
    xmate::teach::Program empty;
    empty.robot = &spec();
    model_->setProgram(empty);
  }
  return true;
}

void ProgramPanel::updateRecordButton() {
  const bool path = record_type_->currentData().toInt() == kRecordPath;
  if (isRecordingPath()) {
    record_->setText(tr("Stop recording path (F9)"));
    record_->setToolTip(tr("End the recording: the path becomes a PATH instruction after the selected one"));
  } else if (path) {
    record_->setText(tr("Start recording path (F9)"));
    record_->setToolTip(tr("Record every joint position while you guide the arm, until you press it again; idle "
                           "stretches at the start and end are trimmed"));
  } else {
    record_->setText(tr("Record waypoint (F9)"));
    record_->setToolTip(tr("Record the robot's current joints, TCP pose and arm angle as a waypoint, inserted "
                           "after the selected instruction"));
  }
  record_action_->setText(record_->text().remove(QStringLiteral(" (F9)")));
  // A PATH replays at the demonstrated pace (its speed is edited in the list afterwards).
  record_speed_->setEnabled(!path);
}

std::string ProgramPanel::adoptRobotTool(xmate::teach::Program& adopted) const {
  xmate::teach::Payload load;
  std::array<double, 16> tool = xmate::teach::kIdentityPose;
  if (auto* robot = session().robot()) {
    tool = robot->toolFrame();
    robot->load(load.mass, load.center, load.inertia);
  }
  const xmate::arm::ArmState& now = session().live().arm;
  return xmate::teach::adoptTool(adopted, now.sample.q, now.tcp, tool, load);
}

bool ProgramPanel::teachWithRobotTool(const QString& action) {
  xmate::teach::Program adopted = program();
  const std::string problem = adoptRobotTool(adopted);
  if (!problem.empty()) {
    note(action + QStringLiteral(": ") + text::programProblem(problem), true);
    return false;
  }
  if (adopted.has_tool != program().has_tool) model_->setProgram(adopted);  // the first pose: its tool
  return true;
}

void ProgramPanel::note(const QString& text, bool error, const QString& path) {
  showStatus(text, error);
  session().reportEvent(error ? Session::EventLevel::kError : Session::EventLevel::kInfo,
                        title() + QStringLiteral(": ") + text, path);
}

void ProgramPanel::resetDiTrigger() {
  // The level now is the reference: only a later rising edge records.
  const int di = di_trigger_->currentData().toInt();
  di_known_ = haveLiveState() && di >= 0 && di < 64;
  if (di_known_) last_di_ = (session().live().inputs >> di) & 1u;
}

void ProgramPanel::fillDiTrigger() {
  std::vector<std::string> names;
  if (const xmate::arm::Arm* arm = session().arm()) names = arm->inputNames();
  else
    for (int i = 0; i < xmate::teach::kXmateSignalCount; ++i)
      names.push_back(xmate::teach::diName(xmate::model::RobotFamily::kXmate, i));
  const QString keep = di_trigger_->currentText();
  const QSignalBlocker quiet(di_trigger_);
  di_trigger_->clear();
  di_trigger_->addItem(tr("Off"), -1);
  for (size_t i = 0; i < names.size() && i < 64; ++i) di_trigger_->addItem(QString::fromStdString(names[i]), int(i));
  const int again = di_trigger_->findText(keep);
  di_trigger_->setCurrentIndex(again >= 0 ? again : 0);
}

void ProgramPanel::cancelPendingVia() {
  if (!have_via_) return;
  have_via_ = false;
  record_state_->setText(tr("Via point discarded."));
}

void ProgramPanel::logicTypeChanged() {
  const auto type = InstructionType(logic_type_->currentData().toInt());
  const int keep = logic_signal_->currentIndex();
  logic_signal_->clear();
  // The xMate's six signals; on a KUKA the first 64 of $OUT / $IN.
  const xmate::model::RobotFamily family = model_->program().robot->family;
  const int first = family == xmate::model::RobotFamily::kKuka ? 1 : 0;
  const int count = family == xmate::model::RobotFamily::kKuka ? 64 : xmate::teach::kXmateSignalCount;
  if (type != InstructionType::kWait)
    for (int i = first; i < first + count; ++i)
      logic_signal_->addItem(QString::fromStdString(type == InstructionType::kSetDo ? xmate::teach::doName(family, i)
                                                                                     : xmate::teach::diName(family, i)),
                             i);
  if (keep >= 0 && keep < logic_signal_->count()) logic_signal_->setCurrentIndex(keep);
  logic_signal_->setEnabled(type != InstructionType::kWait);
  logic_value_->setEnabled(type != InstructionType::kWait);
  logic_ms_->setEnabled(type != InstructionType::kSetDo);
  logic_ms_label_->setText(type == InstructionType::kWaitDi ? tr("Timeout") : tr("Duration"));
  logic_ms_->setToolTip(type == InstructionType::kWaitDi
                            ? tr("Give up (the run fails) if the input has not reached the level by then, 1 to 3 600 000 ms")
                            : tr("How long to wait, 0 to 3 600 000 ms"));
}

bool ProgramPanel::logicFromEditor(size_t row, Instruction& in) {
  in = Instruction{};
  in.type = InstructionType(logic_type_->currentData().toInt());
  in.signal = std::max(0, logic_signal_->currentData().toInt());
  in.value = logic_value_->isChecked();
  if (in.type == InstructionType::kWait) in.ms = logic_ms_->value();
  if (in.type == InstructionType::kWaitDi) in.timeout_ms = logic_ms_->value();
  try {
    xmate::teach::validateInstruction(in, row, *program().robot);
  } catch (const std::exception& e) {
    markInvalid(logic_ms_, true);
    showStatus(tr("Not changed: %1.").arg(QString::fromStdString(e.what())), true);
    return false;
  }
  markInvalid(logic_ms_, false);
  return true;
}

void ProgramPanel::addLogic() {
  if (running_) {
    showStatus(tr("Insert: a run is active — stop it first."), true);
    return;
  }
  const int row = selectedRow() >= 0 ? selectedRow() + 1 : model_->count();
  Instruction in;
  if (!logicFromEditor(size_t(row), in)) return;
  model_->insert(row, in);
  selectRow(row);
  showStatus(tr("Inserted %1 as instruction %2.").arg(QLatin1String(xmate::teach::typeName(in.type))).arg(row + 1), false);
}

void ProgramPanel::applyLogic() {
  const int row = selectedRow();
  if (running_ || row < 0 || xmate::teach::isMotion(model_->instruction(row).type)) return;
  Instruction in;
  if (!logicFromEditor(size_t(row), in) || !model_->replaceLogic(row, in)) return;
  showStatus(tr("Instruction %1 is now %2.").arg(row + 1).arg(model_->details(model_->instruction(row))), false);
}

void ProgramPanel::showSelectedLogic() {
  const int row = selectedRow();
  if (row < 0) return;
  const Instruction& in = model_->instruction(row);
  if (xmate::teach::isMotion(in.type)) return;
  logic_type_->setCurrentIndex(logic_type_->findData(int(in.type)));  // refills the signal list
  if (in.type != InstructionType::kWait) logic_signal_->setCurrentIndex(logic_signal_->findData(in.signal));
  logic_value_->setChecked(in.value);
  if (in.type == InstructionType::kWait) logic_ms_->setValue(in.ms);
  if (in.type == InstructionType::kWaitDi) logic_ms_->setValue(in.timeout_ms);
  markInvalid(logic_ms_, false);
}

void ProgramPanel::touchUp(bool via) {
  const int row = selectedRow();
  if (row < 0 || !haveLiveState() || running_) return;
  if (!teachWithRobotTool(via ? tr("Touch up via") : tr("Touch up"))) return;
  const xmate::teach::Target pose = livePose();
  if (via) {
    if (!model_->replaceVia(row, pose)) {
      showStatus(tr("Touch up via: select a MOVEC instruction."), true);
      return;
    }
    showStatus(tr("Touched up instruction %1: its via point is now the current pose.").arg(row + 1), false);
    return;
  }
  if (!model_->replaceTarget(row, pose)) {
    showStatus(tr("Touch up: select a move instruction (MOVEJ, MOVEL or MOVEC)."), true);
    return;
  }
  showStatus(tr("Touched up instruction %1: its target is now the current pose.").arg(row + 1), false);
}

void ProgramPanel::moveSelected(int delta) {
  const int row = selectedRow();
  if (running_ || !model_->move(row, row + delta)) return;
  selectRow(row + delta);
}

void ProgramPanel::programEdited() {
  modified_ = true;
  updateTitle();
  updateButtons();
  updateOverlay();
}

void ProgramPanel::updateTitle() {
  if (!file_label_) return;
  const QString name = path_.isEmpty() ? tr("untitled") : QFileInfo(path_).fileName();
  file_label_->setText(modified_ ? tr("%1 (modified)").arg(name) : name);
  file_label_->setToolTip(path_.isEmpty() ? tr("Not saved yet") : path_);
  const QString title = tr("Program \u2014 %1%2").arg(name, modified_ ? QStringLiteral(" *") : QString());
  setWindowTitle(title);
  for (QWidget* w = parentWidget(); w; w = w->parentWidget())
    if (auto* dock = qobject_cast<QDockWidget*>(w)) {
      dock->setWindowTitle(title);
      break;
    }
}

void ProgramPanel::updateButtons() {
  const int row = selectedRow();
  const bool motion = row >= 0 && xmate::teach::isMotion(model_->instruction(row).type);
  const bool path = row >= 0 && model_->instruction(row).type == InstructionType::kPath;
  const bool recording = isRecordingPath();
  const auto state = run_slot_->executor.progress().state;
  const bool paused = running_ && state == xmate::teach::RunState::kPaused;
  const bool moving = running_ && (state == xmate::teach::RunState::kRunning || state == xmate::teach::RunState::kChecking);
  for (auto* b : edit_buttons_) b->setEnabled(row >= 0 && !running_);
  edit_buttons_[0]->setEnabled(row > 0 && !running_);
  edit_buttons_[1]->setEnabled(row >= 0 && row + 1 < model_->count() && !running_);
  for (auto* b : live_buttons_) b->setEnabled(motion && haveLiveState() && !running_ && !recording);
  touch_->setEnabled(touch_->isEnabled() && !path);  // a PATH is re-recorded, not touched up
  touch_via_->setEnabled(motion && model_->instruction(row).type == InstructionType::kMoveC && haveLiveState() &&
                         !running_);
  apply_logic_->setEnabled(row >= 0 && !motion && !running_);
  record_->setEnabled(haveLiveState() && !running_);
  record_type_->setEnabled(!recording);  // the recording ends as the kind it started
  // The list is read-only while a run highlights its instructions.
  list_->setEditTriggers(running_ ? QAbstractItemView::NoEditTriggers
                                  : QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                                        QAbstractItemView::SelectedClicked);
  list_->setDragEnabled(!running_);
  // Recording a path and running exclude each other.
  // A run waits while the arm still comes to rest after a stop (the status bar says "stopping").
  const bool stopping = isOpen() && session().live().stopping;
  run_->setEnabled(isOpen() && model_->count() > 0 && !running_ && !recording && !stopping);
  step_->setEnabled(isOpen() && model_->count() > 0 && !recording && !stopping &&
                    (!running_ || (paused && !goto_run_)));
  pause_->setEnabled(moving);
  resume_->setEnabled(paused);
  stop_->setEnabled(running_);
}

}  // namespace rci::ui
