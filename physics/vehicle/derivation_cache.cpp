#include "vehicle/derivation_cache.h"

#include <cstdio>
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <unistd.h>

namespace bdfcar::vehicle {

namespace {

constexpr char kMagic[8] = {'B', 'D', 'F', 'C', 'A', 'C', 'H', '1'};

class Fnv {
 public:
  void bytes(const void* p, std::size_t n) {
    const unsigned char* c = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) h_ = (h_ ^ c[i]) * 1099511628211ull;
  }
  template <class T>
  void add(const T& v) {
    bytes(&v, sizeof v);
  }
  void add(const std::string& s) {
    add(s.size());
    bytes(s.data(), s.size());
  }
  void add(const Vec3& v) { bytes(v.data(), 3 * sizeof(double)); }
  void add(const Mat3& m) { bytes(m.data(), 9 * sizeof(double)); }
  void add(const mb::JointFrame& f) {
    add(f.origin);
    add(f.axes);
  }
  void add(const mb::ForceCurve& c) {
    add(c.coefficient);
    add(c.x.size());
    bytes(c.x.data(), c.x.size() * sizeof(double));
    bytes(c.force.data(), c.force.size() * sizeof(double));
  }
  std::uint64_t value() const { return h_; }

 private:
  std::uint64_t h_ = 14695981039346656037ull;
};

}  // namespace

std::uint64_t hashBytes(const std::vector<char>& b) {
  Fnv f;
  f.bytes(b.data(), b.size());
  return f.value();
}

void ByteBuffer::putDoubles(const std::vector<double>& v) {
  put(static_cast<std::uint64_t>(v.size()));
  const char* p = reinterpret_cast<const char*>(v.data());
  bytes.insert(bytes.end(), p, p + v.size() * sizeof(double));
}

bool ByteBuffer::getDoubles(std::vector<double>& v) {
  std::uint64_t n = 0;
  if (!get(n) || n > (bytes.size() - pos_) / sizeof(double)) {
    pos_ = bytes.size() + 1;  // every later read fails
    return false;
  }
  v.resize(n);
  for (double& x : v) get(x);
  return true;
}

std::uint64_t derivationFingerprint(const Vehicle& v) {
  Fnv f;
  const mb::Model& m = v.model;
  for (const mb::Body& b : m.bodies) {
    f.add(b.name);
    f.add(b.mass);
    f.add(b.com);
    f.add(b.inertia);
    f.add(b.rotorInertia);
    f.add(b.rotorAxis);
    f.add(b.parent);
    f.add(b.joint);
    f.add(b.inParent);
    f.add(b.inChild);
  }
  for (const mb::CutJoint& c : m.cutJoints) {
    f.add(c.name);
    f.add(c.type);
    f.add(c.bodyA);
    f.add(c.bodyB);
    f.add(c.pointA);
    f.add(c.pointB);
    f.add(c.length);
    f.add(c.drivenBody);
    f.add(c.drivenCoordinate);
  }
  for (const mb::SpringDamper& s : m.springs) {
    f.add(s.name);
    f.add(s.bodyA);
    f.add(s.bodyB);
    f.add(s.pointA);
    f.add(s.pointB);
    f.add(s.freeLength);
    f.add(s.preload);
    f.add(s.lumpedWeight);
    f.add(s.spring);
    f.add(s.damper);
    f.add(s.bumpLength);
    f.add(s.bumpStiffness);
    f.add(s.reboundLength);
    f.add(s.reboundStiffness);
  }
  f.add(m.gravity);
  const VehicleLayout& L = v.layout;
  f.add(L.chassis);
  f.add(L.rack);
  for (const WheelLayout& w : L.wheels) {
    f.add(w.spindle);
    f.add(w.carrier);
    f.add(w.spinSign);
  }
  f.add(v.spec.steering.rackTravelFull);
  f.add(v.spec.designHeight);
  for (const WheelSpec& w : v.spec.wheels) {
    // The tyre's radius and stiffness set the static loads and travels.
    f.add(tyre::unloadedRadius(w.tyre));
    f.add(tyre::verticalStiffness(w.tyre));
    f.add(tyre::verticalDamping(w.tyre));
  }
  return f.value();
}

std::string derivationCacheDirectory() {
  if (const char* d = std::getenv("BDFCAR_CACHE_DIR")) {
    const std::string dir = d;
    return dir == "off" ? std::string() : dir;
  }
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return std::string(x) + "/bdfcar";
  if (const char* h = std::getenv("HOME"); h && *h) return std::string(h) + "/.cache/bdfcar";
  return {};
}

std::string derivationCachePath(const std::string& kind, std::uint64_t key) {
  const std::string dir = derivationCacheDirectory();
  if (dir.empty()) return {};
  char name[64];
  std::snprintf(name, sizeof name, "%s-%016llx.bin", kind.c_str(), static_cast<unsigned long long>(key));
  return dir + "/" + name;
}

std::optional<ByteBuffer> readDerivationCache(const std::string& kind, std::uint64_t key) {
  const std::string path = derivationCachePath(kind, key);
  if (path.empty()) return std::nullopt;
  std::ifstream f(path, std::ios::binary);
  if (!f) return std::nullopt;
  const std::vector<char> all((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  // magic | key | payload size | payload | checksum of the payload
  const std::size_t head = sizeof kMagic + 2 * sizeof(std::uint64_t), tail = sizeof(std::uint64_t);
  if (all.size() < head + tail || !std::equal(kMagic, kMagic + sizeof kMagic, all.begin())) return std::nullopt;
  std::uint64_t storedKey = 0, size = 0, sum = 0;
  std::copy(all.begin() + 8, all.begin() + 16, reinterpret_cast<char*>(&storedKey));
  std::copy(all.begin() + 16, all.begin() + 24, reinterpret_cast<char*>(&size));
  if (storedKey != key || size != all.size() - head - tail) return std::nullopt;
  ByteBuffer b;
  b.bytes.assign(all.begin() + head, all.end() - tail);
  std::copy(all.end() - tail, all.end(), reinterpret_cast<char*>(&sum));
  if (sum != hashBytes(b.bytes)) return std::nullopt;
  return b;
}

bool writeDerivationCache(const std::string& kind, std::uint64_t key, const ByteBuffer& payload) {
  const std::string path = derivationCachePath(kind, key);
  if (path.empty()) return false;
  std::error_code ec;
  std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
  // A name of this process's own: parallel runs (a sweep) write side by side.
  const std::string temp = path + ".tmp" + std::to_string(static_cast<long long>(::getpid()));
  {
    std::ofstream f(temp, std::ios::binary | std::ios::trunc);
    if (!f) return false;
    const std::uint64_t size = payload.bytes.size(), sum = hashBytes(payload.bytes);
    f.write(kMagic, sizeof kMagic);
    f.write(reinterpret_cast<const char*>(&key), sizeof key);
    f.write(reinterpret_cast<const char*>(&size), sizeof size);
    f.write(payload.bytes.data(), static_cast<std::streamsize>(payload.bytes.size()));
    f.write(reinterpret_cast<const char*>(&sum), sizeof sum);
    if (!f.flush()) {
      std::filesystem::remove(temp, ec);
      return false;
    }
  }
  std::filesystem::rename(temp, path, ec);
  if (ec) std::filesystem::remove(temp, ec);
  return !ec;
}

}  // namespace bdfcar::vehicle
