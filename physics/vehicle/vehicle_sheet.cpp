#include "vehicle/vehicle_sheet.h"

#include <cmath>
#include <cstdio>

#include "multibody/kinematics.h"
#include "vehicle/motion_ratio.h"
#include "portable_math.h"

namespace bdfcar::vehicle {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Road-wheel angles (rad, + left) of the front wheels of the planar model at
// normalised steering s, relative to its base.
std::array<double, 2> frontAngles(const Vehicle& planar, double s) {
  mb::Data d = mb::makeData(planar.model);
  Eigen::VectorXd q = designPositions(planar);
  setRackTravel(planar, q, planar.layout.rackAxisSign * -planar.spec.steering.rackTravelFull * s);
  mb::updatePositions(planar.model, q, d);
  std::array<double, 2> a{};
  for (int w = 0; w < 2; ++w) {
    const Vec3 n = d.R[planar.layout.base].transpose() * d.R[planar.layout.wheels[w].spindle].col(1);
    a[w] = pm::atan2(-n.x(), n.y());
  }
  return a;
}

}  // namespace

VehicleSheet vehicleSheet(const Vehicle& linkage) { return vehicleSheet(linkage, derivePlanar(linkage)); }

VehicleSheet vehicleSheet(const Vehicle& linkage, const PlanarDerivation& p) {
  const PlanarLoads& P = *p.vehicle.planar;
  const Vehicle& kin = p.kinematic.vehicle;
  VehicleSheet s;
  s.mass = linkage.model.totalMass();
  s.wheelbase = P.wheelbase;
  s.track = P.track;
  s.comHeight = P.comInBase.z();
  s.comBehindFrontAxle = 0.5 * (P.basePoint[0].x() + P.basePoint[1].x()) - P.comInBase.x();
  const double g = -linkage.model.gravity.z();
  for (int a = 0; a < 2; ++a) {
    const int l = 2 * a, r = 2 * a + 1;
    s.axleLoad[a] = P.staticLoad[l] + P.staticLoad[r];
    // The axle's sprung mass: its load less its corners' unsprung masses
    // (carrier and wheel as the kinematic model has them).
    double unsprung = 0;
    for (int w : {l, r})
      unsprung += p.kinematic.carrierMass[w] + kin.model.bodies[kin.layout.wheels[w].spindle].mass;
    const double sprung = s.axleLoad[a] / g - unsprung;
    s.rideFrequency[a] = std::sqrt((P.rate[l] + P.rate[r]) / sprung) / (2 * kPi);
    s.rollCentre[a] = P.rollCentreHeight[a];
  }
  s.wheelRate = p.wheelRate;
  s.rideRate = P.rate;
  s.rollStiffness = p.rollStiffness;
  const double perSteer = roadWheelAnglePerSteer(linkage);
  s.steeringRatio = perSteer != 0 ? linkage.spec.steering.steeringWheelFull / perSteer : NAN;
  // Ackermann at 10 deg of inner (left, in a left turn) road-wheel angle:
  // the steering input found by bisection on the planar model's tables.
  const double inner = 10 * kPi / 180;
  double lo = 0, hi = 1.0;
  if (frontAngles(p.vehicle, hi)[0] < inner) {
    s.ackermann = NAN;  // the steering does not reach it
  } else {
    for (int i = 0; i < 50; ++i) (frontAngles(p.vehicle, 0.5 * (lo + hi))[0] < inner ? lo : hi) = 0.5 * (lo + hi);
    const std::array<double, 2> a = frontAngles(p.vehicle, 0.5 * (lo + hi));
    s.ackermann = ackermannPercent(a[0], a[1], s.wheelbase, s.track[0]);
  }
  return s;
}

double ackermannOuter(double inner, double wheelbase, double track) {
  return pm::atan(wheelbase / (wheelbase / pm::tan(inner) + track));
}

double ackermannPercent(double inner, double outer, double wheelbase, double track) {
  return 100 * (inner - outer) / (inner - ackermannOuter(inner, wheelbase, track));
}

std::string ackermannText(double percent) {
  if (std::isnan(percent)) return "Ackermann not measured: the steering does not reach 10 deg of inner road-wheel angle";
  char text[96];
  std::snprintf(text, sizeof text, "Ackermann %.0f %% at 10 deg inner road-wheel angle", percent);
  return text;
}

std::string describe(const VehicleSheet& s) {
  char buf[1600];
  std::snprintf(buf, sizeof buf,
                "vehicle sheet (at rest on level ground, from the linkage and its derived models):\n"
                "  mass %.1f kg, centre of mass %.3f m above the ground, %.3f m behind the front axle\n"
                "  wheelbase %.3f m, track %.3f m front, %.3f m rear\n"
                "  axle loads %.0f N front, %.0f N rear (%.1f %% front)\n"
                "  wheel rates %.0f / %.0f N/m front, %.0f / %.0f N/m rear; with the tyre %.0f / %.0f, %.0f / %.0f N/m\n"
                "  ride frequencies %.2f Hz front, %.2f Hz rear\n"
                "  roll centres %.3f m front, %.3f m rear; roll stiffness %.0f N m/deg\n"
                "  steering ratio %.2f:1; %s\n",
                s.mass, s.comHeight, s.comBehindFrontAxle, s.wheelbase, s.track[0], s.track[1], s.axleLoad[0],
                s.axleLoad[1], 100 * s.axleLoad[0] / (s.axleLoad[0] + s.axleLoad[1]), s.wheelRate[0], s.wheelRate[1],
                s.wheelRate[2], s.wheelRate[3], s.rideRate[0], s.rideRate[1], s.rideRate[2], s.rideRate[3],
                s.rideFrequency[0], s.rideFrequency[1], s.rollCentre[0], s.rollCentre[1], s.rollStiffness * kPi / 180,
                s.steeringRatio, ackermannText(s.ackermann).c_str());
  return buf;
}

}  // namespace bdfcar::vehicle
