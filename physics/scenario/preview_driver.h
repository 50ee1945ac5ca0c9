// A driver that steers near the friction limit: MacAdam's preview
// optimal-control driver (C. C. MacAdam, "Application of an optimal preview
// control for simulation of closed-loop automobile driving", IEEE Trans.
// Systems, Man and Cybernetics 11(6), 1981). Each tick it predicts the car
// over a preview window with an internal model of it and chooses the one
// steering command, held over the window, that minimises the squared
// distance of the predicted path from the desired one at the preview
// points: a scalar least-squares problem, solved by Gauss-Newton from the
// current command.
//
// Why this one: it is the driver the vehicle-dynamics literature validates
// lane changes with (CarSim's and TruckSim's driver models descend from it),
// it needs only what the car is (no gains to tune per car or speed: the
// preview time is the one setting), and its prediction starts from the
// measured state each tick, so the model's errors are corrected as they
// show. Pure pursuit (path_follower.h) knows nothing of the car's delay and
// cuts or overshoots the lane changes of ISO 3888-2 at speed.
//
// The internal model (vehicle/single_track.h): the single-track car with
// tyres saturating at the road's friction times each axle's static load
// (the linear model alone promises grip the car does not have near the
// limit), the steering system between command and rack as the simulation
// has it (steering_system.h: rate and acceleration bounds, response time),
// the speed held. Stateless: the run state holds nothing of it.
#pragma once

#include <functional>

#include "scenario/steering_system.h"
#include "vehicle/single_track.h"

namespace bdfcar::scenario {

// The signed distance (m) of a point from the desired path, + to the left
// of the path's direction.
using PathOffset = std::function<double(double x, double y)>;

struct PreviewDriverParams {
  double previewTime = 1.0;   // s, the window
  int previewPoints = 15;     // spread evenly over it
  int commandMoves = 6;       // the commands over the window: held over equal parts of it
  // Weight of the squared change of road-wheel angle between parts (m^2 per
  // rad^2): what keeps the commands smooth, as a driver's hands are.
  double changeWeight = 1.0;
  double tick = 0.01;         // s, the driver's tick (the command is held over it)
  SteeringLimits steering;    // the steering system's, in normalised units
  vehicle::SingleTrack car;   // the internal model
  double frontGrip = 0, rearGrip = 0;  // N, the most lateral force per axle (friction x static load)
};

struct PreviewCarState {
  double x = 0, y = 0, yaw = 0;  // the point that follows the path, and the heading (rad)
  double vx = 0, vy = 0;         // m/s, body axes
  double yawRate = 0;            // rad/s
  double steer = 0, steerRate = 0;  // the rack now, normalised (and per s)
};

class PreviewDriver {
 public:
  PreviewDriver(const PreviewDriverParams& p, PathOffset offset) : p_(p), offset_(std::move(offset)) {}
  // The normalised steering command for the next tick, in [-1, 1].
  double steer(const PreviewCarState& s) const;
  // The squared preview error of holding `command` over the whole window (for tests).
  double previewError(const PreviewCarState& s, double command) const;

 private:
  // The offsets at the preview points with commands[k] held over part k.
  void predict(const PreviewCarState& s, const double* commands, double* offsets) const;
  int windowTicks() const;
  int previewPoints() const;
  int commandMoves() const;
  PreviewDriverParams p_;
  PathOffset offset_;
};

// The internal model's parameters for a vehicle (its linkage: World::linkageVehicle) on road friction mu.
PreviewDriverParams previewDriverParams(const vehicle::Vehicle& v, double mu, double tick);

}  // namespace bdfcar::scenario
