// SPDX-License-Identifier: Apache-2.0
// The --screenshot run of rci-studio (screenshot.h).
#include "screenshot.h"

#include <QCoreApplication>
#include <QTimer>

#include <cstdio>

#include "session/session.h"
#include "window/main_window.h"
#include "window/window_capture.h"

namespace {

constexpr int kSettleMs = 2000;   // after the first states: let the 3D view render a few frames
constexpr int kLimitMs = 60000;   // give up after this long

void finish(int code, const QString& message) {
  std::fprintf(code == 0 ? stdout : stderr, "%s\n", qPrintable(message));
  QCoreApplication::exit(code);
}

void capture(rci::ui::MainWindow& window, const QString& path) {
  rci::ui::captureWindow(window, [path](const QImage& image, bool scene_captured) {
    QString error;
    if (!rci::ui::savePng(image, path, error)) {
      finish(1, QStringLiteral("rci-studio: %1").arg(error));
      return;
    }
    finish(0, QStringLiteral("rci-studio: saved %1 (%2x%3)%4")
                  .arg(path)
                  .arg(image.width())
                  .arg(image.height())
                  .arg(scene_captured ? QString() : QStringLiteral("; the 3D view showed its placeholder "
                                                                   "(no OpenGL: run under xvfb-run)")));
  });
}

}  // namespace

void takeScreenshotWhenReady(rci::ui::MainWindow& window, const QString& path) {
  rci::ui::Session& session = window.session();
  auto* armed = new QObject(&window);  // owns the connections; deleted once the capture started
  QObject::connect(&session, &rci::ui::Session::openFailed, armed, [](const QString& reason) {
    finish(1, QStringLiteral("rci-studio: cannot take the screenshot: %1").arg(reason));
  });
  QObject::connect(&session, &rci::ui::Session::tick, armed, [&window, &session, path, armed] {
    if (!session.live().has_state && !session.live().has_arm_state) return;  // an xMate's state, or a KUKA's
    armed->deleteLater();
    QTimer::singleShot(kSettleMs, &window, [&window, path] { capture(window, path); });
  });
  QTimer::singleShot(kLimitMs, &window, [] {
    finish(1, QStringLiteral("rci-studio: cannot take the screenshot: the simulator sent no state within 60 s"));
  });
}
