// Section 5h of RESULTS.md: a vehicle's kinematics from the K&C rig
// (physics/vehicle/kc_rig.h), as `bdfcar kc` prints them.
#include "kc_summary.h"
#include "report/studies.h"
#include "vehicle/vehicle_file.h"

namespace bdfcar::app {

void kcSection(std::ostream& md, const std::string& vehicleFile, const std::string& shownPath) {
  const vehicle::Vehicle v = vehicle::buildVehicle(vehicle::loadVehicleFile(vehicleFile));
  md << "## 5h. K&C: " << v.spec.name << "\n\n"
     << "The K&C rig's sweeps of the linkage (docs/VEHICLES.md, \"K&C rig\"): kinematics at design, the chassis held, "
     << "the wheels moved in parallel travel, in roll and by the rack.\n\n```\n"
     << kcSummary(v, shownPath, vehicle::runKcRig(v)) << "```\n\n"
     << "Command: `bdfcar kc " << shownPath << " --out DIR` (the curves as CSV and plots)\n\n";
}

}  // namespace bdfcar::app
