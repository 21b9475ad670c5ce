// SPDX-License-Identifier: Apache-2.0
// ProgramModel: the instruction table of the Program panel -- display, in-place edits (type, name,
// speed), structural edits and drag & drop reordering of a teach::Program.
#include "panels/program_model.h"

#include <QBrush>
#include <QColor>
#include <QMimeData>
#include <QSet>

#include <algorithm>
#include <utility>

namespace rci::ui {

using xmate::teach::Instruction;
using xmate::teach::InstructionType;
using xmate::teach::Target;

namespace {

const QString kRowMime = QStringLiteral("application/x-rci-program-row");

QString position(const Target& t) {
  if (t.has_pose)
    return QStringLiteral("(%1, %2, %3) mm")
        .arg(t.pose[3] * 1000, 0, 'f', 1)
        .arg(t.pose[7] * 1000, 0, 'f', 1)
        .arg(t.pose[11] * 1000, 0, 'f', 1);
  QStringList deg;
  for (double v : t.q) deg << QString::number(v * 57.29577951308232, 'f', 1);
  return QStringLiteral("q = [%1] deg").arg(deg.join(QStringLiteral(", ")));
}

}  // namespace

ProgramModel::ProgramModel(QObject* parent) : QAbstractTableModel(parent) {}

void ProgramModel::setProgram(const xmate::teach::Program& program, bool as_edit) {
  beginResetModel();
  program_ = program;
  current_ = -1;
  endResetModel();
  if (as_edit) emit edited();
}

void ProgramModel::insert(int row, const Instruction& instruction) {
  row = std::clamp(row, 0, count());
  beginInsertRows({}, row, row);
  program_.instructions.insert(program_.instructions.begin() + row, instruction);
  endInsertRows();
  emit edited();
}

bool ProgramModel::remove(int row) {
  if (row < 0 || row >= count()) return false;
  beginRemoveRows({}, row, row);
  program_.instructions.erase(program_.instructions.begin() + row);
  endRemoveRows();
  emit edited();
  return true;
}

bool ProgramModel::move(int from, int to) {
  if (from < 0 || from >= count() || to < 0 || to >= count() || from == to) return false;
  // beginMoveRows takes the destination as the row the item is inserted before.
  beginMoveRows({}, from, from, {}, to > from ? to + 1 : to);
  auto& list = program_.instructions;
  Instruction moved = std::move(list[size_t(from)]);
  list.erase(list.begin() + from);
  list.insert(list.begin() + to, std::move(moved));
  endMoveRows();
  emit edited();
  return true;
}

bool ProgramModel::duplicate(int row) {
  if (row < 0 || row >= count()) return false;
  Instruction copy = instruction(row);
  if (!copy.name.empty()) copy.name = nextName().toStdString();
  insert(row + 1, copy);
  return true;
}

bool ProgramModel::replaceTarget(int row, const Target& target) {
  if (row < 0 || row >= count() || !xmate::teach::isMotion(instruction(row).type)) return false;
  program_.instructions[size_t(row)].target = target;
  emit dataChanged(index(row, 0), index(row, kColumnCount - 1));
  emit edited();
  return true;
}

bool ProgramModel::replaceVia(int row, const Target& via) {
  if (row < 0 || row >= count() || instruction(row).type != InstructionType::kMoveC) return false;
  program_.instructions[size_t(row)].via = via;
  emit dataChanged(index(row, 0), index(row, kColumnCount - 1));
  emit edited();
  return true;
}

bool ProgramModel::replaceLogic(int row, const Instruction& logic) {
  if (row < 0 || row >= count() || xmate::teach::isMotion(instruction(row).type) || xmate::teach::isMotion(logic.type))
    return false;
  Instruction& in = program_.instructions[size_t(row)];
  const std::string name = in.name;
  in = logic;
  in.name = name;
  emit dataChanged(index(row, 0), index(row, kColumnCount - 1));
  emit edited();
  return true;
}

bool ProgramModel::canChangeType(const Instruction& in, InstructionType to) {
  if (!xmate::teach::isMotion(in.type) || !xmate::teach::isMotion(to)) return false;
  return to != InstructionType::kMoveC || in.type == InstructionType::kMoveC;
}

bool ProgramModel::changeType(int row, InstructionType to) {
  if (row < 0 || row >= count() || !canChangeType(instruction(row), to)) return false;
  Instruction& in = program_.instructions[size_t(row)];
  if (in.type == to) return true;
  in.type = to;
  if (to != InstructionType::kMoveC) in.via = Target{};
  emit dataChanged(index(row, 0), index(row, kColumnCount - 1));
  emit edited();
  return true;
}

void ProgramModel::setCurrent(int row) {
  if (row == current_) return;
  const int old = current_;
  current_ = row;
  for (int r : {old, row})
    if (r >= 0 && r < count()) emit dataChanged(index(r, 0), index(r, kColumnCount - 1), {Qt::BackgroundRole});
}

QString ProgramModel::nextName() const {
  QSet<QString> used;
  for (const auto& in : program_.instructions) used.insert(QString::fromStdString(in.name));
  for (int n = 1;; ++n) {
    const QString name = QStringLiteral("P%1").arg(n);
    if (!used.contains(name)) return name;
  }
}

QString ProgramModel::details(const Instruction& in) const {
  const xmate::model::RobotFamily family = program_.robot->family;
  switch (in.type) {
    case InstructionType::kMoveJ:
    case InstructionType::kMoveL:
      return QStringLiteral("to ") + position(in.target);
    case InstructionType::kMoveC:
      return QStringLiteral("via ") + position(in.via) + QStringLiteral(" to ") + position(in.target);
    case InstructionType::kWait:
      return QStringLiteral("wait %1 ms").arg(in.ms);
    case InstructionType::kSetDo:
      return QStringLiteral("%1 = %2").arg(QString::fromStdString(xmate::teach::doName(family, in.signal)),
                                           in.value ? QStringLiteral("on") : QStringLiteral("off"));
    case InstructionType::kWaitDi:
      return QStringLiteral("until %1 = %2, timeout %3 ms")
          .arg(QString::fromStdString(xmate::teach::diName(family, in.signal)), in.value ? QStringLiteral("on") : QStringLiteral("off"))
          .arg(in.timeout_ms);
  }
  return {};
}

int ProgramModel::rowCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : count(); }
int ProgramModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : kColumnCount; }

