// The K&C rig's numbers at design as text (physics/vehicle/kc_rig.h): what
// `bdfcar kc` prints and the report writes for a vehicle.
#pragma once

#include <string>

#include "vehicle/kc_rig.h"

namespace bdfcar::app {

std::string kcSummary(const vehicle::Vehicle& v, const std::string& path, const vehicle::KcResult& r);

}  // namespace bdfcar::app
