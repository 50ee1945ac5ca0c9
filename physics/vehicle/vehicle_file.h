// Loads a vehicle data file (assets/vehicles/*.toml) into a VehicleSpec.
// Left-hand parts marked `mirror = true` are copied to the right with
// y -> -y; names get "L"/"R" appended (spindle_F -> spindle_FL, spindle_FR).
// Errors throw config::ConfigError naming the file, line, key and expectation.
#pragma once

#include <string>

#include "vehicle/vehicle_spec.h"

namespace bdfcar::vehicle {

VehicleSpec loadVehicleFile(const std::string& path);

}  // namespace bdfcar::vehicle
