// OpenGL availability check of the 3D view (gl_probe.h).
#include "gl_probe.h"

#include <QCoreApplication>
#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>

namespace rci::ui {

GlProbe probeOpenGl() {
  const QString platform = QGuiApplication::platformName();
  if (platform == QLatin1String("offscreen") || platform == QLatin1String("minimal")) {
    return {false, QCoreApplication::translate("RobotView", "the Qt platform \"%1\" has no display").arg(platform)};
  }
  QOpenGLContext context;
  if (!context.create()) return {false, QCoreApplication::translate("RobotView", "no OpenGL context could be created")};
  QOffscreenSurface surface;
  surface.setFormat(context.format());
  surface.create();
  if (!surface.isValid()) return {false, QCoreApplication::translate("RobotView", "no OpenGL surface could be created")};
  if (!context.makeCurrent(&surface)) {
    return {false, QCoreApplication::translate("RobotView", "the OpenGL context could not be made current")};
  }
  context.doneCurrent();
  return {true, {}};
}

}  // namespace rci::ui
