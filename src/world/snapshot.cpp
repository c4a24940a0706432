// Snapshots (snapshot.hpp): one visitor over every member of a World, run by a Writer to save and
// by a Reader to restore, so the two cannot disagree on the order.
#include "simdphys/snapshot.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <string_view>
#include <type_traits>

#include "simdphys/mesh_bvh.hpp"

namespace simdphys {
namespace {

constexpr std::string_view kMagic = "SIMDPHYS-SNAPSHOT\n";
constexpr std::size_t kHeader = kMagic.size() + 4 + 8 + 8;

// Values saved as their bytes: plain data without pointers (Eigen's fixed-size vectors are, though
// not trivially copyable by the standard's rule, as they declare their copies).
template <class T>
constexpr bool kBytes = std::is_trivially_destructible_v<T> && !std::is_pointer_v<T>;

std::uint64_t fnv1a(std::span<const std::byte> bytes) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (const std::byte b : bytes) h = (h ^ std::uint64_t(b)) * 0x100000001b3ull;
  return h;
}

struct Writer {
  std::vector<std::byte> out;
  template <class T>
  void pod(const T& v) {
    static_assert(kBytes<T>);
    const auto* p = reinterpret_cast<const std::byte*>(&v);
    out.insert(out.end(), p, p + sizeof(T));
  }
  template <class V>
  void list(const V& v) {
    pod(std::uint64_t(v.size()));
    const auto* p = reinterpret_cast<const std::byte*>(v.data());
    out.insert(out.end(), p, p + v.size() * sizeof(typename V::value_type));
  }
  std::size_t count(std::size_t n) {
    pod(std::uint64_t(n));
    return n;
  }
  static constexpr bool kReading = false;
};

struct Reader {
  std::span<const std::byte> in;
  std::size_t at = 0;
  [[noreturn]] static void fail(const std::string& what) {
    throw Error("restore: the snapshot is inconsistent: " + what);
  }
  void need(std::size_t bytes) {
    if (bytes > in.size() - at) fail("it ends inside its data");
  }
  template <class T>
  void pod(T& v) {
    static_assert(kBytes<T>);
    need(sizeof(T));
    std::memcpy(static_cast<void*>(&v), in.data() + at, sizeof(T));
    at += sizeof(T);
  }
  template <class V>
  void list(V& v) {
    std::uint64_t n = 0;
    pod(n);
    using T = typename V::value_type;
    if (n > (in.size() - at) / sizeof(T)) fail("a list is longer than the data left");
    v.resize(std::size_t(n));
    if (n > 0)  // an empty vector's data() may be null, which memcpy may not take
      std::memcpy(static_cast<void*>(v.data()), in.data() + at, std::size_t(n) * sizeof(T));
    at += std::size_t(n) * sizeof(T);
  }
  std::size_t count(std::size_t) {
    std::uint64_t n = 0;
    pod(n);
    if (n > in.size() - at) fail("a count is larger than the data left");
    return std::size_t(n);
  }
  static constexpr bool kReading = true;
};

}  // namespace

