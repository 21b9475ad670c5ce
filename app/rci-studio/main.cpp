// SPDX-License-Identifier: Apache-2.0
// rci-studio: the operator window. Parses the options, sets up the application (Fusion
// style, icon, settings names), shows the main window and connects to the target.
#include <QApplication>
#include <QDir>
#include <QSettings>

#include <cstdio>

#include "options.h"
#include "screenshot.h"
#include "session/session.h"
#include "window/main_window.h"
#include "window/target_settings.h"

namespace {

void setUpApplication() {
  QApplication::setOrganizationName(QStringLiteral("RCI Studio"));
  QApplication::setApplicationName(QStringLiteral("rci-studio"));
  QApplication::setApplicationDisplayName(QStringLiteral("RCI Studio"));
  QApplication::setApplicationVersion(QStringLiteral(RCI_VERSION));
  QGuiApplication::setDesktopFileName(QStringLiteral("rci-studio"));
  rci::ui::applyStudioStyle();
}

// Screenshots use a fresh, throw-away settings store: the default layout, not the user's.
QString useTemporarySettings() {
  const QString dir = QDir::temp().filePath(QStringLiteral("rci-studio-screenshot-%1").arg(QCoreApplication::applicationPid()));
  QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, dir);
  QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, dir);
  return dir;
}

}  // namespace

int main(int argc, char** argv) {
  QStringList arguments;
  for (int i = 1; i < argc; ++i) arguments << QString::fromLocal8Bit(argv[i]);
  StudioOptions options;
  QString error;
  if (!parseStudioOptions(arguments, options, error)) {
    std::fprintf(stderr, "rci-studio: %s\n", qPrintable(error));
    return 2;
  }
  if (options.help_all) {
    QCoreApplication core(argc, argv);
    showStudioHelpAll();
  }
  if (options.help) {
    std::printf("%s", qPrintable(studioUsage()));
    return 0;
  }
  if (options.version) {
    std::printf("rci-studio %s\n", RCI_VERSION);
    return 0;
  }

  QApplication app(argc, argv);
  setUpApplication();
  const QString temporary_settings = options.screenshot.isEmpty() ? QString() : useTemporarySettings();

  // Without --model, the simulator simulates the model last used (xMate7 Pro the first time): after
  // a KUKA (simulated or over RSI), the built-in KUKA simulator of that model.
  if (!options.model_given && options.screenshot.isEmpty()) {
    if (std::optional<rci::ui::SessionTarget> last = rci::ui::lastTarget()) {
      options.target.type = last->type;
      if (last->isKuka() && options.target.kind == rci::ui::SessionTarget::Kind::kSimulator &&
          !options.target.lockstep) {
        options.target.kind = rci::ui::SessionTarget::Kind::kKukaSimulator;
        options.target.kuka_model = last->kuka_model;
      }
    }
  }

  rci::ui::Session session;
  rci::ui::MainWindow window(session);
  window.show();
  window.connectTo(options.target);
  if (!options.screenshot.isEmpty()) takeScreenshotWhenReady(window, options.screenshot);
  const int code = app.exec();
  if (!temporary_settings.isEmpty()) QDir(temporary_settings).removeRecursively();
  return code;
}
