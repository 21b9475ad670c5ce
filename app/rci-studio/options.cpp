// SPDX-License-Identifier: Apache-2.0
// Parsing of rci-studio's command line (options.h) with QCommandLineParser: -h/--help, -v/--version,
// "--opt value" and "--opt=value"; our checks of the values on top.
#include "options.h"

#include <QCommandLineParser>
#include <QFileInfo>

#include <cstdlib>

#include "rsi/config.h"
#include "window/target_settings.h"

namespace {

struct StudioParser {
  QCommandLineParser parser;
  QCommandLineOption help = parser.addHelpOption();
  QCommandLineOption version = parser.addVersionOption();
  QCommandLineOption model{QStringLiteral("model"),
                           QStringLiteral("Robot model: xmate7_pro (default), xmate3_pro, xmate7, xmate3 (ROKAE "
                                          "xMate, over RCI); kr6_r900_sixx, kr16_2 (KUKA, over RSI). A KUKA model "
                                          "without --robot opens the built-in KUKA simulator."),
                           QStringLiteral("NAME")};
  QCommandLineOption robot{QStringLiteral("robot"),
                           QStringLiteral("Connect to the xMate controller at HOST:PORT instead of the simulator; or, "
                                          "with rsi:FILE and a KUKA --model, wait for a KUKA robot's RSI at the "
                                          "address its Ethernet config FILE names."),
                           QStringLiteral("HOST:PORT")};
  QCommandLineOption ft_sensor{QStringLiteral("ft-sensor"),
                               QStringLiteral("KUKA over RSI: the force/torque sensor at HOST[:PORT] (RDT, port "
                                              "49152 by default), for hand guiding."),
                               QStringLiteral("HOST[:PORT]")};
  QCommandLineOption context{QStringLiteral("context"),
                             QStringLiteral("KUKA over RSI: the RSI context the robot runs (NAME.rsi.xml); by default "
                                            "the one beside the Ethernet config that names it."),
                             QStringLiteral("FILE")};
  QCommandLineOption lockstep{QStringLiteral("lockstep"),
                              QStringLiteral("Run the built-in xMate simulator in lock-step (deterministic) clock.")};
  QCommandLineOption screenshot{QStringLiteral("screenshot"),
                                QStringLiteral("Start, connect to the simulator, save the window as a PNG, exit."),
                                QStringLiteral("FILE")};