QVariant ProgramModel::data(const QModelIndex& index, int role) const {
  if (!index.isValid() || index.row() >= count()) return {};
  const Instruction& in = instruction(index.row());
  const bool motion = xmate::teach::isMotion(in.type);
  if (role == Qt::BackgroundRole)
    return index.row() == current_ ? QVariant(QBrush(QColor(255, 214, 120))) : QVariant();
  if (role == Qt::TextAlignmentRole && (index.column() == kIndex || index.column() == kSpeed))
    return int(Qt::AlignRight | Qt::AlignVCenter);
  if (role == Qt::ToolTipRole) return details(in);
  if (role != Qt::DisplayRole && role != Qt::EditRole) return {};
  switch (index.column()) {
    case kIndex: return index.row() + 1;
    case kType: return QString::fromLatin1(xmate::teach::typeName(in.type));
    case kName: return QString::fromStdString(in.name);
    case kSpeed:
      if (!motion) return {};
      return role == Qt::EditRole ? QVariant(in.speed * 100) : QVariant(QString::number(in.speed * 100, 'f', 0));
    case kDetails: return details(in);
    default: return {};
  }
}

QVariant ProgramModel::headerData(int section, Qt::Orientation orientation, int role) const {
  if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return QAbstractTableModel::headerData(section, orientation, role);
  switch (section) {
    case kIndex: return tr("#");
    case kType: return tr("Type");
    case kName: return tr("Name");
    case kSpeed: return tr("Speed (%)");
    case kDetails: return tr("Target / parameters");
    default: return {};
  }
}

Qt::ItemFlags ProgramModel::flags(const QModelIndex& index) const {
  if (!index.isValid()) return Qt::ItemIsDropEnabled;
  Qt::ItemFlags f = Qt::ItemIsSelectable | Qt::ItemIsEnabled | Qt::ItemIsDragEnabled;
  const bool motion = xmate::teach::isMotion(instruction(index.row()).type);
  if (index.column() == kName || (motion && (index.column() == kType || index.column() == kSpeed)))
    f |= Qt::ItemIsEditable;
  return f;
}

bool ProgramModel::setData(const QModelIndex& index, const QVariant& value, int role) {
  if (!index.isValid() || role != Qt::EditRole || index.row() >= count()) return false;
  Instruction& in = program_.instructions[size_t(index.row())];
  switch (index.column()) {
    case kType: {
      const QString text = value.toString();
      for (auto t : {InstructionType::kMoveJ, InstructionType::kMoveL, InstructionType::kMoveC})
        if (text == QLatin1String(xmate::teach::typeName(t))) return changeType(index.row(), t);
      return false;
    }
    case kName:
      in.name = value.toString().trimmed().toStdString();
      break;
    case kSpeed: {
      bool ok = false;
      const double percent = value.toDouble(&ok);
      if (!ok || !xmate::teach::isMotion(in.type) || !(percent >= 1 && percent <= 100)) return false;
      in.speed = percent / 100;
      break;
    }
    default:
      return false;
  }
  emit dataChanged(index, index);
  emit edited();
  return true;
}

Qt::DropActions ProgramModel::supportedDropActions() const { return Qt::MoveAction; }

QStringList ProgramModel::mimeTypes() const { return {kRowMime}; }

QMimeData* ProgramModel::mimeData(const QModelIndexList& indexes) const {
  if (indexes.isEmpty()) return nullptr;
  auto* mime = new QMimeData;
  mime->setData(kRowMime, QByteArray::number(indexes.first().row()));
  return mime;
}

bool ProgramModel::dropMimeData(const QMimeData* data, Qt::DropAction action, int row, int, const QModelIndex& parent) {
  if (!data || action != Qt::MoveAction || !data->hasFormat(kRowMime)) return false;
  bool ok = false;
  const int from = data->data(kRowMime).toInt(&ok);
  if (!ok) return false;
  int before = row >= 0 ? row : (parent.isValid() ? parent.row() : count());
  const int to = before > from ? before - 1 : before;
  move(from, std::clamp(to, 0, count() - 1));
  // The move is done here; returning false keeps the view from also removing the source row
  // (QAbstractItemView removes dragged rows after a move drop that the model accepted).
  return false;
}

}  // namespace rci::ui
