// Shared by the benchmark suites: workloads generated once, registration once per path, and the
// counters the report (bench/report.py) reads.
//
// Names are task/method/path/n: task is the workload (aabb_query, aabb_pairs, cull_spheres, ...),
// method the algorithm (bvh, brute, grid, autovec, bullet_dbvt, ...), path the instruction set
// the run was forced to (a SIMD target, "reference", or "peer" for other engines).
// Counters: items_per_second (the workload's unit: box tests, boxes, objects), result (the count
// found), exact (1 when the result equals the reference figure of WORKLOADS.md), and where
// relevant checksum, bytes_per_second and error (differences from the double reference).
#pragma once

#include <benchmark/benchmark.h>

#include <functional>
#include <string>

#include "cloth.hpp"
#include "pyramid.hpp"
#include "simdphys/core.hpp"
#include "simdphys/geometry3d/streams.hpp"
#include "workloads.hpp"

namespace simdphys::bench {

const workloads::AabbWorkload& aabbWorkload(std::size_t n);
const workloads::AabbReference& aabbReference(std::size_t n);
const workloads::CullWorkload& cullWorkload();
// 100,000 spheres from seed 7: centres uniform in the W1 cube [-100, 100]^3, radii in [0.1, 1.5].
const SphereStream& sphereField();

using Body = std::function<void(benchmark::State&)>;

// Registers `body` under task/method/<path>/n, running with the path forced, for every path
// this machine has (the reference path too when `withReference`). `iterations` > 0 fixes the
// iteration count (a simulation's frames), else Google Benchmark chooses it.
void registerPerPath(const std::string& task, const std::string& method, std::size_t n,
                     const Body& body, bool withReference = true, std::int64_t iterations = 0);
// Registers `body` on the best SIMD path only: for comparing algorithms rather than paths.
void registerBestPath(const std::string& task, const std::string& method, std::size_t n,
                      const Body& body, std::int64_t iterations = 0);
// Registers `body` once, under task/method/label/n: label is "peer" for another engine's run, or
// "scalar" for code that has one path only (the octree's build). `iterations` as above.
void registerOnce(const std::string& task, const std::string& method, const std::string& label,
                  std::size_t n, const Body& body, std::int64_t iterations = 0);

// W3's measures of a cloth at the end (workloads/cloth.hpp) as the run's counters, with the
// deepest penetration over every frame and whether every position stayed finite.
void clothCounters(benchmark::State& state, const workloads::ClothWorkload& w,
                   std::span<const Vec3f> x, double deepest, bool finite);

// W5's figures of a pyramid run (workloads/pyramid.hpp) as the run's counters, the same for every
// solver: frames; ms_per_frame and body_steps_per_s (boxes x frames / s) over `seconds`, the time
// the frames' steps took; items processed (body steps); max_displacement and standing, from
// measurePyramid of the boxes' centres at the end (`end`) against `start`; deepest_penetration,
// the engine's own contact depth, the largest over every frame.
void pyramidCounters(benchmark::State& state, std::span<const Vec3f> start,
                     std::span<const Vec3f> end, int frames, double seconds, double deepest);

// Marks the run as failed if `found` differs from `expected`, else records both.
bool checkExact(benchmark::State& state, std::uint64_t found, std::uint64_t expected);

#ifdef SIMDPHYS_HAVE_BULLET
void registerBulletBenchmarks();  // peers/bullet_bench.cpp
#endif

}  // namespace simdphys::bench
