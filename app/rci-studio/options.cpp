// SPDX-License-Identifier: Apache-2.0
// Parsing of rci-studio's command line (options.h).
#include "options.h"

#include "window/target_settings.h"

namespace {

bool takeValue(const QStringList& arguments, int& i, QString& value, QString& error) {
  const QString name = arguments[i];
  if (i + 1 >= arguments.size() || arguments[i + 1].startsWith(QLatin1String("--"))) {
    error = QStringLiteral("%1 needs a value (see --help)").arg(name);
    return false;
  }
  value = arguments[++i];
  return true;
}

}  // namespace

QString studioUsage() {
  return QStringLiteral(
      "Usage: rci-studio [options]\n"
      "Watch and control a ROKAE xMate robot over RCI, or the built-in simulator (the default).\n\n"
      "Options:\n"
      "  --model NAME         robot model: xmate7_pro (default), xmate3_pro, xmate7, xmate3\n"
      "  --robot HOST:PORT    connect to the robot controller at HOST:PORT instead of the simulator\n"
      "  --lockstep           run the built-in simulator in lock-step (deterministic) clock\n"
      "  --screenshot FILE    start, connect to the simulator, save the window as a PNG, exit\n"
      "  --version            print the version and exit\n"
      "  --help               print this help and exit\n");
}

bool parseStudioOptions(const QStringList& arguments, StudioOptions& options, QString& error) {
  options.target.kind = rci::ui::SessionTarget::Kind::kSimulator;
  options.target.loopback = true;
  for (int i = 0; i < arguments.size(); ++i) {
    const QString& argument = arguments[i];
    QString value;
    if (argument == QLatin1String("--help") || argument == QLatin1String("-h")) {
      options.help = true;
    } else if (argument == QLatin1String("--version")) {
      options.version = true;
    } else if (argument == QLatin1String("--lockstep")) {
      options.target.lockstep = true;
    } else if (argument == QLatin1String("--model")) {
      if (!takeValue(arguments, i, value, error)) return false;
      if (!rci::ui::parseModel(value, options.target.type)) {
        error = QStringLiteral("unknown model \"%1\": use xmate7_pro, xmate3_pro, xmate7 or xmate3").arg(value);
        return false;
      }
      options.model_given = true;
    } else if (argument == QLatin1String("--robot")) {
      if (!takeValue(arguments, i, value, error)) return false;
      if (!rci::ui::parseHostPort(value, options.target.host, options.target.port, error)) return false;
      options.target.kind = rci::ui::SessionTarget::Kind::kRobot;
    } else if (argument == QLatin1String("--screenshot")) {
      if (!takeValue(arguments, i, value, error)) return false;
      options.screenshot = value;
    } else {
      error = QStringLiteral("unknown option \"%1\" (see --help)").arg(argument);
      return false;
    }
  }
  if (!options.screenshot.isEmpty() && options.target.kind == rci::ui::SessionTarget::Kind::kRobot) {
    error = QStringLiteral("--screenshot uses the built-in simulator; leave out --robot");
    return false;
  }
  return true;
}
