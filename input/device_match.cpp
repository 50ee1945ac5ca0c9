// Which mapping file a connected device uses.
#include <algorithm>
#include <cctype>

#include "input/mapping.h"
#include "name_match.h"

namespace bdfcar::input {

// Case-insensitive substring test.
bool containsNoCase(std::string_view haystack, std::string_view needle) {
  const auto lower = [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); };
  const auto it = std::search(haystack.begin(), haystack.end(), needle.begin(), needle.end(),
                              [&](char a, char b) { return lower(a) == lower(b); });
  return it != haystack.end();
}

namespace {

// Wheels and joysticks are both read through SDL's joystick API with axis indices.
bool joystickFamily(DeviceKind k) { return k == DeviceKind::Wheel || k == DeviceKind::Joystick; }

// How well a mapping fits a device: -1 not at all, higher is better.
int fitScore(const DeviceMapping& m, DeviceKind kind, std::string_view name) {
  if (m.kind == DeviceKind::Keyboard || kind == DeviceKind::Keyboard) return -1;
  const bool specific = !m.nameContains.empty();
  if (specific && std::none_of(m.nameContains.begin(), m.nameContains.end(),
                               [&](const std::string& s) { return containsNoCase(name, s); }))
    return -1;
  const bool sameKind = m.kind == kind;
  // SDL often types a wheel as a plain joystick: a file naming the device, or a
  // generic joystick file, may still claim any joystick-API device.
  const bool crossKind = joystickFamily(m.kind) && joystickFamily(kind) && (specific || m.kind == DeviceKind::Joystick);
  if (!sameKind && !crossKind) return -1;
  return (specific ? 2 : 0) + (sameKind ? 1 : 0);
}

}  // namespace

// Best-fitting mapping index for a device, first file wins ties; -1 for none.
int matchMapping(const std::vector<DeviceMapping>& mappings, DeviceKind kind, std::string_view deviceName) {
  int best = -1, bestScore = -1;
  for (int i = 0; i < static_cast<int>(mappings.size()); ++i) {
    const int score = fitScore(mappings[i], kind, deviceName);
    if (score > bestScore) best = i, bestScore = score;
  }
  return best;
}

}  // namespace bdfcar::input
