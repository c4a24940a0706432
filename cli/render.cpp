// simdphys render SCENE: steps the scene and ray casts every k-th frame into a PNG through the
// library's Scene (one primary ray a pixel, a shadow ray towards the sun), then, where ffmpeg is
// installed, joins the frames into an animated GIF or an MP4.
#include <simdphys/scene/scene.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numbers>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

#include "commands.hpp"
#include "progress.hpp"
#include "session.hpp"

namespace simdphys::cli {
namespace {

// What each model of the picture is, for its colour.
enum class Kind { kObstacle, kGround, kBody, kCloth, kParticle };

struct Picture {
  Scene scene;
  std::vector<Kind> kinds;  // per model index (models are only added, so index = add order)
  void add(const Model& m, Kind k) {
    scene.add(m);
    kinds.push_back(k);
  }
};

// A cloth grid's quads as two triangles each.
Mesh clothMesh(const Cloth& c) {
  Mesh mesh{c.positions(), {}};
  const auto nx = std::uint32_t(c.gridColumns()), nz = std::uint32_t(c.gridRows());
  for (std::uint32_t j = 0; j + 1 < nz; ++j)
    for (std::uint32_t i = 0; i + 1 < nx; ++i) {
      const std::uint32_t a = j * nx + i, b = a + 1, d = a + nx, e = d + 1;
      mesh.triangles.push_back({a, b, e});
      mesh.triangles.push_back({a, e, d});
    }
  return mesh;
}

// A hull body's faces as triangle fans, where the body is.
Mesh hullMesh(const HullShape& shape, const Vec3f& position, const Quatf& orientation) {
  Mesh mesh;
  for (const Vec3f& v : shape.vertices()) mesh.vertices.push_back(position + orientation * v);
  for (int f = 0; f < shape.faceCount(); ++f) {
    const auto face = shape.face(f);
    for (std::size_t k = 1; k + 1 < face.size(); ++k)
      mesh.triangles.push_back({face[0], face[k], face[k + 1]});
  }
  return mesh;
}

Picture picture(const World& world, float particleRadius) {
  Picture p;
  for (const ObstacleShape& s : world.obstacles().shapes()) {
    if (const auto* plane = std::get_if<Plane>(&s)) {
      // A plane as a wide thin slab under its surface, its y axis along the normal.
      const Vec3f n = plane->normal, u = n.unitOrthogonal(), w = u.cross(n);
      Mat3f axes;
      axes << u, n, w;
      p.add({Obb{-plane->d * n - 0.05f * n, {60, 0.05f, 60}, axes}}, Kind::kGround);
    } else if (const auto* mesh = std::get_if<MeshObstacle>(&s)) {
      p.add({*mesh}, Kind::kObstacle);
    } else if (const auto* box = std::get_if<Obb>(&s)) {
      p.add({*box}, box->halfExtents.maxCoeff() > 20 ? Kind::kGround : Kind::kObstacle);
    } else if (const auto* aabb = std::get_if<Aabb>(&s)) {
      p.add({*aabb}, Kind::kObstacle);
    } else {
      p.add({std::get<Sphere>(s)}, Kind::kObstacle);
    }
  }
  const RigidBodies& bodies = world.bodies();
  for (std::uint32_t i = 0; i < bodies.size(); ++i) {
    const Handle h = bodies.handle(i);
    const auto shape = BodyShape(int(bodies.stream(fields::Body::shape)[i]));
    if (shape == BodyShape::kBox)
      p.add({bodies.box(h)}, Kind::kBody);
    else if (shape == BodyShape::kSphere)
      p.add({bodies.sphere(h)}, Kind::kBody);
    else
      p.add({std::make_shared<const MeshBvh>(
                hullMesh(*bodies.hull(h), bodies.position(h), bodies.orientation(h)))},
            Kind::kBody);
  }
  for (std::size_t c = 0; c < world.clothCount(); ++c) {
    const Cloth& cloth = world.cloth(world.clothHandle(c));
    if (cloth.isGrid()) {
      p.add({std::make_shared<const MeshBvh>(clothMesh(cloth))}, Kind::kCloth);
    } else {
      for (const Vec3f& x : cloth.positions()) p.add({Sphere{x, 2 * particleRadius}}, Kind::kCloth);
    }
  }
  for (std::size_t s = 0; s < world.particleSystemCount(); ++s) {
    const ParticleSystem& ps = world.particles(world.particleSystemHandle(s));
    for (std::size_t i = 0; i < ps.size(); ++i)
      p.add({Sphere{{ps.x()[i], ps.y()[i], ps.z()[i]}, particleRadius}}, Kind::kParticle);
  }
  p.scene.update();
  return p;
}

Vec3f colourOf(Kind k) {
  switch (k) {
    case Kind::kGround:
      return {0.82f, 0.80f, 0.74f};
    case Kind::kBody:
      return {0.90f, 0.55f, 0.25f};
    case Kind::kCloth:
      return {0.80f, 0.25f, 0.25f};
    case Kind::kParticle:
      return {0.25f, 0.45f, 0.85f};
    default:
      return {0.55f, 0.68f, 0.80f};
  }
}

// The camera the file gives, else one that frames the bodies, cloths and particles (or, with
// none, the obstacles) from above and to the side.
Camera cameraFor(const SceneFile& scene, int width, int height) {
  const float fov = scene.camera.fovDegrees * std::numbers::pi_v<float> / 180;
  if (scene.camera.given)
    return Camera::perspective(scene.camera.eye, scene.camera.target, Vec3f::UnitY(), fov,
                               float(width), float(height), 0.05f, 1000);
  Aabb box{Vec3f::Constant(kMaxCoordinate), Vec3f::Constant(-kMaxCoordinate)};
  auto grow = [&](const Vec3f& x) { box.min = box.min.cwiseMin(x), box.max = box.max.cwiseMax(x); };
  const World& w = scene.world;
  for (std::uint32_t i = 0; i < w.bodies().size(); ++i)
    grow(w.bodies().position(w.bodies().handle(i)));
  for (std::size_t c = 0; c < w.clothCount(); ++c) {
    grow(w.cloth(w.clothHandle(c)).bounds().min);
    grow(w.cloth(w.clothHandle(c)).bounds().max);
  }
  for (std::size_t s = 0; s < w.particleSystemCount(); ++s) {
    const ParticleSystem& ps = w.particles(w.particleSystemHandle(s));
    for (std::size_t i = 0; i < ps.size(); ++i) grow({ps.x()[i], ps.y()[i], ps.z()[i]});
  }
  if (box.min.x() > box.max.x()) box = {Vec3f::Constant(-5), Vec3f::Constant(5)};
  const Vec3f centre = 0.5f * (box.min + box.max);
  const float radius = std::max(0.5f * (box.max - box.min).norm(), 1.0f);
  const Vec3f eye =
      centre + Vec3f(0.6f, 0.45f, 1).normalized() * (1.3f * radius / std::tan(fov / 2));
  return Camera::perspective(eye, centre, Vec3f::UnitY(), fov, float(width), float(height), 0.05f,
                             1000);
}

std::uint8_t toByte(float v) { return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255)); }

