// Shared by the libFuzzer targets (fuzz/*.cpp, scripts/fuzz.sh).
//
// The loaders take file paths, so each input is written to a scratch folder
// laid out like assets/: <scratch>/case/ holds the input, and <scratch>/vehicles,
// terrain, models are links to the real assets, so a scenario's
// "../vehicles/sedan.toml" resolves and a fuzzed file never lands in assets/.
//
// Error policy: the loaders' documented exceptions (config::ConfigError,
// terrain::TerrainFileError, mb::ModelError, std::invalid_argument from the
// terrain checks, a plain std::runtime_error) are correct behaviour on bad
// input. Anything else reaching the top (std::bad_alloc, std::length_error,
// std::out_of_range, std::filesystem_error, ...) is a finding: it is printed
// and the process aborts, so libFuzzer saves the input as a crash.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cxxabi.h>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <typeinfo>
#include <unistd.h>

#include "config/toml_reader.h"
#include "multibody/model_error.h"
#include "terrain/terrain_file.h"

#ifndef BDFCAR_ASSETS_DIR
#error "BDFCAR_ASSETS_DIR must name the source tree's assets/ (fuzz/CMakeLists.txt)"
#endif

namespace bdfcar::fuzz {

namespace fs = std::filesystem;


// The scratch folder of this process (removed at exit).
inline const fs::path& scratch() {
  static const fs::path dir = [] {
    const fs::path d = fs::temp_directory_path() / ("bdfcar-fuzz-" + std::to_string(::getpid()));
    fs::create_directories(d / "case");
    for (const char* sub : {"vehicles", "terrain", "models", "scenarios", "input"}) {
      std::error_code ec;
      fs::create_directory_symlink(fs::path(BDFCAR_ASSETS_DIR) / sub, d / sub, ec);
    }
    std::atexit([] {
      std::error_code ec;
      fs::remove_all(scratch(), ec);
    });
    return d;
  }();
  return dir;
}

// Writes the input to <scratch>/case/<name> and returns that path.
inline std::string writeCase(const std::uint8_t* data, std::size_t size, const std::string& name) {
  const fs::path p = scratch() / "case" / name;
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  if (!out) {
    std::fprintf(stderr, "fuzz harness: cannot write %s\n", p.c_str());
    std::abort();
  }
  return p.string();
}

inline std::string typeName(const std::type_info& t) {
  int status = 0;
  std::unique_ptr<char, void (*)(void*)> n(abi::__cxa_demangle(t.name(), nullptr, nullptr, &status), std::free);
  return status == 0 && n ? n.get() : t.name();
}

[[noreturn]] inline void unexpected(const std::exception& e) {
  std::fprintf(stderr, "==fuzz== FINDING: unexpected exception %s: %s\n", typeName(typeid(e)).c_str(), e.what());
  std::abort();
}

// Runs f and lets through only the documented loader errors.
template <class F>
void expectOnlyDocumentedErrors(F&& f) {
  try {
    f();
  } catch (const config::ConfigError&) {
  } catch (const terrain::TerrainFileError&) {
  } catch (const mb::ModelError&) {
  } catch (const std::invalid_argument&) {
  } catch (const std::runtime_error& e) {
    // A plain runtime_error is documented; its standard subclasses
    // (filesystem_error via system_error, range_error, overflow_error) are not.
    if (typeid(e) != typeid(std::runtime_error)) unexpected(e);
  } catch (const std::exception& e) {
    unexpected(e);
  }
}

}  // namespace bdfcar::fuzz
