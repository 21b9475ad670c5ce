// SPDX-License-Identifier: Apache-2.0
// Command-line options of rci-studio (QCommandLineParser): --model, --robot HOST:PORT | rsi:FILE,
// --ft-sensor HOST[:PORT], --context FILE, --lockstep, --screenshot FILE, -h/--help, -v/--version.
// Any thread (parsing reads the RSI files named).
#pragma once

#include <QString>
#include <QStringList>

#include "session/session.h"

struct StudioOptions {
  rci::ui::SessionTarget target;  // what to connect to at start
  bool model_given = false;       // --model was on the command line
  QString screenshot;             // empty: run interactively
  bool help = false;
  bool help_all = false;          // --help-all: the help with Qt's own options (showStudioHelpAll)
  bool version = false;
};

// Parses arguments (without argv[0]). false and error set (what was wrong, what to do) on bad input.
bool parseStudioOptions(const QStringList& arguments, StudioOptions& options, QString& error);
QString studioUsage();
// Prints the help with Qt's own options and exits 0 (QCommandLineParser::process); needs a
// QCoreApplication.
[[noreturn]] void showStudioHelpAll();
