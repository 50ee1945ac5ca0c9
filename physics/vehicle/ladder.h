// The fidelity ladder as one list: every rung of "model only what a scene
// needs", from the full linkage down, with what it is derived from, what it
// models and what it leaves out, how a state maps to its neighbours, where
// it is valid and how its error is certified. Scenario keys, `bdfcar info`,
// telemetry, the HUD and `auto` read this list; adding a rung touches this
// list and the rung's own files (its derivation, its mapping, its validity).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "vehicle/vehicle_builder.h"

namespace bdfcar::vehicle {

struct RungDescription {
  Fidelity fidelity;
  const char* name;         // the scenario key's value, `--fidelity`, the HUD
  const char* derivedFrom;  // how the rung is made from the vehicle file
  const char* models;       // what it carries of the linkage
  const char* omits;        // what it leaves out (its certificate shows the cost)
  const char* mapping;      // how a state moves to and from the rung above it
  const char* validity;     // where it may run (checked every tick under `auto`)
  const char* certificate;  // how its error is measured for the car in hand
  bool derived;             // built from the linkage at load time (certified against it)
};

// The rungs, from the full model down (index = the Fidelity's value).
const std::array<RungDescription, 3>& ladder();
const RungDescription& describeRung(Fidelity f);
// A rung by its name; nullopt for any other text.
std::optional<Fidelity> rungByName(std::string_view name);
// The names, "linkage, kinematic, planar" (for messages).
std::string rungNames();

}  // namespace bdfcar::vehicle
