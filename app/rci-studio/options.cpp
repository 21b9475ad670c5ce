// SPDX-License-Identifier: Apache-2.0
// Parsing of rci-studio's command line (options.h) with QCommandLineParser: -h/--help, -v/--version,
// "--opt value" and "--opt=value"; our checks of the values on top.
#include "options.h"

#include <QCommandLineParser>

#include <cstdlib>

#include "window/target_settings.h"

namespace {

struct StudioParser {
  QCommandLineParser parser;
  QCommandLineOption help = parser.addHelpOption();
  QCommandLineOption version = parser.addVersionOption();
  QCommandLineOption model{QStringLiteral("model"),
                           QStringLiteral("Robot model: xmate7_pro (default), xmate3_pro, xmate7, xmate3."),
                           QStringLiteral("NAME")};
  QCommandLineOption robot{QStringLiteral("robot"),
                           QStringLiteral("Connect to the robot controller at HOST:PORT instead of the simulator."),
                           QStringLiteral("HOST:PORT")};
  QCommandLineOption lockstep{QStringLiteral("lockstep"),
                              QStringLiteral("Run the built-in simulator in lock-step (deterministic) clock.")};
  QCommandLineOption screenshot{QStringLiteral("screenshot"),
                                QStringLiteral("Start, connect to the simulator, save the window as a PNG, exit."),
                                QStringLiteral("FILE")};

  StudioParser() {
    parser.setApplicationDescription(QStringLiteral(
        "Watch and control a ROKAE xMate robot over RCI, or the built-in simulator (the default).\n"
        "Bad options exit with status 2."));
    parser.addOptions({model, robot, lockstep, screenshot});
  }
};

}  // namespace

QString studioUsage() {
  StudioParser p;
  // Without a QCoreApplication (--help runs without a display) Qt cannot know the program's name.
  return p.parser.helpText().replace(QLatin1String("<executable_name>"), QLatin1String("rci-studio"));
}

void showStudioHelpAll() {
  StudioParser p;
  p.parser.process(QStringList{QStringLiteral("rci-studio"), QStringLiteral("--help-all")});  // prints and exits 0
  std::exit(0);
}

bool parseStudioOptions(const QStringList& arguments, StudioOptions& options, QString& error) {
  options.target.kind = rci::ui::SessionTarget::Kind::kSimulator;
  options.target.loopback = true;
  StudioParser p;
  if (!p.parser.parse(QStringList{QStringLiteral("rci-studio")} + arguments)) {
    const QStringList unknown = p.parser.unknownOptionNames();
    if (!unknown.isEmpty()) {
      const QString& name = unknown.first();
      error = QStringLiteral("unknown option \"%1%2\" (see --help)")
                  .arg(QLatin1String(name.size() == 1 ? "-" : "--"), name);
    } else {
      error = p.parser.errorText() + QStringLiteral(" (see --help)");
      // Qt's "Missing value after '--screenshot'." in our words.
      static const QString missing = QStringLiteral("Missing value after '");
      if (error.startsWith(missing))
        error = error.mid(missing.size()).section(QLatin1Char('\''), 0, 0) + QStringLiteral(" needs a value (see --help)");
    }
    return false;
  }
  if (!p.parser.positionalArguments().isEmpty()) {
    error = QStringLiteral("unexpected argument \"%1\": rci-studio takes options only (see --help)")
                .arg(p.parser.positionalArguments().first());
    return false;
  }
  options.help = p.parser.isSet(p.help);
  options.help_all = p.parser.isSet(QStringLiteral("help-all"));
  options.version = p.parser.isSet(p.version);
  // "--screenshot --lockstep": the next option is not a value (Qt would take it as one).
  for (const QCommandLineOption* option : {&p.model, &p.robot, &p.screenshot}) {
    if (p.parser.isSet(*option) && p.parser.value(*option).startsWith(QLatin1String("--"))) {
      error = QStringLiteral("--%1 needs a value (see --help)").arg(option->names().first());
      return false;
    }
  }
  options.target.lockstep = p.parser.isSet(p.lockstep);
  if (p.parser.isSet(p.model)) {
    const QString value = p.parser.value(p.model);
    if (!rci::ui::parseModel(value, options.target.type)) {
      error = QStringLiteral("unknown model \"%1\": use xmate7_pro, xmate3_pro, xmate7 or xmate3").arg(value);
      return false;
    }
    options.model_given = true;
  }
  if (p.parser.isSet(p.robot)) {
    if (!rci::ui::parseHostPort(p.parser.value(p.robot), options.target.host, options.target.port, error)) return false;
    options.target.kind = rci::ui::SessionTarget::Kind::kRobot;
  }
  options.screenshot = p.parser.value(p.screenshot);
  if (!options.screenshot.isEmpty() && options.target.kind == rci::ui::SessionTarget::Kind::kRobot) {
    error = QStringLiteral("--screenshot uses the built-in simulator; leave out --robot");
    return false;
  }
  return true;
}
