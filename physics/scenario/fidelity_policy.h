// When `[fidelity] suspension = "auto"` may drive on the planar model and
// when it needs the full one (the kinematic model): decided once per driver
// tick from what the terrain and the tyres say.
//
//  - The terrain ahead of each wheel is scanned along the heading, every
//    kScanStep of road, as far as kLookAhead seconds ahead (at least
//    kMinLookAhead): ground off the road plane (kRoadHeight) or tilted
//    (kRoadSlope), or no ground, is a stretch that needs heave, roll and
//    pitch of the base, up to kMargin past it. The road is scanned once: a
//    tick scans only what has come into range since the last one; a terrain
//    that is one level plane is not scanned at all, and a stretch the
//    terrain vouches for as a whole (Terrain::levelOver: a ground's plane
//    and its meshes' triangles there all level) costs a query per wheel (a
//    box around its strip), not a ray per wheel every kScanStep; a level
//    stretch is asked for kScanAhead beyond the look-ahead at once (a query
//    every few ticks, not every tick). The decisions are the rays' either
//    way; a stretch found rough is acted on only once within the look-ahead.
//  - The ground under each wheel now (the contact planes of the last step)
//    must be the road plane too: a car standing on a hill or a curb is not
//    on the road plane, whatever the scan says of the road ahead.
//  - A tyre using more than kSaturation of its friction needs the full model,
//    and so does a lateral acceleration (speed x yaw rate) beyond the share
//    of the tyres' limit the planar rung's certificate covers.
//  - Up at once; down only after kCalm seconds with neither (no chatter).
// The state is a plain value (part of the run state).
#pragma once

#include <array>
#include <limits>

#include <Eigen/Core>

#include "terrain/terrain.h"
#include "tyre/tyre_model.h"
#include "vehicle/vehicle_forces.h"

namespace bdfcar::scenario {

class FidelityPolicy {
 public:
  struct State {
    double odometer = 0;    // m travelled (|forward speed| x tick)
    double scanned = 0;     // m of odometer up to which the road ahead has been scanned
    double fullUntil = -1;  // m of odometer until which the full model is needed
    double calm = 0;        // s with neither rough road ahead nor a tyre near its limit
    long switches = 0;      // rung switches so far
    long missed = 0;        // of them, up from the planar model standing on ground it cannot drive on
    long refused = 0;       // switches down refused: the mapping would have moved the chassis
    double maxJump = 0;     // m, the largest chassis position jump of a switch made
    double maxTurn = 0;     // rad, the largest chassis rotation of a switch made
    bool operator==(const State&) const = default;
  };
  enum class Decision { Full, Planar, Hold };

  // wheelOffsets: each tyre's contact point relative to the centre of mass,
  // in the heading frame (x forward, y left); roadZ: the planar model's road.
  // lateralLevel: the planar rung's certified range, lateral acceleration
  // as a share of the tyres' limit (rung_certificate.h; infinite: no limit).
  FidelityPolicy(const terrain::Terrain& terrain, double roadZ, const std::array<Eigen::Vector2d, 4>& wheelOffsets,
                 const std::array<tyre::TyreParams, 4>& tyres, double lateralLevel);

  // com: centre of mass (x, y); yaw; forward speed; yaw rate; the tyres' latest outputs.
  Decision decide(State& s, const Eigen::Vector2d& com, double yaw, double speed, double yawRate,
                  const std::array<vehicle::WheelContact, 4>& wheels, double tick) const;
  // The planar model met ground it cannot drive on (the scan missed it):
  // the full model from here for kMargin.
  static void forceFull(State& s);
  // A switch down refused (it would have moved the chassis): calm again
  // before the next try.
  static void refuse(State& s);
  // Whether the ground at a point is the road plane.
  bool level(const Eigen::Vector2d& xy) const;

  static constexpr double kLookAhead = 0.6;     // s
  static constexpr double kMinLookAhead = 3.0;  // m
  static constexpr double kScanStep = 0.1;      // m
  static constexpr double kScanAhead = 2.0;     // m past the look-ahead a level stretch is vouched for at once
  static constexpr double kMargin = 1.0;        // m past the last rough point
  static constexpr double kSaturation = 0.8;    // of the tyre's friction
  static constexpr double kCalm = 1.0;          // s
  static constexpr double kRoadHeight = 0.005;  // m off the road plane
  static constexpr double kRoadSlope = 0.5 * 3.14159265358979323846 / 180;  // rad
  // cos(kRoadSlope): the least z of a level road's normal (computed once; the
  // checks ask it for every wheel at every step).
  static double roadNormalZ();
  // A switch may not move the chassis more than this (the mapping drops
  // what the lower rung has not got: heave, travels).
  static constexpr double kMaxJump = 0.005;  // m
  static constexpr double kMaxTurn = 0.01;   // rad
  // level()'s ray: down from this far above the road plane, this long.
  static constexpr double kRayAbove = 1.0;   // m
  static constexpr double kRayLength = 2.0;  // m

 private:
  // Whether the terrain vouches for the road being level under every scan
  // point from `first` to `last` (point(offset, distance)); false: scan by rays.
  template <class Point>
  bool levelAhead(double first, double last, const Point& point) const;
  const terrain::Terrain& terrain_;
  double roadZ_;
  std::array<Eigen::Vector2d, 4> offsets_;
  std::array<tyre::TyreParams, 4> tyres_;
  double lateralLevel_;
  // Each tyre's peak friction at the last road friction it was asked for
  // (a function of the two alone: asked every tick, it changes only where
  // the road's friction does).
  struct PeakFriction {
    double road = std::numeric_limits<double>::quiet_NaN(), mu = 0;
  };
  double peakFriction(int w, double road) const;
  mutable std::array<PeakFriction, 4> peak_{};
};

}  // namespace bdfcar::scenario
