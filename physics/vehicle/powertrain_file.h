// Reads a vehicle file's [powertrain] table (docs/VEHICLES.md) into a
// PowertrainSpec: engine torque curve and speeds, clutch, gearbox and shift
// schedule, differential, handbrake. Checks that the schedule can work (it
// cannot hunt between two gears, it shifts below the rev limit); errors name
// the file, line and key (config::ConfigError).
#pragma once

#include "config/toml_reader.h"
#include "vehicle/powertrain_spec.h"

namespace bdfcar::vehicle {

PowertrainSpec readPowertrain(config::Table& powertrain);

}  // namespace bdfcar::vehicle
