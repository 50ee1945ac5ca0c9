// Vehicle files (physics/vehicle/vehicle_file.h), then the model built from
// them (buildVehicle, as `bdfcar info` does): a file the loader accepts must
// build or be refused with mb::ModelError.
#include "fuzz_common.h"
#include "vehicle/vehicle_builder.h"
#include "vehicle/vehicle_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = bdfcar::fuzz::writeCase(data, size, "vehicle.toml");
  bdfcar::fuzz::expectOnlyDocumentedErrors([&] {
    const bdfcar::vehicle::VehicleSpec spec = bdfcar::vehicle::loadVehicleFile(path);
    (void)bdfcar::vehicle::buildVehicle(spec);
  });
  return 0;
}