  StudioParser() {
    parser.setApplicationDescription(QStringLiteral(
        "Watch and control a ROKAE xMate robot over RCI or a KUKA robot over RSI, or the built-in simulator of\n"
        "either (the default: the xMate simulator, or the simulator of the model last used).\n"
        "  rci-studio --model kr6_r900_sixx                          the built-in KUKA simulator\n"
        "  rci-studio --robot rsi:RSI_EthernetConfig.xml --model kr6_r900_sixx [--ft-sensor 192.168.1.1]\n"
        "                                                            a KUKA robot over RSI\n"
        "Bad options exit with status 2."));
    parser.addOptions({model, robot, ft_sensor, context, lockstep, screenshot});
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
  for (const QCommandLineOption* option : {&p.model, &p.robot, &p.ft_sensor, &p.context, &p.screenshot}) {
    if (p.parser.isSet(*option) && p.parser.value(*option).startsWith(QLatin1String("--"))) {
      error = QStringLiteral("--%1 needs a value (see --help)").arg(option->names().first());
      return false;
    }
  }
  options.target.lockstep = p.parser.isSet(p.lockstep);
  bool kuka = false;
  if (p.parser.isSet(p.model)) {
    const QString value = p.parser.value(p.model);
    if (!rci::ui::parseAnyModel(value, options.target.type, options.target.kuka_model, kuka)) {
      error = QStringLiteral("unknown model \"%1\": use xmate7_pro, xmate3_pro, xmate7 or xmate3 (xMate), or "
                             "kr6_r900_sixx or kr16_2 (KUKA)")
                  .arg(value);
      return false;
    }
    options.model_given = true;
  }
  const QString model = p.parser.value(p.model).trimmed().toLower();
  if (p.parser.isSet(p.robot)) {
    const QString value = p.parser.value(p.robot).trimmed();
    if (value.startsWith(QLatin1String("rsi:"), Qt::CaseInsensitive)) {
      const QString path = value.mid(4).trimmed();
      if (path.isEmpty()) {
        error = QStringLiteral("--robot rsi: needs the robot's RSI Ethernet config file after it, e.g. "
                               "--robot rsi:RSI_EthernetConfig.xml --model kr6_r900_sixx");
        return false;
      }
      if (!options.model_given) {
        error = QStringLiteral("--robot rsi:%1 needs the KUKA's model: add --model kr6_r900_sixx or --model kr16_2")
                    .arg(path);
        return false;
      }
      if (!kuka) {
        error = QStringLiteral("%1 is an xMate, which connects over RCI: use --robot HOST:PORT with it, or give the "
                               "KUKA's model (--model kr6_r900_sixx or --model kr16_2) for rsi:%2")
                    .arg(model, path);
        return false;
      }
      if (!QFileInfo(path).isFile()) {
        error = QStringLiteral("the RSI Ethernet config \"%1\" does not exist: give the path of the robot's Ethernet "
                               "config file (copied from the controller), e.g. --robot rsi:RSI_EthernetConfig.xml")
                    .arg(path);
        return false;
      }
      QString listen;
      if (!rci::ui::rsiListenAddress(path, listen, error)) return false;
      options.target.kind = rci::ui::SessionTarget::Kind::kKukaRobot;
      options.target.rsi_config = QFileInfo(path).absoluteFilePath();
    } else {
      if (kuka) {
        error = QStringLiteral("%1 is a KUKA, which connects over RSI: use --robot rsi:ETHERNET.xml (the robot's RSI "
                               "Ethernet config file), or leave out --robot for the built-in KUKA simulator")
                    .arg(model);
        return false;
      }
      if (!rci::ui::parseHostPort(value, options.target.host, options.target.port, error)) return false;
      options.target.kind = rci::ui::SessionTarget::Kind::kRobot;
    }
  } else if (kuka) {
    options.target.kind = rci::ui::SessionTarget::Kind::kKukaSimulator;
  }
  const bool kuka_robot = options.target.kind == rci::ui::SessionTarget::Kind::kKukaRobot;
  if (p.parser.isSet(p.ft_sensor)) {
    if (!kuka_robot) {
      error = QStringLiteral("--ft-sensor is for a KUKA over RSI (--robot rsi:FILE --model kr6_r900_sixx); the "
                             "built-in KUKA simulator has its own sensor: leave out --ft-sensor");
      return false;
    }
    if (!rci::ui::parseSensorAddress(p.parser.value(p.ft_sensor), options.target.ft_sensor, error)) return false;
  }
  if (p.parser.isSet(p.context)) {
    if (!kuka_robot) {
      error = QStringLiteral("--context is for a KUKA over RSI (--robot rsi:FILE --model kr6_r900_sixx); the "
                             "built-in KUKA simulator runs its own sample context: leave out --context");
      return false;
    }
    const QString path = p.parser.value(p.context).trimmed();
    if (!QFileInfo(path).isFile()) {
      error = QStringLiteral("the RSI context \"%1\" does not exist: give the NAME.rsi.xml the robot runs (copied "
                             "from the controller), or leave out --context to use the one beside the Ethernet config")
                  .arg(path);
      return false;
    }
    try {
      xmate::rsi::readContext(path.toStdString());
    } catch (const std::exception& e) {
      error = QStringLiteral("the RSI context cannot be used: %1").arg(QString::fromStdString(e.what()));
      return false;
    }
    options.target.rsi_context = QFileInfo(path).absoluteFilePath();
  } else if (kuka_robot) {
    // The context the robot runs, beside the Ethernet config: exactly one must name it.
    const std::vector<std::string> found = xmate::rsi::contextsNaming(options.target.rsi_config.toStdString());
    if (found.size() != 1) {
      QStringList names;
      for (const std::string& context : found) names << QFileInfo(QString::fromStdString(context)).fileName();
      const QString file = QFileInfo(options.target.rsi_config).fileName();
      error = found.empty()
                  ? QStringLiteral("no RSI context (NAME.rsi.xml) beside %1 uses it: copy the context the robot runs "
                                   "next to it, or give it with --context NAME.rsi.xml")
                        .arg(file)
                  : QStringLiteral("%1 RSI contexts beside %2 use it (%3): say which one the robot runs with "
                                   "--context NAME.rsi.xml")
                        .arg(found.size())
                        .arg(file, names.join(QStringLiteral(", ")));
      return false;
    }
  }
  if (options.target.lockstep && options.target.isKuka()) {
    error = QStringLiteral("--lockstep is for the built-in xMate simulator; the KUKA runs on its own clock: leave "
                           "out --lockstep");
    return false;
  }
  options.screenshot = p.parser.value(p.screenshot);
  if (!options.screenshot.isEmpty() && !options.target.isSimulator()) {
    error = QStringLiteral("--screenshot uses the built-in simulator; leave out --robot");
    return false;
  }
  return true;
}
