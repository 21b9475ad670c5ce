// SPDX-License-Identifier: Apache-2.0
// ProgramModel: the Program panel's table of instructions -- owns the teach::Program being
// edited and offers the edits the panel needs (insert, delete, move, duplicate, type, speed, name,
// touch-up of target or via, logic parameters), drag & drop reordering, the highlight of the instruction that runs,
// and what the last run reported for each instruction (tooltip).
#pragma once

#include <QAbstractTableModel>
#include <QHash>
#include <QStringList>

#include "teach/program.h"

namespace rci::ui {

class ProgramModel : public QAbstractTableModel {
  Q_OBJECT
 public:
  enum Column { kIndex, kType, kName, kSpeed, kDetails, kColumnCount };

  explicit ProgramModel(QObject* parent = nullptr);

  const xmate::teach::Program& program() const { return program_; }
  // Replaces the whole program (Open, New); emits edited() only when `as_edit`.
  void setProgram(const xmate::teach::Program& program, bool as_edit = false);
  const xmate::teach::Instruction& instruction(int row) const { return program_.instructions[size_t(row)]; }
  int count() const { return int(program_.instructions.size()); }

  // Edits; each emits edited(). Rows out of range are ignored (false).
  void insert(int row, const xmate::teach::Instruction& instruction);
  bool remove(int row);
  bool move(int from, int to);  // to: the row the instruction ends up at
  bool duplicate(int row);      // the copy goes right after the original
  bool replaceTarget(int row, const xmate::teach::Target& target);  // MOVEJ / MOVEL / MOVEC rows only
  bool replaceVia(int row, const xmate::teach::Target& via);  // MOVEC rows only
  // Replaces a logic instruction (WAIT, SET_DO, WAIT_DI) with another one, keeping its name.
  bool replaceLogic(int row, const xmate::teach::Instruction& logic);
  // MOVEJ <-> MOVEL always; MOVEC -> MOVEJ/MOVEL drops the via point; nothing becomes MOVEC (it needs
  // a via point: record one as C). A PATH keeps its type, and nothing becomes one (it is recorded).
  static bool canChangeType(const xmate::teach::Instruction& in, xmate::teach::InstructionType to);
  bool changeType(int row, xmate::teach::InstructionType to);

  // The row shown as running (-1: none).
  void setCurrent(int row);
  int current() const { return current_; }

  // "<prefix><n>" ("P3", "Path 2") with the smallest n not used by a name yet.
  QString nextName(const QString& prefix = QStringLiteral("P")) const;
  // The prefix new names of an instruction of this type take: "Path " for PATH, else "P".
  static QString namePrefix(xmate::teach::InstructionType type);
  // One line describing an instruction: its targets or its parameters.
  QString details(const xmate::teach::Instruction& in) const;  // signals named as on the program's robot

  // What the last run said about each instruction (one line per row, "" for none), shown in the
  // row's tooltip. Cleared by any edit that moves rows or changes the program (it no longer applies).
  void setResults(const QStringList& per_row);
  QString result(int row) const { return row >= 0 && row < results_.size() ? results_[row] : QString(); }

  // QAbstractTableModel
  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role) const override;
  QVariant headerData(int section, Qt::Orientation orientation, int role) const override;
  Qt::ItemFlags flags(const QModelIndex& index) const override;
  bool setData(const QModelIndex& index, const QVariant& value, int role) override;
  Qt::DropActions supportedDropActions() const override;
  QStringList mimeTypes() const override;
  QMimeData* mimeData(const QModelIndexList& indexes) const override;
  bool dropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                    const QModelIndex& parent) override;

 signals:
  // The program changed through an edit (not through setProgram(..., false) or setCurrent()).
  void edited();

 private:
  // A PATH's summary ("8.2 s · 0.63 m TCP · 820 samples @ 100 Hz"): forward kinematics over every
  // sample, so remembered by the path's content and the program's tool (the table paints often).
  QString pathDetails(const xmate::teach::JointPath& path) const;
  void clearResults();

  xmate::teach::Program program_;
  int current_ = -1;
  QStringList results_;
  mutable QHash<quint64, QString> path_details_;
};

}  // namespace rci::ui
