// bdfcar from a program of one's own (docs/API.md): a lane change run as
// `bdfcar run` runs it, then a car driven tick by tick, saved and restored,
// and (with the frames library) one picture of it.
//
//   lane_change OUT.csv
#include <bdfcar/bdfcar.h>
#ifdef WITH_FRAMES
#include <bdfcar/camera.h>
#endif

#include <cmath>
#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: lane_change OUT.csv\n");
    return 2;
  }
  try {
    const std::string scenario = bdfcar::assetDir() + "/scenarios/lane_change.toml";
    std::printf("bdfcar %s, assets in %s\n", bdfcar::version().c_str(), bdfcar::assetDir().c_str());

    const bdfcar::Telemetry t = bdfcar::run(scenario, {.duration = 2.0}, argv[1]);
    std::printf("run: %zu rows, %s, yaw rate at the end %.10g rad/s\n", t.rows(), t.ok ? "ok" : t.failure.c_str(),
                t.at(t.rows() - 1, "yawrate_radps"));

    bdfcar::Car car(scenario, {.fidelity = "planar"});
    const std::vector<char> start = car.save();
    for (int i = 0; i < 100; ++i) car.tick({.steer = 0.2});
    const std::vector<double> first = car.observation();
    car.restore(start);
    for (int i = 0; i < 100; ++i) car.tick({.steer = 0.2});
    const bool same = car.observation() == first;
    std::printf("car: t = %.2f s, %s\n", car.time(), same ? "the restored state continues bit for bit" : "DIFFERS");
    try {
      car.tick({.steer = NAN});
    } catch (const std::invalid_argument& e) {
      std::printf("refused: %s\n", e.what());
    }
#ifdef WITH_FRAMES
    bdfcar::Camera camera(car, 160, 90);
    const std::vector<std::uint8_t> rgb = camera.render();
    long lit = 0;
    for (std::uint8_t c : rgb) lit += c > 16;
    std::printf("frame: %dx%d from %s, %ld of %zu bytes lit\n", camera.width(), camera.height(),
                camera.renderer().c_str(), lit, rgb.size());
#endif
    return same && t.ok ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