namespace detail {

// Every member that a step reads or writes, in one order for both directions. A Reader rebuilds
// what is derived (an obstacle mesh's tree, the obstacles' tree) instead of reading it.
struct Snapshot {
  // Structs with padding are saved member by member: their padding bytes are whatever a copy left
  // there, and two worlds in the same state must give the same bytes. The sizes make a new member
  // a compile error here until it is saved.
  template <class Ar>
  static void io(Ar& a, ParticleSettings& s) {
    static_assert(sizeof(ParticleSettings) == 44, "a member was added: save it here");
    a.pod(s.integrator), a.pod(s.gravity), a.pod(s.damping), a.pod(s.drag), a.pod(s.restitution);
    a.pod(s.friction), a.pod(s.restitutionThreshold), a.pod(s.skin), a.pod(s.maxBounces);
  }
  template <class Ar>
  static void io(Ar& a, ClothSettings& s) {
    static_assert(sizeof(ClothSettings) == 40, "a member was added: save it here");
    a.pod(s.model), a.pod(s.gravity), a.pod(s.substeps), a.pod(s.damping), a.pod(s.margin);
    a.pod(s.friction), a.pod(s.tethers), a.pod(s.penalty);
  }
  template <class Ar>
  static void io(Ar& a, RigidSettings& s) {
    static_assert(sizeof(RigidSettings) == 76, "a member was added: save it here");
    a.pod(s.model), a.pod(s.gravity), a.pod(s.substeps), a.pod(s.iterations);
    a.pod(s.contactHertz), a.pod(s.contactDampingRatio), a.pod(s.maxPushSpeed);
    a.pod(s.baumgarte), a.pod(s.projection), a.pod(s.linearSlop), a.pod(s.speculativeDistance);
    a.pod(s.restitutionThreshold), a.pod(s.linearDamping), a.pod(s.angularDamping);
    a.pod(s.warmStarting), a.pod(s.reuseManifolds), a.pod(s.sleeping), a.pod(s.sleepSpeed);
    a.pod(s.timeToSleep);
  }
  template <class Ar>
  static void io(Ar& a, std::vector<PairGeometryT<float>>& pairs) {
    static_assert(sizeof(PairGeometryT<float>) == 168, "a member was added: save it here");
    pairs.resize(a.count(pairs.size()));
    for (PairGeometryT<float>& p : pairs) {
      a.pod(p.key), a.pod(p.position), a.pod(p.rotation), a.pod(p.normal), a.pod(p.count);
      a.pod(p.id), a.pod(p.onA), a.pod(p.onB);
    }
  }

  template <class Ar>
  static void io(Ar& a, HandleTable& t) {
    a.list(t.slots_);
    a.list(t.slotOf_);
    a.list(t.free_);
    for (std::size_t i = 0; i < t.slotOf_.size(); ++i)
      if (t.slotOf_[i] >= t.slots_.size() || t.slots_[t.slotOf_[i]].index != i)
        Reader::fail("a handle table's slot " + std::to_string(i) + " is not its element's");
  }

  template <class Ar, class Fields>
  static void io(Ar& a, StreamSet<Fields>& s) {
    std::size_t n = a.count(s.size());
    if constexpr (Ar::kReading) s.resize(n);
    for (std::size_t f = 0; f < StreamSet<Fields>::kFields; ++f) {
      std::span<float> live = s.writable(f);
      for (float& v : live) a.pod(v);
    }
  }

  template <class Ar>
  static void io(Ar& a, ObstacleShape& shape) {
    std::uint32_t kind = std::uint32_t(shape.index());
    a.pod(kind);
    if constexpr (Ar::kReading) {
      switch (kind) {
        case 0:
          shape = Plane{Vec3f::Zero(), 0};
          break;
        case 1:
          shape = Sphere{Vec3f::Zero(), 0};
          break;
        case 2:
          shape = Aabb{Vec3f::Zero(), Vec3f::Zero()};
          break;
        case 3:
          shape = Obb{Vec3f::Zero(), Vec3f::Zero()};
          break;
        case 4: {
          Mesh mesh;
          a.list(mesh.vertices);
          a.list(mesh.triangles);
          shape = std::make_shared<const MeshBvh>(std::move(mesh));  // validates it
          return;
        }
        default:
          Reader::fail("an obstacle of unknown kind " + std::to_string(kind));
      }
    } else if (const auto* mesh = std::get_if<MeshObstacle>(&shape)) {
      a.list((*mesh)->mesh().vertices);
      a.list((*mesh)->mesh().triangles);
      return;
    }
    std::visit(
        [&](auto& s) {
          if constexpr (!std::is_same_v<std::decay_t<decltype(s)>, MeshObstacle>) a.pod(s);
        },
        shape);
  }

  template <class Ar>
  static void io(Ar& a, Obstacles& o) {
    o.shapes_.resize(a.count(o.shapes_.size()));
    for (ObstacleShape& s : o.shapes_) io(a, s);
    io(a, o.handles_);
    a.pod(o.version_);
    if constexpr (Ar::kReading) {
      if (o.handles_.size() != o.shapes_.size()) Reader::fail("obstacles and their handles differ");
      o.dirty_ = true;
      o.update();
    }
  }

