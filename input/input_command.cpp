#include "input_command.h"

#include <SDL.h>

namespace bdfcar::input {

// SDL's quit event, taken only if there is one.
bool quitRequested() {
  SDL_Event e;
  return SDL_PeepEvents(&e, 1, SDL_GETEVENT, SDL_QUIT, SDL_QUIT) > 0;
}

// 10 ms, then poll (events and device state).
Controls waitTick(InputSystem& input) {
  SDL_Delay(static_cast<Uint32>(kCommandTick * 1000));
  return input.poll(kCommandTick);
}

// Live values of nothing would be the keyboard's zeros for ever; a capture of nothing, nothing.
void sayNoDevice(std::FILE* out, const char* consequence) {
  std::fprintf(out,
               "no wheel, joystick or game controller is connected: %s (plug one in, or check that this user may "
               "read /dev/input; the keyboard drives through `bdfcar drive`)\n",
               consequence);
}

// The driving device first: it is the one `bdfcar drive` would read.
const DeviceStatus* commandDevice(const std::vector<DeviceStatus>& devices) {
  for (const DeviceStatus& d : devices)
    if (d.active) return &d;
  return devices.empty() ? nullptr : &devices.front();
}

// By SDL instance id (device indices shift as devices come and go).
const DeviceStatus* findStatus(const std::vector<DeviceStatus>& devices, int instanceId) {
  for (const DeviceStatus& d : devices)
    if (d.instanceId == instanceId) return &d;
  return nullptr;
}

// Devices open for the body's lifetime; errors as every mode words them.
int withDevices(const MonitorOptions& o, const std::function<int(InputSystem&)>& body) {
  InputOptions io;
  io.mappingDir = o.mappingDir;
  io.deviceFilter = o.deviceFilter;
  try {
    InputSystem input(io);
    return body(input);
  } catch (const std::exception& e) {  // MappingError carries file:line; SDL failures say which call
    std::fprintf(stderr, "bdfcar input: %s\n", e.what());
    return 1;
  }
}

// The device to work on, or the no-device line.
int withCommandDevice(const MonitorOptions& o, const char* noDeviceConsequence,
                      const std::function<int(InputSystem&, const DeviceStatus&)>& body) {
  return withDevices(o, [&](InputSystem& input) {
    const std::vector<DeviceStatus> devices = input.devices();
    const DeviceStatus* device = commandDevice(devices);
    if (!device) {
      sayNoDevice(o.out, noDeviceConsequence);
      return 0;
    }
    if (devices.size() > 1)
      std::fprintf(o.out, "%zu devices: using '%s' (--device TEXT picks another)\n", devices.size(),
                   device->name.c_str());
    return body(input, *device);
  });
}

}  // namespace bdfcar::input
