// SPDX-License-Identifier: Apache-2.0
// The 3D view's camera as an orbit around a target point, z up: rotate, pan, zoom, framing, and
// the pointer ray for picking. Plain maths, no Qt3D, so it is testable on its own.
#pragma once

#include <QMatrix4x4>
#include <QPointF>
#include <QSizeF>
#include <QVector3D>

namespace rci::ui {

struct Ray {
  QVector3D origin;
  QVector3D direction;  // unit
};

struct OrbitCamera {
  QVector3D target{0, 0, 0.45f};
  float yaw_deg = 35;     // about z, from +x
  float pitch_deg = 24;   // above the xy plane
  float distance = 2.6f;  // m
  float fov_deg = 40;     // vertical field of view

  QVector3D position() const;
  QVector3D forward() const;  // unit, from the camera to the target
  // Frames a robot of the given reach standing at the origin.
  static OrbitCamera framing(double reach);
  // Pointer drag by (dx, dy) pixels.
  void rotate(float dx, float dy);
  void pan(float dx, float dy, float viewport_height);
  // Wheel steps (positive: closer).
  void zoom(float steps);
  // The ray through a pixel of a viewport of the given size.
  Ray ray(const QPointF& pixel, const QSizeF& viewport) const;
  // Where a world point lands in the viewport (pixels); false if behind the camera.
  bool project(const QVector3D& point, const QSizeF& viewport, QPointF& pixel) const;
  QMatrix4x4 viewProjection(const QSizeF& viewport) const;
};

// The point where ray meets the plane through plane_point with normal plane_normal; the ray's
// origin if they are parallel.
QVector3D intersectPlane(const Ray& ray, const QVector3D& plane_point, const QVector3D& plane_normal);

}  // namespace rci::ui
