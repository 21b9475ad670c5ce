// SPDX-License-Identifier: Apache-2.0
// Orbit camera maths (orbit_camera.h).
#include "orbit_camera.h"

#include <QtMath>

#include <algorithm>
#include <cmath>

namespace rci::ui {

QVector3D OrbitCamera::forward() const {
  const float yaw = qDegreesToRadians(yaw_deg), pitch = qDegreesToRadians(pitch_deg);
  return -QVector3D(std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), std::sin(pitch));
}

QVector3D OrbitCamera::position() const { return target - forward() * distance; }

OrbitCamera OrbitCamera::framing(double reach) {
  OrbitCamera c;
  c.target = QVector3D(0.12f * float(reach), 0, float(0.3 * reach));
  c.distance = float(1.75 * reach);
  return c;
}

void OrbitCamera::rotate(float dx, float dy) {
  yaw_deg = std::fmod(yaw_deg - 0.4f * dx, 360.0f);
  pitch_deg = std::clamp(pitch_deg + 0.4f * dy, -85.0f, 85.0f);
}

void OrbitCamera::pan(float dx, float dy, float viewport_height) {
  const QVector3D f = forward();
  const QVector3D right = QVector3D::crossProduct(f, QVector3D(0, 0, 1)).normalized();
  const QVector3D up = QVector3D::crossProduct(right, f).normalized();
  const float metres_per_pixel =
      2.0f * distance * std::tan(qDegreesToRadians(fov_deg) / 2) / std::max(1.0f, viewport_height);
  target += (-right * dx + up * dy) * metres_per_pixel;
}

void OrbitCamera::zoom(float steps) { distance = std::clamp(distance * std::pow(0.88f, steps), 0.2f, 30.0f); }

QMatrix4x4 OrbitCamera::viewProjection(const QSizeF& viewport) const {
  QMatrix4x4 projection, view;
  const float aspect = float(viewport.width() / std::max(1.0, viewport.height()));
  projection.perspective(fov_deg, aspect, 0.02f, 100.0f);
  view.lookAt(position(), target, QVector3D(0, 0, 1));
  return projection * view;
}

Ray OrbitCamera::ray(const QPointF& pixel, const QSizeF& viewport) const {
  const QMatrix4x4 inverse = viewProjection(viewport).inverted();
  const float x = float(2 * pixel.x() / viewport.width() - 1), y = float(1 - 2 * pixel.y() / viewport.height());
  const QVector3D near_point = inverse.map(QVector3D(x, y, -1)), far_point = inverse.map(QVector3D(x, y, 1));
  return {near_point, (far_point - near_point).normalized()};
}

bool OrbitCamera::project(const QVector3D& point, const QSizeF& viewport, QPointF& pixel) const {
  const QVector4D clip = viewProjection(viewport) * QVector4D(point, 1);
  if (clip.w() <= 0) return false;
  pixel = QPointF((clip.x() / clip.w() + 1) / 2 * viewport.width(), (1 - clip.y() / clip.w()) / 2 * viewport.height());
  return true;
}

QVector3D intersectPlane(const Ray& ray, const QVector3D& plane_point, const QVector3D& plane_normal) {
  const float denom = QVector3D::dotProduct(ray.direction, plane_normal);
  if (std::abs(denom) < 1e-6f) return ray.origin;
  const float t = QVector3D::dotProduct(plane_point - ray.origin, plane_normal) / denom;
  return ray.origin + ray.direction * t;
}

}  // namespace rci::ui
