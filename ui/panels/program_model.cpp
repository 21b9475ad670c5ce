// SPDX-License-Identifier: Apache-2.0
// ProgramModel: the instruction table of the Program panel -- display, in-place edits (type, name,
// speed), structural edits and drag & drop reordering of a teach::Program, and the last run's
// result per instruction.
#include "panels/program_model.h"

#include <QBrush>
#include <QColor>
#include <QMimeData>
#include <QSet>

#include <algorithm>
#include <cstring>
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

// FNV-1a over raw bytes: the key under which a PATH's summary is remembered.
quint64 hashBytes(quint64 hash, const void* data, size_t size) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
  return hash;
}

// Only the moves to a taught target have one (a PATH has its samples instead).
bool hasTarget(InstructionType type) {
  return type == InstructionType::kMoveJ || type == InstructionType::kMoveL || type == InstructionType::kMoveC;
}

}  // namespace

ProgramModel::ProgramModel(QObject* parent) : QAbstractTableModel(parent) {}

void ProgramModel::setProgram(const xmate::teach::Program& program, bool as_edit) {
  beginResetModel();
  program_ = program;
  current_ = -1;
  clearResults();
  endResetModel();
  if (as_edit) emit edited();
}

void ProgramModel::insert(int row, const Instruction& instruction) {
  row = std::clamp(row, 0, count());
  beginInsertRows({}, row, row);
  program_.instructions.insert(program_.instructions.begin() + row, instruction);
  endInsertRows();
  clearResults();
  emit edited();
}

bool ProgramModel::remove(int row) {
  if (row < 0 || row >= count()) return false;
  beginRemoveRows({}, row, row);
  program_.instructions.erase(program_.instructions.begin() + row);
  endRemoveRows();
  clearResults();
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
  clearResults();
  emit edited();
  return true;
}

bool ProgramModel::duplicate(int row) {
  if (row < 0 || row >= count()) return false;
  Instruction copy = instruction(row);
  if (!copy.name.empty()) copy.name = nextName(namePrefix(copy.type)).toStdString();
  insert(row + 1, copy);
  return true;
}

bool ProgramModel::replaceTarget(int row, const Target& target) {
  if (row < 0 || row >= count() || !hasTarget(instruction(row).type)) return false;
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
  if (!hasTarget(in.type) || !hasTarget(to)) return false;
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

QString ProgramModel::nextName(const QString& prefix) const {
  QSet<QString> used;
  for (const auto& in : program_.instructions) used.insert(QString::fromStdString(in.name));
  for (int n = 1;; ++n) {
    const QString name = prefix + QString::number(n);
    if (!used.contains(name)) return name;
  }
}

QString ProgramModel::namePrefix(InstructionType type) {
  return type == InstructionType::kPath ? QStringLiteral("Path ") : QStringLiteral("P");
}

void ProgramModel::setResults(const QStringList& per_row) {
  results_ = per_row;
  if (count() > 0) emit dataChanged(index(0, 0), index(count() - 1, kColumnCount - 1), {Qt::ToolTipRole});
}

void ProgramModel::clearResults() { results_.clear(); }

QString ProgramModel::pathDetails(const xmate::teach::JointPath& path) const {
  quint64 key = 1469598103934665603ull;
  key = hashBytes(key, &path.rate_hz, sizeof path.rate_hz);
  key = hashBytes(key, path.q.data(), path.q.size() * sizeof(xmate::teach::JointPoint));
  key = hashBytes(key, program_.tool.data(), sizeof program_.tool);
  key = hashBytes(key, &program_.robot, sizeof program_.robot);
  if (auto it = path_details_.constFind(key); it != path_details_.constEnd()) return *it;
  QString text;
  try {
    const xmate::teach::PathSummary s = xmate::teach::summarizePath(path, *program_.robot, program_.tool);
    text = QStringLiteral("%1 s \u00b7 %2 m TCP \u00b7 %3 samples @ %4 Hz")
               .arg(s.duration, 0, 'f', 1)
               .arg(s.tcp_length, 0, 'f', 2)
               .arg(s.samples)
               .arg(QString::number(path.rate_hz, 'g', 6));
  } catch (const std::exception& e) {  // a path the loader would refuse (too short): say so, do not guess
    text = QStringLiteral("%1 samples @ %2 Hz (%3)")
               .arg(path.q.size())
               .arg(QString::number(path.rate_hz, 'g', 6), QString::fromStdString(e.what()));
  }
  if (path_details_.size() > 256) path_details_.clear();  // programs rarely hold that many paths
  path_details_.insert(key, text);
  return text;
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
    case InstructionType::kPath:
      return pathDetails(in.path);
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
  if (role == Qt::ToolTipRole) {
    const QString last = result(index.row());
    return last.isEmpty() ? details(in) : details(in) + QStringLiteral("\n") + tr("Last run: %1").arg(last);
  }
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
  const InstructionType type = instruction(index.row()).type;
  const bool editable = index.column() == kName || (xmate::teach::isMotion(type) && index.column() == kSpeed) ||
                        (hasTarget(type) && index.column() == kType);
  if (editable) f |= Qt::ItemIsEditable;
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
