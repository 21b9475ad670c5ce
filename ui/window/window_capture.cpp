// SPDX-License-Identifier: Apache-2.0
// Whole-window screenshots (window_capture.h).
#include "window/window_capture.h"

#include <QPainter>
#include <QPixmap>
#include <QPointer>
#include <QSaveFile>

#include "window/main_window.h"
#include "window/parts.h"

namespace rci::ui {

void captureWindow(MainWindow& window, std::function<void(const QImage&, bool)> done) {
  QPointer<MainWindow> guard(&window);
  captureRobotView(window.robotView(), [guard, done = std::move(done)](const QImage& scene) {
    if (!guard) return;
    const QPixmap grab = guard->grab();
    QImage image = grab.toImage().convertToFormat(QImage::Format_RGB32);
    if (!scene.isNull()) {
      QWidget* view = guard->robotView();
      const qreal ratio = grab.devicePixelRatio();
      const QPoint at = view->mapTo(guard.data(), QPoint(0, 0));
      QPainter painter(&image);
      painter.drawImage(QRectF(at.x() * ratio, at.y() * ratio, view->width() * ratio, view->height() * ratio), scene);
    }
    done(image, !scene.isNull());
  });
}

bool savePng(const QImage& image, const QString& path, QString& error) {
  QSaveFile file(path);
  if (!file.open(QIODevice::WriteOnly)) {
    error = QStringLiteral("cannot write %1: %2").arg(path, file.errorString());
    return false;
  }
  if (!image.save(&file, "PNG") || !file.commit()) {
    error = QStringLiteral("cannot write %1: %2").arg(path, file.errorString());
    return false;
  }
  return true;
}

}  // namespace rci::ui
