// SPDX-License-Identifier: Apache-2.0
// OpenGL availability check of the 3D view (gl_probe.h).
#include "gl_probe.h"

#include <QCoreApplication>
#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>

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
  GlProbe probe{true, {}, {}, false};
  const auto* name = reinterpret_cast<const char*>(context.functions()->glGetString(GL_RENDERER));
  probe.renderer = name != nullptr ? QString::fromLatin1(name) : QString();
  probe.software = isSoftwareRenderer(probe.renderer);
  context.doneCurrent();
  return probe;
}

bool isSoftwareRenderer(const QString& renderer) {
  for (const char* cpu : {"llvmpipe", "softpipe", "swrast", "Software Rasterizer", "SwiftShader"})
    if (renderer.contains(QLatin1String(cpu), Qt::CaseInsensitive)) return true;
  return false;
}

}  // namespace rci::ui
