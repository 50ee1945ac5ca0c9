#include "input_virtual.h"

#include <unistd.h>

#include <fstream>

namespace bdfcar::test_input {

fs::path freshDir(const std::string& tag) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  fs::path dir = fs::temp_directory_path() /
                 ("bdfcar_test_input_" + tag + "_" + info->name() + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

fs::path writeFile(const fs::path& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir / name) << text;
  return dir / name;
}

Virtual attach(SDL_JoystickType type, const char* name, int axes, int buttons, void (*update)(void*), void* userdata) {
  SDL_VirtualJoystickDesc desc{};
  desc.version = SDL_VIRTUAL_JOYSTICK_DESC_VERSION;
  desc.type = static_cast<Uint16>(type);
  desc.naxes = static_cast<Uint16>(axes);
  desc.nbuttons = static_cast<Uint16>(buttons);
  desc.name = name;
  desc.Update = update;
  desc.userdata = userdata;
  const int index = SDL_JoystickAttachVirtualEx(&desc);
  Virtual v;
  if (index < 0) return v;
  v.joystick = SDL_JoystickOpen(index);
  v.id = SDL_JoystickInstanceID(v.joystick);
  return v;
}

int deviceIndex(SDL_JoystickID id) {
  for (int i = 0; i < SDL_NumJoysticks(); ++i)
    if (SDL_JoystickGetDeviceInstanceID(i) == id) return i;
  return -1;
}

std::string readAndClose(std::FILE* file) {
  std::rewind(file);
  std::string text;
  for (int ch; (ch = std::fgetc(file)) != EOF;) text += static_cast<char>(ch);
  std::fclose(file);
  return text;
}

void VirtualDevicesTest::SetUp() {
  setenv("SDL_VIDEODRIVER", "dummy", 1);
  ASSERT_EQ(SDL_Init(SDL_INIT_EVENTS | SDL_INIT_JOYSTICK | SDL_INIT_GAMECONTROLLER), 0) << SDL_GetError();
  dir = freshDir("devices");
}

void VirtualDevicesTest::TearDown() {
  SDL_Quit();
  fs::remove_all(dir);
}

}  // namespace bdfcar::test_input
