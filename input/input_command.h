// What the three modes of `bdfcar input` (monitor, calibrate, force-feedback
// test) share (private to input/).
#pragma once

#include <cstdio>
#include <functional>
#include <vector>

#include "input/input_system.h"
#include "input/monitor.h"

namespace bdfcar::input {

constexpr double kCommandTick = 0.01;  // s, the simulator's input rate
constexpr int kExitInterrupted = 130;  // 128 + SIGINT, as every bdfcar command (README, "Exit codes")

// Whether Ctrl-C (SDL turns SIGINT into SDL_QUIT) asked to stop.
bool quitRequested();

// One tick's wait, then that tick's controls (devices' new state read).
Controls waitTick(InputSystem& input);

// The line every mode prints when there is no wheel, joystick or game
// controller, with what that means for the mode ("nothing to calibrate").
void sayNoDevice(std::FILE* out, const char* consequence);

// The device a mode works on: the driving one, else the first; nullptr: none.
const DeviceStatus* commandDevice(const std::vector<DeviceStatus>& devices);

// The device with this instance id now, or nullptr (unplugged).
const DeviceStatus* findStatus(const std::vector<DeviceStatus>& devices, int instanceId);

// Opens the devices of o (mapping folder, name filter) and runs body on them.
// Exceptions (a bad mapping file names file:line; SDL failures) are printed
// as "bdfcar input: ..." and return 1.
int withDevices(const MonitorOptions& o, const std::function<int(InputSystem&)>& body);

// withDevices, the body run on the
// commandDevice; with none, says so (sayNoDevice) and returns 0, as the monitor does.
int withCommandDevice(const MonitorOptions& o, const char* noDeviceConsequence,
                      const std::function<int(InputSystem&, const DeviceStatus&)>& body);

}  // namespace bdfcar::input
