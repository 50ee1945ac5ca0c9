// Loads a vehicle data file (assets/vehicles/*.toml) into a VehicleSpec.
// Left-hand parts marked `mirror = true` are copied to the right with
// y -> -y; names get "L"/"R" appended (spindle_F -> spindle_FL, spindle_FR).
// Errors throw config::ConfigError naming the file, line, key and expectation.
#pragma once

#include <string>
#include <vector>

#include "config/toml_reader.h"
#include "vehicle/vehicle_spec.h"

namespace bdfcar::vehicle {

// `settings` (--set) apply over the file (config::parseTomlFile).
VehicleSpec loadVehicleFile(const std::string& path, const std::vector<config::Setting>& settings = {});

}  // namespace bdfcar::vehicle
