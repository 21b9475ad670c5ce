// Can this process show a Qt3D window? Checked before the 3D view creates one: Qt3D's renderer
// hangs under the offscreen platform (DESIGN.md, "3D view").
#pragma once

#include <QString>

namespace rci::ui {

struct GlProbe {
  bool ok = false;
  QString reason;  // why not (empty when ok)
};

// False on the "offscreen" and "minimal" platforms, or when no OpenGL context can be created and
// made current on an offscreen surface. Needs a QGuiApplication.
GlProbe probeOpenGl();

}  // namespace rci::ui
