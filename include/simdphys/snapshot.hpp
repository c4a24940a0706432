// Snapshots: a World's whole state (settings, obstacles, particle systems, cloths, rigid bodies
// with their contact caches and sleep state, the handle tables) in a versioned binary form.
// Stepping a restored world gives bit for bit the states stepping the original gives, on the same
// execution path (docs/scenes.md, Snapshots).
//
// The format: the magic "SIMDPHYS-SNAPSHOT\n", the format version (u32), the payload's length
// (u64) and its FNV-1a 64 checksum, then the payload; little-endian, as written by this machine
// type. A snapshot that is truncated, corrupt, of another version or inconsistent is refused with
// an Error that says which, and nothing is restored.
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <vector>

#include "simdphys/world.hpp"

namespace simdphys {

inline constexpr std::uint32_t kSnapshotVersion = 2;

std::vector<std::byte> snapshot(const World& world);
// FNV-1a 64 of snapshot(world): equal hashes, equal states (the batch runner records it).
std::uint64_t stateHash(const World& world);
World restore(std::span<const std::byte> bytes);

// The same through a file; errors name the file.
void saveSnapshot(const World& world, const std::filesystem::path& file);
World loadSnapshot(const std::filesystem::path& file);

}  // namespace simdphys
