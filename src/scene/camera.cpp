// Cameras: perspective, orthographic, orbit; the frustum and picking ray they imply.
#include "simdphys/scene/camera.hpp"
#include "src/reference/math-inl.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace simdphys {
namespace {

void requireViewportSize(float width, float height, const char* where) {
  if (!(width > 0 && height > 0 && std::isfinite(width) && std::isfinite(height)))
    throw Error(std::string(where) + ": the viewport must have a positive, finite size");
}

}  // namespace

Camera Camera::perspective(const Vec3f& eye, const Vec3f& target, const Vec3f& up, float fovY,
                           float width, float height, float zNear, float zFar) {
  requireViewportSize(width, height, "Camera::perspective");
  return {lookAt(eye, target, up), simdphys::perspective(fovY, width / height, zNear, zFar),
          Vec4f(0, 0, width, height)};
}

Camera Camera::orthographic(const Vec3f& eye, const Vec3f& target, const Vec3f& up,
                            float halfHeight, float width, float height, float zNear, float zFar) {
  requireViewportSize(width, height, "Camera::orthographic");
  const float halfWidth = halfHeight * width / height;
  return {lookAt(eye, target, up),
          simdphys::orthographic(-halfWidth, halfWidth, -halfHeight, halfHeight, zNear, zFar),
          Vec4f(0, 0, width, height)};
}

Frustum Camera::frustum() const {
  return Frustumd::fromMatrix(projection.cast<double>() * view.cast<double>()).cast<float>();
}

Ray Camera::ray(float px, float py) const {
  const ScreenRay<float> r = screenToRay(px, py, viewport, view, projection);
  return {r.origin, r.direction};
}

RayStream Camera::primaryRays() const {
  const float w = viewport[2], h = viewport[3];
  if (!(w >= 1 && h >= 1 && w == std::floor(w) && h == std::floor(h)))
    throw Error("Camera::primaryRays: the viewport's width and height must be whole numbers");
  // As screenToRay: the same float inverse, the same unprojection and normalisation.
  const Mat4f inverse = (projection * view).inverse();
  RayStream rays;
  rays.reserve(std::size_t(w) * std::size_t(h));
  for (float j = 0; j < h; ++j)
    for (float i = 0; i < w; ++i) {
      const float px = viewport[0] + i + 0.5f, py = viewport[1] + j + 0.5f;
      const Vec3f nearPoint = unproject(Vec3f(px, py, 0), viewport, inverse);
      const Vec3f farPoint = unproject(Vec3f(px, py, 1), viewport, inverse);
      rays.push({nearPoint,
                 detail::normalized(farPoint - nearPoint, "Camera::primaryRays", "far - near")});
    }
  return rays;
}

Vec3f Camera::eye() const {
  // view = [R | -R e]: e = -R^T t, R orthonormal.
  const Mat3f r = view.topLeftCorner<3, 3>();
  return -(r.transpose() * view.topRightCorner<3, 1>());
}

OrbitCamera::OrbitCamera(const Vec3f& target, float distance, float yaw, float pitch)
    : target_(target), distance_(distance), yaw_(yaw), pitch_(0) {
  if (!target.allFinite() || !(distance > 0 && std::isfinite(distance)) || !std::isfinite(yaw))
    throw Error("OrbitCamera: target and yaw must be finite and distance positive");
  rotate(0, pitch);
}

void OrbitCamera::rotate(float dYaw, float dPitch) {
  if (!std::isfinite(dYaw) || !std::isfinite(dPitch))
    throw Error("OrbitCamera::rotate: the angles must be finite");
  yaw_ = std::remainder(yaw_ + dYaw, 2 * std::numbers::pi_v<float>);
  pitch_ = std::clamp(pitch_ + dPitch, -kPitchLimit, kPitchLimit);
}

void OrbitCamera::zoom(float factor) {
  if (!(factor > 0 && std::isfinite(factor)))
    throw Error("OrbitCamera::zoom: the factor must be positive and finite");
  distance_ *= factor;
}

void OrbitCamera::pan(float dRight, float dUp) {
  if (!std::isfinite(dRight) || !std::isfinite(dUp))
    throw Error("OrbitCamera::pan: the offsets must be finite");
  const Mat4f v = view();
  // The rows of the view's rotation are right, up and -forward in world coordinates.
  target_ += dRight * v.block<1, 3>(0, 0).transpose() + dUp * v.block<1, 3>(1, 0).transpose();
}

Vec3f OrbitCamera::eye() const {
  // Yaw 0, pitch 0: on +z. Pitch lifts towards +y, yaw turns about +y (right-hand rule).
  const float cp = std::cos(pitch_), sp = std::sin(pitch_);
  const float cy = std::cos(yaw_), sy = std::sin(yaw_);
  return target_ + distance_ * Vec3f(cp * sy, sp, cp * cy);
}

Mat4f OrbitCamera::view() const { return lookAt(eye(), target_, Vec3f::UnitY()); }

Camera OrbitCamera::camera(float fovY, float width, float height, float zNear, float zFar) const {
  return Camera::perspective(eye(), target_, Vec3f::UnitY(), fovY, width, height, zNear, zFar);
}

bool intersectsObb(const Frustum& f, const Obb& box) {
  for (const Plane& p : f.planes) {
    const float dist = p.normal.dot(box.center) + p.d;
    float reach = 0;
    for (int i = 0; i < 3; ++i)
      reach += std::abs(p.normal.dot(box.axes.col(i))) * box.halfExtents[i];
    if (!(dist + reach >= 0)) return false;
  }
  return true;
}

}  // namespace simdphys
