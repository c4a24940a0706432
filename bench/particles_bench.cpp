// W4: particles bouncing off a ground box and a ramp, 300 frames of the world per run (one
// iteration a frame), with the error against the same world stepped by the double reference
// beside the speed; the cost of stepping an empty world and a world of one particle; and the four
// integrators' speed against their error on two closed-form cases.
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <variant>

#include "bench_common.hpp"
#include "particles.hpp"
#include "testing/particles.hpp"
#include "testing/plain_loops.hpp"

namespace simdphys::bench {
namespace {

using Clock = std::chrono::steady_clock;

// The bytes a step must move per particle: it reads the position, the velocity and the inverse
// mass (7 floats) and writes the position and the velocity (6 floats); the force (3 floats) is
// read only in a system that has forces, which W4 has not.
constexpr std::size_t kReadBytes = 7 * sizeof(float), kWrittenBytes = 6 * sizeof(float);
constexpr std::size_t kForceBytes = 3 * sizeof(float);
constexpr double kApart = 1e-3;  // m: the error above which a particle counts as apart

// W4, or one of its variants: 256 more obstacles (workloads::addParticleField) or a terrain mesh
// (workloads::addParticleTerrain).
struct Variant {
  std::size_t n;
  bool field;
  bool terrain = false;
  auto operator<=>(const Variant&) const = default;
};

const workloads::ParticleWorkload& initialWorld(Variant v) {
  static std::map<Variant, std::unique_ptr<workloads::ParticleWorkload>> cache;
  auto& w = cache[v];
  if (!w) {
    w = std::make_unique<workloads::ParticleWorkload>(workloads::makeParticleWorkload(v.n));
    if (v.field) workloads::addParticleField(w->world);
    if (v.terrain) workloads::addParticleTerrain(w->world);
  }
  return *w;
}

// The final positions of W4 stepped 300 frames by the double reference: slow (a minute at
// 1,000,000), so computed once per N and shared by every path's run.
const std::vector<Vec3d>& doubleFinal(Variant v) {
  static std::map<Variant, std::vector<Vec3d>> cache;
  std::vector<Vec3d>& x = cache[v];
  if (x.empty()) {
    workloads::ParticleWorkload w = initialWorld(v);  // stepDouble updates the world's obstacles
    const ParticleSystem& s = w.world.particles(w.particles);
    test::ParticlesD p = test::toDouble(s);
    for (int f = 0; f < workloads::kParticleFrames; ++f) test::stepDouble(p, s, w.world);
    x = std::move(p.x);
  }
  return x;
}

// How deep p lies inside the deepest of W4's boxes (0 outside all of them).
double depthInside(const Obstacles& obstacles, const Vec3f& p) {
  double deepest = 0;
  for (const ObstacleShape& shape : obstacles.shapes())
    if (const Obb* box = std::get_if<Obb>(&shape)) {
      const Vec3f q = box->axes.transpose() * (p - box->center);
      deepest = std::max(deepest, double((box->halfExtents - q.cwiseAbs()).minCoeff()));
    }
  return deepest;
}

// W4's final state against the obstacles and the double reference. A particle inside an
// obstacle is what W4 forbids; the run keeps its time and the report flags it.
void finalCounters(benchmark::State& state, Variant variant, const World& world,
                   const ParticleSystem& s) {
  const std::vector<Vec3d>& exact = doubleFinal(variant);
  std::size_t inside = 0, apart = 0;
  double height = 0, worst = 0, squares = 0, depth = 0;
  for (std::uint32_t i = 0; i < s.size(); ++i) {
    const Vec3f x(s.x()[i], s.y()[i], s.z()[i]);
    if (world.obstacles().inside(x))
      ++inside, depth = std::max(depth, depthInside(world.obstacles(), x));
    height += x.y();
    const double e = (x.cast<double>() - exact[i]).norm();
    worst = std::max(worst, e), squares += e * e, apart += e > kApart;
  }
  const double n = double(s.size());
  state.counters["inside"] = double(inside);
  state.counters["mean_height"] = height / n;
  state.counters["error_max"] = worst;
  state.counters["error_rms"] = std::sqrt(squares / n);
  state.counters["apart_fraction"] = double(apart) / n;
  state.counters["inside_depth"] = depth;
}

// One run: W4 from its initial state, one frame an iteration (registered with 300 of them).
void particlesRun(benchmark::State& state, Variant variant, bool plainLoops) {
  doubleFinal(variant);  // before the timing, the first time
  workloads::ParticleWorkload w = initialWorld(variant);
  const std::size_t n = variant.n;
  const ParticleSystem& s = w.world.particles(w.particles);
  std::uint64_t contacts = 0, pushedOut = 0, limited = 0;
  std::optional<test::ScopedPlainLoops> plain;
  if (plainLoops) plain.emplace();
  for (auto _ : state) {
    w.world.step();
    const StepProfile& p = w.world.profile();
    contacts += p.contacts, pushedOut += p.pushedOut, limited += p.bounceLimited;
  }
  const auto steps = std::int64_t(state.iterations()) * std::int64_t(n);
  state.SetItemsProcessed(steps);
  const std::size_t bytes = kReadBytes + kWrittenBytes + (s.hasForces() ? kForceBytes : 0);
  state.SetBytesProcessed(steps * std::int64_t(bytes));
  state.counters["frames"] = double(state.iterations());
  state.counters["contacts"] = double(contacts);
  state.counters["pushed_out"] = double(pushedOut);
  state.counters["bounce_limited"] = double(limited);
  if (state.iterations() != workloads::kParticleFrames)
    state.SkipWithError("W4 runs 300 frames: its checks need the final state");
  else
    finalCounters(state, variant, w.world, s);
}

// Times world.step() called as the benchmark's loop, and reports nanoseconds a step.
void stepCost(benchmark::State& state, World& world) {
  const auto start = Clock::now();
  for (auto _ : state) world.step();
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  state.counters["ns_per_step"] = seconds * 1e9 / double(state.iterations());
  state.SetItemsProcessed(std::int64_t(state.iterations()));
}

// ---- the integrators on closed forms -----------------------------------------------------------

constexpr Integrator kIntegrators[] = {Integrator::kExplicitEuler, Integrator::kSemiImplicitEuler,
                                       Integrator::kVelocityVerlet, Integrator::kPositionVerlet};
constexpr int kStepsPerSecond[] = {30, 60, 120, 240, 480};

// "velocity Verlet" -> "velocity_verlet"
std::string methodName(Integrator integrator, int stepsPerSecond) {
  std::string name = toString(integrator);
  for (char& c : name) c = c == ' ' || c == '-' ? '_' : char(std::tolower(c));
  return name + "_dt" + std::to_string(stepsPerSecond);
}

// Position Verlet keeps the previous position as the mean velocity over the last step, so it
// starts from v(-dt / 2) (particles.hpp); the other forms start from v(0).
Vec3d startVelocity(Integrator integrator, const Vec3d& v0, const Vec3d& a0, double dt) {
  return integrator == Integrator::kPositionVerlet ? Vec3d(v0 - a0 * (dt / 2)) : v0;
}

// A vector of three draws in [a, b), x first; float draws, so exact in double and in float.
Vec3d draw(workloads::Random& r, float a, float b) {
  const double x = r.uniform(a, b), y = r.uniform(a, b);
  return {x, y, r.uniform(a, b)};
}

void integratorCounters(benchmark::State& state, Integrator integrator, double dt, double seconds,
                        std::size_t particleSteps, double error) {
  state.counters["integrator"] = double(integrator);
  state.counters["dt"] = dt;
  state.counters["ns_per_step"] = seconds * 1e9 / double(particleSteps);
  state.counters["error"] = error;
}

// A projectile under gravity, through a World on the path (no obstacles, no damping): n particles
// thrown from random points at random velocities (seed 14), 1 s of steps, error the largest
// distance from x0 + v0 t + g t^2 / 2 at the end.
constexpr std::size_t kProjectiles = 10'000;
void projectile(benchmark::State& state, Integrator integrator, int stepsPerSecond) {
  const WorldSettings ws{.timeStep = 1.0f / float(stepsPerSecond)};
  ParticleSettings settings;
  settings.integrator = integrator;
  const double dt = ws.timeStep;
  const Vec3d g = settings.gravity.cast<double>();
  workloads::Random r(14);
  std::vector<Vec3d> x0, v0;
  for (std::size_t i = 0; i < kProjectiles; ++i) {
    x0.push_back(draw(r, -10, 10));
    v0.push_back(draw(r, -5, 5));
  }
  double seconds = 0, error = 0;
  std::size_t particleSteps = 0;
  for (auto _ : state) {
    state.PauseTiming();
    World world(ws);
    ParticleSystem& s = world.particles(world.addParticles(settings));
    for (std::size_t i = 0; i < kProjectiles; ++i)
      s.add(x0[i].cast<float>(), startVelocity(integrator, v0[i], g, dt).cast<float>());
    state.ResumeTiming();
    const auto start = Clock::now();
    for (int k = 0; k < stepsPerSecond; ++k) world.step();
    seconds += std::chrono::duration<double>(Clock::now() - start).count();
    particleSteps += kProjectiles * std::size_t(stepsPerSecond);
    const double t = dt * stepsPerSecond;
    error = 0;
    for (std::uint32_t i = 0; i < s.size(); ++i) {
      const Vec3d exact = x0[i] + v0[i] * t + g * (t * t / 2);
      error = std::max(error, (Vec3d(s.x()[i], s.y()[i], s.z()[i]) - exact).norm());
    }
  }
  state.SetItemsProcessed(std::int64_t(particleSteps));
  integratorCounters(state, integrator, dt, seconds, particleSteps, error);
}

// A harmonic oscillator, x'' = -w^2 x with w = 2 pi (a period of 1 s), in float through the
// scalar reference's integrate() (the world's forces are held for a step, an oscillator's are
// not): n particles from random positions and velocities (seed 15), 10 periods, error the largest
// distance from x0 cos wt + v0 / w sin wt at the end.
constexpr std::size_t kOscillators = 1'000;
void oscillator(benchmark::State& state, Integrator integrator, int stepsPerSecond) {
  constexpr double kOmega = 2 * std::numbers::pi, kPeriods = 10;
  const float dt = 1.0f / float(stepsPerSecond);
  const int steps = int(kPeriods) * stepsPerSecond;
  const float w2 = float(kOmega * kOmega);
  const auto spring = [w2](const Vec3f& x) { return Vec3f(-w2 * x); };
  workloads::Random r(15);
  std::vector<Vec3d> x0, v0;
  for (std::size_t i = 0; i < kOscillators; ++i) {
    x0.push_back(draw(r, -1, 1));
    v0.push_back(draw(r, -6, 6));
  }
  std::vector<Vec3f> x(kOscillators), v(kOscillators);
  double seconds = 0, error = 0;
  std::size_t particleSteps = 0;
  for (auto _ : state) {
    for (std::size_t i = 0; i < kOscillators; ++i) {
      x[i] = x0[i].cast<float>();
      v[i] = startVelocity(integrator, v0[i], -kOmega * kOmega * x0[i], dt).cast<float>();
    }
    const auto start = Clock::now();
    for (std::size_t i = 0; i < kOscillators; ++i)
      for (int k = 0; k < steps; ++k)
        reference::integrate<float>(integrator, x[i], v[i], dt, spring);
    seconds += std::chrono::duration<double>(Clock::now() - start).count();
    benchmark::DoNotOptimize(x.data());
    particleSteps += kOscillators * std::size_t(steps);
    const double t = double(dt) * steps;
    error = 0;
    for (std::size_t i = 0; i < kOscillators; ++i) {
      const Vec3d exact = x0[i] * std::cos(kOmega * t) + v0[i] * (std::sin(kOmega * t) / kOmega);
      error = std::max(error, (x[i].cast<double>() - exact).norm());
    }
  }
  state.SetItemsProcessed(std::int64_t(particleSteps));
  integratorCounters(state, integrator, dt, seconds, particleSteps, error);
}

}  // namespace

void registerParticleBenchmarks() {
  for (std::size_t n : {100'000, 1'000'000}) {
    registerPerPath(
        "particles", "w4", n,
        [n](benchmark::State& state) {
          particlesRun(state, {n, false}, false);
        },
        true, workloads::kParticleFrames);
    // The plain loop over the streams (simd/particles.cpp's stepParticlesAutovec), compiled for
    // each SIMD path: the step runs it while plain loops are on. At 1,000,000 on the best path
    // only: its ratio is read at 100,000, and the larger runs are the slow ones.
    const Body plain = [n](benchmark::State& state) { particlesRun(state, {n, false}, true); };
    if (n == 100'000)
      registerPerPath("particles", "autovec", n, plain, false, workloads::kParticleFrames);
    else
      registerBestPath("particles", "autovec", n, plain, workloads::kParticleFrames);
  }
  // Many obstacles, found through the tree: W4 with 256 pillars more, at 100,000.
  registerPerPath(
      "particles", "w4_field", 100'000,
      [](benchmark::State& state) {
        particlesRun(state, {100'000, true}, false);
      },
      true, workloads::kParticleFrames);
  // A triangle mesh, its entries tested lane by lane: W4 with a terrain of 8,192 triangles.
  registerPerPath(
      "particles", "w4_terrain", 100'000,
      [](benchmark::State& state) {
        particlesRun(state, {100'000, false, true}, false);
      },
      true, workloads::kParticleFrames);
  registerPerPath("world_step", "empty", 0, [](benchmark::State& state) {
    World world;
    stepCost(state, world);
  });
  // W4's first particle alone with W4's obstacles: within a second of steps it rests on the
  // ramp or the ground, so the step is mostly that of a resting contact.
  registerPerPath("world_step", "one_particle", 1, [](benchmark::State& state) {
    workloads::ParticleWorkload w = workloads::makeParticleWorkload(1);
    stepCost(state, w.world);
  });
  for (Integrator integrator : kIntegrators)
    for (int stepsPerSecond : kStepsPerSecond) {
      const std::string method = methodName(integrator, stepsPerSecond);
      registerBestPath("integrate_projectile", method, kProjectiles, [=](benchmark::State& state) {
        projectile(state, integrator, stepsPerSecond);
      });
      registerOnce("integrate_oscillator", method, "scalar", kOscillators,
                   [=](benchmark::State& state) { oscillator(state, integrator, stepsPerSecond); });
    }
}

}  // namespace simdphys::bench
