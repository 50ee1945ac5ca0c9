// What the input tests share: per-test folders of mapping files, SDL virtual
// devices (no hardware, no display), and a command's printed output.
#pragma once

#include <SDL.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

namespace bdfcar::test_input {

namespace fs = std::filesystem;

constexpr double kDt = 0.01;    // s, one tick
constexpr double kTol = 1e-12;  // values computed two ways agree to this

// A fresh per-test folder (named by tag, the test and the process).
fs::path freshDir(const std::string& tag);

// Writes a file and returns its path.
fs::path writeFile(const fs::path& dir, const std::string& name, const std::string& text);

// A virtual device held open by the test to move its axes and buttons.
struct Virtual {
  SDL_JoystickID id = -1;
  SDL_Joystick* joystick = nullptr;
};

// Attaches a virtual device of an SDL joystick type with the given counts;
// SDL calls `update(userdata)` (if given) each time it updates the device's
// state, where a test can script its axes. id < 0: SDL refused.
Virtual attach(SDL_JoystickType type, const char* name, int axes, int buttons, void (*update)(void*) = nullptr,
               void* userdata = nullptr);

// Current device index of a device (indices shift as devices come and go).
int deviceIndex(SDL_JoystickID id);

// Everything written to a temporary file so far, which it closes.
std::string readAndClose(std::FILE* file);

// The device tests' fixture: SDL headless (SDL_VIDEODRIVER=dummy, no
// display) and a fresh folder `dir` for the test's mapping files; SDL_Quit at
// the end also detaches the virtual devices. Tests keep to devices named
// kVirtualPrefix..., so a real device on the machine changes nothing.
inline constexpr const char* kVirtualPrefix = "bdfcar-test";
class VirtualDevicesTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;
  fs::path dir;
};

}  // namespace bdfcar::test_input