void writePng(const std::string& file, const Picture& p, const Camera& camera, int width,
              int height) {
  const RayStream rays = camera.primaryRays();
  std::vector<ModelHit> hits(rays.size());
  p.scene.raycast(rays, hits);
  const Vec3f sun = Vec3f(-0.35f, 0.85f, 0.4f).normalized();
  std::vector<std::uint8_t> image(rays.size() * 3);
  for (std::size_t i = 0; i < hits.size(); ++i) {
    const Ray ray = rays[i];
    Vec3f colour(0.75f, 0.82f, 0.92f);  // the sky
    if (hits[i].hit()) {
      const ModelHit& h = hits[i];
      const bool lit = !p.scene.raycast({h.point + 1e-3f * h.normal, sun}).hit();
      const float sunLight = lit ? std::max(0.0f, h.normal.dot(sun)) : 0.0f;
      const float eyeLight = std::max(0.0f, -h.normal.dot(ray.direction.normalized()));
      // Bodies vary a little in tone (by a hash of their index), so neighbours stay apart.
      const float tone = p.kinds[h.model] == Kind::kBody
                             ? 0.8f + 0.2f * float((h.model * 2654435761u) >> 28) / 15
                             : 1.0f;
      colour = tone * colourOf(p.kinds[h.model]) * (0.15f + 0.55f * sunLight + 0.3f * eyeLight);
    }
    for (int c = 0; c < 3; ++c) image[3 * i + std::size_t(c)] = toByte(colour[c]);
  }
  if (!stbi_write_png(file.c_str(), width, height, 3, image.data(), width * 3))
    throw Error(file + ": cannot be written");
}

bool haveFfmpeg() { return std::system("ffmpeg -version > /dev/null 2>&1") == 0; }

}  // namespace

void render(const RenderOptions& o) {
  Session s(o.scene, o.overrides);
  const int every = o.every > 0 ? o.every : std::max(1, s.frames() / 60);
  std::filesystem::create_directories(o.out);
  const Camera camera = cameraFor(s.scene(), o.width, o.height);
  Progress bar("simdphys render", s.frames(), stderrIsTerminal());
  int pictures = 0;
  auto shoot = [&] {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", pictures++);
    writePng((std::filesystem::path(o.out) / name).string(),
             picture(s.scene().world, o.particleRadius), camera, o.width, o.height);
  };
  shoot();  // the start
  for (int f = 1; f <= s.frames(); ++f) {
    s.step();
    if (f % every == 0) shoot();
    bar.update(f);
  }
  bar.finish();
  std::printf("wrote %d pictures (%dx%d, every %d frames of %d) to %s/frame_*.png\n", pictures,
              o.width, o.height, every, s.frames(), o.out.c_str());
  if (o.video.empty()) return;
  if (!haveFfmpeg()) {
    std::printf(
        "ffmpeg is not installed (apt-get install ffmpeg): no %s; the PNG frames are kept\n",
        o.video.c_str());
    return;
  }
  // 60 Hz frames shown every `every`: the animation plays in real time. A GIF gets its own
  // palette (two passes in one filter graph).
  const double fps = 60.0 / every;
  const bool gif = std::filesystem::path(o.video).extension() == ".gif";
  const std::string filter = gif ? "-vf \"split[a][b];[a]palettegen[p];[b][p]paletteuse\""
                                 : "-pix_fmt yuv420p -vf \"pad=ceil(iw/2)*2:ceil(ih/2)*2\"";
  const std::string cmd = "ffmpeg -y -loglevel error -framerate " + std::to_string(fps) + " -i \"" +
                          o.out + "/frame_%05d.png\" " + filter + " \"" + o.video + "\"";
  if (std::system(cmd.c_str()) != 0) throw Error("ffmpeg failed: " + cmd);
  std::printf("wrote %s\n", o.video.c_str());
}

}  // namespace simdphys::cli
