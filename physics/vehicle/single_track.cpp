#include "vehicle/single_track.h"

#include <Eigen/Dense>
#include <cmath>

#include "tyre/tyre_model.h"
#include "vehicle/mass_moments.h"
#include "vehicle/motion_ratio.h"
#include "vehicle/vehicle_sheet.h"

namespace bdfcar::vehicle {

namespace {
// The model as x' = A x + B delta, a_y = C x + D delta, x = (vy, r).
struct StateSpace {
  Eigen::Matrix2d A;
  Eigen::Vector2d B;
  Eigen::RowVector2d C;
  double D = 0;
};

StateSpace stateSpace(const SingleTrack& s, double u) {
  const double Cf = s.frontStiffness, Cr = s.rearStiffness, m = s.mass, I = s.yawInertia;
  StateSpace ss;
  ss.A << -(Cf + Cr) / (m * u), -(s.a * Cf - s.b * Cr) / (m * u) - u,
      -(s.a * Cf - s.b * Cr) / (I * u), -(s.a * s.a * Cf + s.b * s.b * Cr) / (I * u);
  ss.B << Cf / m, s.a * Cf / I;
  ss.C << ss.A(0, 0), ss.A(0, 1) + u;  // a_y = vy' + u r
  ss.D = ss.B(0);
  return ss;
}
}  // namespace

double SingleTrack::understeerGradient() const {
  return mass * (b * rearStiffness - a * frontStiffness) / (wheelbase() * frontStiffness * rearStiffness);
}

double SingleTrack::steadyLateralGain(double u) const {
  return u * u / (wheelbase() + understeerGradient() * u * u);
}

void SingleTrack::derivatives(double u, double vy, double r, double delta, double& dvy, double& dr) const {
  const double Ff = frontStiffness * (delta - (vy + a * r) / u);
  const double Fr = -rearStiffness * (vy - b * r) / u;
  dvy = (Ff + Fr) / mass - u * r;
  dr = (a * Ff - b * Fr) / yawInertia;
}

double SingleTrack::lateralAcceleration(double u, double vy, double r, double delta) const {
  double dvy = 0, dr = 0;
  derivatives(u, vy, r, delta, dvy, dr);
  return dvy + u * r;
}

double SingleTrack::rampLag(double u) const {
  // G(s) = C (sI - A)^-1 B + D = G0 + G1 s + ...: a ramp rho t gives
  // a_y -> G0 rho t + G1 rho = G0 rho (t - lag), lag = -G1 / G0, with
  // G0 = D - C A^-1 B and G1 = -C A^-2 B.
  const StateSpace ss = stateSpace(*this, u);
  const Eigen::Matrix2d Ai = ss.A.inverse();
  const double G0 = ss.D - ss.C * Ai * ss.B;
  const double G1 = -ss.C * Ai * Ai * ss.B;
  return -G1 / G0;
}

SingleTrack singleTrack(const Vehicle& v) {
  SingleTrack s;
  const VehicleSheet sheet = vehicleSheet(v);
  MassMoments all;
  for (const BodySpec& body : v.spec.bodies) all.add(body.mass, body.com, body.inertia);
  s.mass = all.m;
  s.yawInertia = all.inertiaAtCom()(2, 2);
  s.a = sheet.comBehindFrontAxle;
  s.b = sheet.wheelbase - sheet.comBehindFrontAxle;
  for (int axle = 0; axle < 2; ++axle) {
    const double load = 0.5 * sheet.axleLoad[axle];
    const double C = tyre::corneringStiffness(v.wheel(2 * axle).tyre, load) +
                     tyre::corneringStiffness(v.wheel(2 * axle + 1).tyre, load);
    (axle == 0 ? s.frontStiffness : s.rearStiffness) = C;
  }
  s.roadWheelPerSteer = roadWheelAnglePerSteer(v);
  return s;
}

}  // namespace bdfcar::vehicle
