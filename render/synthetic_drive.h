// A kinematic car driving the ISO 3888-1 lane change along the course's
// reference line: no physics, just plausible poses, steering, wheel spin,
// body roll and suspension links (hardpoints of the reference sedan). For
// renderer tests, benchmarks and demos before the multibody vehicle exists.
#pragma once

#include "scenario/iso3888_course.h"
#include "vehicle/vehicle_view.h"

namespace bdfcar::render {

struct SyntheticDrive {
  scenario::Iso3888Course course;
  double speed = 60.0 / 3.6;  // m/s along x
  double leadIn = 20.0;       // m driven before the course starts
  double groundZ = 0.0;       // height of the (flat) ground
};

struct SyntheticFrame {
  vehicle::VehicleView view;
  vehicle::HudInfo hud;
};

// State of the kinematic car at time t (s) after the start of the run.
SyntheticFrame syntheticLaneChange(const SyntheticDrive& drive, double t);

// Duration of the run from the lead-in to 20 m past the course end, s.
double syntheticDuration(const SyntheticDrive& drive);

}  // namespace bdfcar::render
