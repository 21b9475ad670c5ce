// SPDX-License-Identifier: Apache-2.0
// Program panel: New / Open / Save / Save as, the unsaved-changes prompt (maybeSaveProgram, also the
// window's close hook) and the dialogs behind replaceable functions (tests avoid modal dialogs).
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>

#include "panels/program_model.h"
#include "panels/program_panel.h"
#include "session/session.h"
#include "teach/program_io.h"

namespace rci::ui {

void ProgramPanel::setDialogs(Dialogs dialogs) {
  const QString filter = tr("RCI programs (*.json);;All files (*)");
  if (!dialogs.open_path)
    dialogs.open_path = [this, filter] {
      const QString dir = loadValue(QStringLiteral("lastDir"), QDir::homePath()).toString();
      return QFileDialog::getOpenFileName(this, tr("Open program"), dir, filter);
    };
  if (!dialogs.save_path)
    dialogs.save_path = [this, filter](const QString& suggested) {
      QString path = QFileDialog::getSaveFileName(this, tr("Save program"), suggested, filter);
      if (!path.isEmpty() && QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".json");
      return path;
    };
  if (!dialogs.unsaved)
    dialogs.unsaved = [this] {
      const auto answer = QMessageBox::question(
          this, tr("Unsaved program"), tr("The program has unsaved changes. Save them?"),
          QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
      return answer == QMessageBox::Save      ? UnsavedChoice::kSave
             : answer == QMessageBox::Discard ? UnsavedChoice::kDiscard
                                              : UnsavedChoice::kCancel;
    };
  dialogs_ = std::move(dialogs);
}

bool maybeSaveProgram(QWidget* root) {
  auto* panel = root ? root->findChild<ProgramPanel*>() : nullptr;
  return !panel || panel->maybeSaveProgram();
}

bool ProgramPanel::maybeSaveProgram() {
  if (!modified_) return true;
  switch (dialogs_.unsaved()) {
    case UnsavedChoice::kSave: return saveClicked();
    case UnsavedChoice::kDiscard: return true;
    case UnsavedChoice::kCancel: return false;
  }
  return false;
}

void ProgramPanel::newClicked() {
  if (running_) {
    showStatus(tr("New: a run is active — stop it first."), true);
    return;
  }
  if (refusedWhileRecording(tr("New"))) return;
  if (!maybeSaveProgram()) return;
  newProgram();
  showStatus(tr("New program."), false);
}

void ProgramPanel::newProgram() {
  xmate::teach::Program empty;
  empty.robot = &spec();
  model_->setProgram(empty);
  path_.clear();
  modified_ = false;
  cancelPendingVia();
  resetRunDisplay();
  updateTitle();
  updateButtons();
  updateOverlay();
}

void ProgramPanel::openClicked() {
  if (running_) {
    showStatus(tr("Open: a run is active — stop it first."), true);
    return;
  }
  if (refusedWhileRecording(tr("Open"))) return;
  if (!maybeSaveProgram()) return;
  const QString path = dialogs_.open_path();
  if (!path.isEmpty()) openFile(path);
}

bool ProgramPanel::openFile(const QString& path) {
  xmate::teach::Program loaded;
  try {
    loaded = xmate::teach::loadProgram(path.toStdString());
  } catch (const std::exception& e) {
    note(tr("Open failed: %1 — the program shown was not changed.").arg(QString::fromStdString(e.what())), true, path);
    return false;
  }
  model_->setProgram(loaded);
  path_ = path;
  modified_ = false;
  cancelPendingVia();
  saveValue(QStringLiteral("lastDir"), QFileInfo(path).absolutePath());
  resetRunDisplay();
  updateTitle();
  updateButtons();
  updateOverlay();
  QString note;
  if (isOpen()) {
    try {
      xmate::teach::requireRobot(loaded, spec());
    } catch (const std::exception& e) {
      note = QStringLiteral(" ") + QString::fromStdString(e.what());
    }
  }
  this->note(tr("Opened %1: %n instruction(s).", nullptr, int(loaded.instructions.size())).arg(QFileInfo(path).fileName()) + note,
             !note.isEmpty(), path);
  return true;
}

bool ProgramPanel::saveClicked() { return path_.isEmpty() ? saveAsClicked() : saveFile(path_); }

bool ProgramPanel::saveAsClicked() {
  const QString dir = loadValue(QStringLiteral("lastDir"), QDir::homePath()).toString();
  const QString suggested = path_.isEmpty() ? QDir(dir).filePath(QStringLiteral("program.json")) : path_;
  const QString path = dialogs_.save_path(suggested);
  return !path.isEmpty() && saveFile(path);
}

bool ProgramPanel::saveFile(const QString& path) {
  const auto& p = program();
  try {
    for (size_t i = 0; i < p.instructions.size(); ++i) xmate::teach::validateInstruction(p.instructions[i], i, *p.robot);
    xmate::teach::saveProgram(path.toStdString(), p);
  } catch (const std::exception& e) {
    note(tr("Save failed: %1 — nothing was written; fix it and save again.").arg(QString::fromStdString(e.what())), true, path);
    return false;
  }
  path_ = path;
  modified_ = false;
  saveValue(QStringLiteral("lastDir"), QFileInfo(path).absolutePath());
  updateTitle();
  note(tr("Saved %1.").arg(QFileInfo(path).fileName()), false, path);
  return true;
}

}  // namespace rci::ui
