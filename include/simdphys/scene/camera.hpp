// Cameras (book chapter 13): a view and a projection over a viewport, perspective or
// orthographic, with the frustum and the picking ray they imply; an orbit camera that turns
// around a target; and the OBB-in-frustum test beside the sphere and AABB tests of scene.hpp.
// Conventions (view down -z, clip depth [0, 1], pixels from the top-left, y down) are those of
// docs/conventions.md; the matrices come from math.hpp.
#pragma once

#include "simdphys/math.hpp"
#include "simdphys/mesh_bvh.hpp"
#include "simdphys/scene/frustum.hpp"

namespace simdphys {

struct Camera {
  Mat4f view = Mat4f::Identity();        // world to view (lookAt)
  Mat4f projection = Mat4f::Identity();  // view to clip
  Vec4f viewport{0, 0, 1, 1};            // x, y, width, height in pixels

  // A pinhole camera at eye looking at target: vertical field of view fovY (radians) over a
  // width x height viewport at (0, 0), aspect width / height. Throws Error as lookAt and
  // perspective do.
  static Camera perspective(const Vec3f& eye, const Vec3f& target, const Vec3f& up, float fovY,
                            float width, float height, float zNear, float zFar);
  // A parallel projection showing `halfHeight` above and below the view axis (and
  // halfHeight * width / height to each side), depths zNear..zFar in front of the eye.
  static Camera orthographic(const Vec3f& eye, const Vec3f& target, const Vec3f& up,
                             float halfHeight, float width, float height, float zNear, float zFar);

  Mat4f viewProjection() const { return projection * view; }
  // The six planes of viewProjection(), extracted in double and rounded once: unit normals to
  // the last bit, as workload W6's frustum.
  Frustum frustum() const;
  // The world ray through the window point (px, py) (pixel centres at +0.5): screenToRay.
  Ray ray(float px, float py) const;
  // The rays through every pixel centre of the viewport, in scanline order from the top-left:
  // element j * width + i is ray(x + i + 0.5, y + j + 0.5), to the bit (the matrix is inverted
  // once instead of per pixel). Throws Error unless the viewport's size is a whole number.
  RayStream primaryRays() const;
  // The eye position (the inverse view's translation).
  Vec3f eye() const;
};

// A camera that orbits a target at a distance: yaw turns about world +y, pitch raises the eye
// above the target's horizontal plane (clamped short of the poles, where up would be parallel
// to the view direction), zoom scales the distance, pan moves the target in the view plane.
// yaw = pitch = 0 puts the eye on +z of the target, looking down -z.
class OrbitCamera {
 public:
  OrbitCamera(const Vec3f& target, float distance, float yaw = 0, float pitch = 0);

  void rotate(float dYaw, float dPitch);
  void zoom(float factor);            // distance *= factor (> 0)
  void pan(float dRight, float dUp);  // in world units along the view's right and up

  Vec3f eye() const;
  const Vec3f& target() const { return target_; }
  float distance() const { return distance_; }
  float yaw() const { return yaw_; }
  float pitch() const { return pitch_; }
  Mat4f view() const;  // lookAt(eye, target, +y)
  // A perspective camera with this view.
  Camera camera(float fovY, float width, float height, float zNear, float zFar) const;

  // Pitch stays within this of +-pi/2: lookAt's up (+y) must not be parallel to the view.
  static constexpr float kPitchLimit = 1.5f;

 private:
  Vec3f target_;
  float distance_, yaw_, pitch_;
};

// True unless one plane has the whole box outside it (the conservative test, as
// Frustum::intersectsBox): the box's reach along a normal n is sum |n . axis_i| h_i.
bool intersectsObb(const Frustum& frustum, const Obb& box);

}  // namespace simdphys