  template <class Ar>
  static void io(Ar& a, ParticleSystem& p) {
    io(a, static_cast<StreamSet<fields::Particle>&>(p));
    io(a, p.settings_);
    io(a, p.handles_);
    a.pod(p.hasForces_);
    a.pod(p.outsideOf_);
    if constexpr (Ar::kReading) {
      validate(p.settings_, "restore: a particle system");
      if (p.handles_.size() != p.size()) Reader::fail("particles and their handles differ");
    }
  }

  template <class Ar>
  static void io(Ar& a, Cloth& c) {
    io(a, c.settings_);
    a.pod(c.count_), a.pod(c.stride_), a.pod(c.nx_), a.pod(c.nz_), a.pod(c.slots_);
    for (auto& s : c.s_) a.list(s);
    a.list(c.springs_), a.list(c.batchOf_), a.list(c.batchBegin_);
    a.list(c.sa_), a.list(c.sb_), a.list(c.sRest_), a.list(c.sCompliance_), a.list(c.sStiffness_),
        a.list(c.sDamping_);
    for (auto& r : c.gridRest_) a.list(r);
    a.pod(c.kinds_);
    a.list(c.anchor_), a.list(c.tether_), a.list(c.quads_);
    a.pod(c.rate2_), a.pod(c.dampRate_), a.pod(c.maxInvMass_), a.pod(c.damped_), a.pod(c.bounds_);
    if constexpr (Ar::kReading) {
      validate(c.settings_, "restore: a cloth");
      for (const auto& s : c.s_)
        if (s.size() != c.s_[0].size() || s.size() < c.slots_)
          Reader::fail("a cloth's streams differ");
      for (std::size_t i = 0; i < c.sa_.size(); ++i)
        if (c.sa_[i] >= c.slots_ || i >= c.sb_.size() || c.sb_[i] >= c.slots_)
          Reader::fail("a cloth's spring joins no particle");
      for (const std::uint32_t anchor : c.anchor_)
        if (anchor >= c.anchor_.size()) Reader::fail("a cloth's tether has no anchor");
    }
  }

  template <class Ar>
  static void io(Ar& a, HullShape& h) {
    static_assert(sizeof(HullShape) == 176, "a member was added: save it here");
    a.list(h.vertices_), a.list(h.faceIndices_), a.list(h.faceStart_), a.list(h.normals_);
    a.list(h.offsets_);
    a.pod(h.half_), a.pod(h.inertia_), a.pod(h.centre_), a.pod(h.volume_), a.pod(h.rotation_);
    if constexpr (Ar::kReading) {
      const std::size_t faces = h.offsets_.size();
      if (h.faceStart_.size() != faces + 1 || h.normals_.size() != faces ||
          h.faceStart_.front() != 0 || h.faceStart_.back() != h.faceIndices_.size() ||
          !std::is_sorted(h.faceStart_.begin(), h.faceStart_.end()))
        Reader::fail("a hull's faces");
      for (const std::uint8_t v : h.faceIndices_)
        if (v >= h.vertices_.size()) Reader::fail("a hull's face names no vertex");
    }
  }

  template <class Ar>
  static void io(Ar& a, RigidBodies& b) {
    io(a, static_cast<StreamSet<fields::Body>&>(b));
    io(a, b.settings_);
    io(a, b.handles_);
    b.hulls_.resize(a.count(b.hulls_.size()));
    for (auto& h : b.hulls_) {
      if constexpr (Ar::kReading) {
        auto shape = std::shared_ptr<HullShape>(new HullShape());
        io(a, *shape);
        h = std::move(shape);
      } else {
        io(a, const_cast<HullShape&>(*h));
      }
    }
    a.list(b.cache_.manifolds);
    io(a, b.cache_.pairs);
    // The last step's counts (not its wall time, which is no state).
    a.pod(b.deepest_), a.pod(b.manifolds_), a.pod(b.points_), a.pod(b.colours_), a.pod(b.overflow_);
    if constexpr (Ar::kReading) {
      validate(b.settings_, "restore: the rigid bodies");
      if (b.handles_.size() != b.size()) Reader::fail("bodies and their handles differ");
      for (std::size_t i = 0; i < b.size(); ++i) {
        const float shape = b.value(fields::Body::shape, i), hull = b.value(fields::Body::hull, i);
        if (!(shape == float(BodyShape::kSphere) || shape == float(BodyShape::kBox) ||
              (shape == float(BodyShape::kHull) && hull >= 0 && hull < float(b.hulls_.size()) &&
               hull == std::floor(hull))))
          Reader::fail("a body's shape");
      }
    }
  }

