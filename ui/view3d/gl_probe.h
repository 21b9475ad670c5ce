// SPDX-License-Identifier: Apache-2.0
// Can this process show a Qt3D window? Checked before the 3D view creates one: Qt3D's renderer
// hangs under the offscreen platform (docs/architecture.md, "The 3D view").
#pragma once

#include <QString>

namespace rci::ui {

struct GlProbe {
  bool ok = false;
  QString reason;    // why not (empty when ok)
  QString renderer;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  bool software = false;  // rendered on the CPU (Mesa llvmpipe, softpipe, swrast)
};

// True for the GL_RENDERER strings of CPU rasterisers.
bool isSoftwareRenderer(const QString& renderer);

// False on the "offscreen" and "minimal" platforms, or when no OpenGL context can be created and
// made current on an offscreen surface; otherwise also names the renderer. Needs a QGuiApplication.
GlProbe probeOpenGl();

}  // namespace rci::ui
