// What the renderer and the HUD read from a running vehicle: world poses of
// the chassis and wheels, suspension members as segments, and the figures a
// driver wants to see. Plain data, copied out of the physics once per frame.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <utility>
#include <string>
#include <vector>

namespace bdfcar::vehicle {

struct BodyPose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();           // world, m
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity(); // body axes in world
};

enum class LinkKind { Arm, Strut, TieRod, Link, Rack, Spring };

// A suspension member drawn as a cylinder between two world points.
struct LinkSegment {
  Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero();
  double radius = 0.015;
  LinkKind kind = LinkKind::Link;
};

// Wheel index order everywhere: 0 FL, 1 FR, 2 RL, 3 RR.
struct WheelView {
  BodyPose pose;                    // spindle frame: y = spin axis (pointing left on both sides), x forward
  double radius = 0.31, width = 0.235;
  Eigen::Vector3d contactPoint = Eigen::Vector3d::Zero();
  double normalForce = 0.0;         // N
  bool inContact = false;
};

// Static geometry of the car body for drawing (from the vehicle file).
struct VehicleGeometry {
  std::string bodyMesh;             // path of the body mesh asset (OBJ), chassis frame, m; empty = a box
  Eigen::Vector3d bodyColour = Eigen::Vector3d(0.75, 0.08, 0.08);
  double length = 4.6, width = 1.9, height = 1.4;  // m, bounding box of the body
  double wheelbase = 2.46, trackFront = 2.2, trackRear = 1.9;
  double wheelRadius = 0.3099, wheelWidth = 0.235;
  Eigen::Vector3d bodyOffset = Eigen::Vector3d::Zero();  // body box centre in chassis frame
};

struct VehicleView {
  double time = 0.0;                // s
  BodyPose chassis;                 // chassis reference frame (x forward, y left, z up)
  std::array<WheelView, 4> wheels;
  std::vector<LinkSegment> links;   // suspension members, world coordinates
  // The best lap's car at the same time into the lap (a timed circuit's
  // ghost, drawn translucent): its chassis frame, when there is one.
  bool ghost = false;
  BodyPose ghostChassis;
};

// Figures for the heads-up display.
struct HudInfo {
  double time = 0.0;                // s
  double speed = 0.0;               // m/s (the HUD shows km/h)
  double steeringWheelAngle = 0.0;  // rad (the HUD shows degrees)
  double lateralAcceleration = 0.0; // m/s^2, COM along chassis y, + left (telemetry ay_mps2)
  double longitudinalAcceleration = 0.0;  // m/s^2, COM along chassis x, + forward (ax_mps2)
  double yawRate = 0.0;             // rad/s
  double realTimeFactor = 0.0;      // simulated / wall time
  // What that ratio measures: "RTF" a live drive's (paced at 1, over the
  // last second), "render" frames drawn without a display (simulation,
  // drawing and encoding together: the rendering's speed, not the car's).
  std::string realTimeLabel = "RTF";
  double stepTime = 0.0;            // s of wall time per 10 ms physics step
  double throttle = 0.0, brake = 0.0;  // 0..1: the pedals the car gets (a speed hold's included)
  double speedHold = -1.0;          // m/s a speed hold keeps (it drives: no throttle to show), -1 none
  // A car with a powertrain: its gear (-1 R, 0 N, 1..n) and engine speed.
  bool powertrain = false;
  int gear = 0;
  double engineRpm = 0.0;
  bool shifting = false;
  double handbrake = 0.0;           // 0..1
  int coneHits = -1;                // -1 = not on a cone course
  std::vector<std::pair<int, double>> knockedCones;  // index in the course's cones, heading of the car that hit it (rad)
  double courseTime = -1.0;         // s, -1 = not timing
  // Lap timing (a scenario with [laps]): the lap under way (-1: no timing,
  // 0: the out lap), the sector, its time so far, the last and the best lap
  // (s, -1 none), the delta to the best at the same distance (s, NaN none).
  int lap = -1, sector = 0;
  double lapTime = -1.0, lastLap = -1.0, bestLap = -1.0, lapDelta = 0.0;
  bool lapDeltaShown = false, lapValid = true;
  // The course's verdict the moment it is decided: "" while open, else
  // "PASSED" or "FAILED: why".
  std::string verdict;
  std::string model;                // the rung of the fidelity ladder driving (linkage, kinematic)
  // What the suspension view (body translucent or hidden) draws for that model.
  std::string members;
  std::string message;              // status line (paused, recording, diverged, ...)
  std::string menu;                 // the pause menu's lines while it is open ("" closed)
  double mapX = 0, mapY = 0, mapYaw = 0;  // the car on the track map: centre of mass (world, m), heading (rad)
};

}  // namespace bdfcar::vehicle