  template <class Ar>
  static void io(Ar& a, World& w) {
    static_assert(sizeof(WorldSettings) == 12, "a member was added: save it here");
    a.pod(w.settings_);
    if constexpr (Ar::kReading) validate(w.settings_, "restore: the world");
    io(a, w.obstacles_);
    w.systems_.resize(a.count(w.systems_.size()));
    for (ParticleSystem& p : w.systems_) io(a, p);
    io(a, w.systemHandles_);
    std::size_t cloths = a.count(w.cloths_.size());
    if constexpr (Ar::kReading)
      for (std::size_t i = 0; i < cloths; ++i) w.cloths_.push_back(Cloth());
    for (Cloth& c : w.cloths_) io(a, c);
    io(a, w.clothHandles_);
    io(a, w.bodies_);
    if (w.systemHandles_.size() != w.systems_.size() || w.clothHandles_.size() != w.cloths_.size())
      Reader::fail("the world's systems and their handles differ");
  }
};

}  // namespace detail

std::vector<std::byte> snapshot(const World& world) {
  Writer payload;
  detail::Snapshot::io(payload, const_cast<World&>(world));  // a Writer only reads
  Writer out;
  for (const char c : kMagic) out.pod(c);
  out.pod(kSnapshotVersion);
  out.pod(std::uint64_t(payload.out.size()));
  out.pod(fnv1a(payload.out));
  out.out.insert(out.out.end(), payload.out.begin(), payload.out.end());
  return std::move(out.out);
}

std::uint64_t stateHash(const World& world) { return fnv1a(snapshot(world)); }

World restore(std::span<const std::byte> bytes) {
  if (bytes.size() < kHeader || std::memcmp(bytes.data(), kMagic.data(), kMagic.size()) != 0)
    throw Error("restore: not a simdphys snapshot (no \"SIMDPHYS-SNAPSHOT\" header)");
  Reader header{bytes, kMagic.size()};
  std::uint32_t version = 0;
  std::uint64_t length = 0, checksum = 0;
  header.pod(version), header.pod(length), header.pod(checksum);
  if (version != kSnapshotVersion)
    throw Error("restore: snapshot format version " + std::to_string(version) +
                ", this library reads version " + std::to_string(kSnapshotVersion));
  const std::span<const std::byte> payload = bytes.subspan(kHeader);
  if (payload.size() < length)
    throw Error("restore: the snapshot is truncated: " + std::to_string(payload.size()) + " of " +
                std::to_string(length) + " bytes of data");
  if (payload.size() > length)
    throw Error("restore: the snapshot has " + std::to_string(payload.size() - length) +
                " bytes after its data");
  if (fnv1a(payload) != checksum)
    throw Error("restore: the snapshot is corrupt (its checksum differs)");
  World world;
  Reader r{payload};
  detail::Snapshot::io(r, world);
  if (r.at != payload.size()) Reader::fail("data is left after the world");
  return world;
}

void saveSnapshot(const World& world, const std::filesystem::path& file) {
  const std::vector<std::byte> bytes = snapshot(world);
  std::ofstream out(file, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  if (!out) throw Error("saveSnapshot: " + file.string() + ": cannot be written");
}

World loadSnapshot(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error("loadSnapshot: " + file.string() + ": cannot be read");
  std::vector<char> text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  try {
    return restore(std::as_bytes(std::span(text)));
  } catch (const Error& e) {
    throw Error(file.string() + ": " + e.what());
  }
}

}  // namespace simdphys
