// An on-disk cache of what deriving a reduced model costs (the linkage sweep
// and its check: about 0.2 s for the reference sedan), keyed by a
// fingerprint of everything the derivation reads from the linkage model and
// by the format version, so that an edited vehicle file never finds a stale
// entry. A missing, unreadable, truncated or corrupt entry is a miss (the
// model is derived again and the entry rewritten); a cache directory that
// cannot be written costs nothing but the time.
//
// Where: $BDFCAR_CACHE_DIR, else $XDG_CACHE_HOME/bdfcar, else
// $HOME/.cache/bdfcar. BDFCAR_CACHE_DIR=off (or empty) turns it off.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "vehicle/vehicle_builder.h"

namespace bdfcar::vehicle {

// Bytes with typed writes and checked reads (the entry's payload).
class ByteBuffer {
 public:
  std::vector<char> bytes;
  template <class T>
  void put(const T& value) {
    const char* p = reinterpret_cast<const char*>(&value);
    bytes.insert(bytes.end(), p, p + sizeof(T));
  }
  void putDoubles(const std::vector<double>& v);
  // Reads from the front; false once past the end (every later read fails too).
  template <class T>
  bool get(T& value) {
    if (pos_ + sizeof(T) > bytes.size()) return false;
    std::copy(bytes.begin() + pos_, bytes.begin() + pos_ + sizeof(T), reinterpret_cast<char*>(&value));
    pos_ += sizeof(T);
    return true;
  }
  bool getDoubles(std::vector<double>& v);
  bool atEnd() const { return pos_ == bytes.size(); }

 private:
  std::size_t pos_ = 0;
};

// FNV-1a of bytes (a cache key from several parts).
std::uint64_t hashBytes(const std::vector<char>& bytes);

// FNV-1a over what a derivation reads: every body, cut joint and spring of
// the model, the layout, the rack's travel at full steer, the design height.
std::uint64_t derivationFingerprint(const Vehicle& v);

// The cache directory, or empty when the cache is off.
std::string derivationCacheDirectory();

// The entry's path for a kind ("kinematic") and key; empty when the cache is off.
std::string derivationCachePath(const std::string& kind, std::uint64_t key);
std::optional<ByteBuffer> readDerivationCache(const std::string& kind, std::uint64_t key);
// Written to a temporary file and renamed into place; false if it could not be.
bool writeDerivationCache(const std::string& kind, std::uint64_t key, const ByteBuffer& payload);

}  // namespace bdfcar::vehicle
