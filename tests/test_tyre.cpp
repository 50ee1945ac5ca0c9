// Fiala tyre: the properties the spec's force law must have (small-slip
// stiffnesses, saturation at the friction limit, continuity at the critical
// slips, sign conventions, friction scaling) and well-defined behaviour at
// standstill.
#include <gtest/gtest.h>

#include <cmath>

#include "tyre/fiala.h"

using namespace bdfcar::tyre;

namespace {

FialaParams reference() { return FialaParams{}; }  // the reference sedan's Fiala data

// A wheel of the reference tyre at height z above the plane z = 0, heading +x.
WheelKinematics wheelAt(double z, double vx, double vy, double omega) {
  WheelKinematics w;
  w.centre = Vec3(0, 0, z);
  w.spinAxis = Vec3::UnitY();
  w.centreVelocity = Vec3(vx, vy, 0);
  w.spinRate = omega;
  return w;
}

ContactPlane flat(double mu = 0.8) {
  ContactPlane g;
  g.valid = true;
  g.friction = mu;
  return g;
}

}  // namespace

TEST(Fiala, SmallSlipStiffnessesAreTheCorneringAndSlipStiffness) {
  const FialaParams p = reference();
  const double Fz = 5000, e = 1e-6;
  EXPECT_NEAR(fialaPatchForces(p, e, 0, Fz, 0.8).Fx / e, p.slipStiffness, 1e-3 * p.slipStiffness);
  EXPECT_NEAR(fialaPatchForces(p, 0, e, Fz, 0.8).Fy / e, -p.corneringStiffness, 1e-3 * p.corneringStiffness);
}

TEST(Fiala, SaturatesAtTheSlidingFriction) {
  const FialaParams p = reference();
  const double Fz = 6000;
  // Full sliding (S >= 1): U = Umin, |Fy| = Umin Fz, no aligning moment.
  const PatchForces lat = fialaPatchForces(p, 0.0, 0.8, Fz, 0.8);
  EXPECT_DOUBLE_EQ(lat.Fy, -p.uMin * Fz);
  EXPECT_DOUBLE_EQ(lat.Mz, 0.0);
  // Longitudinal: Fx tends to U Fz from below as the slip grows.
  const double fx = fialaPatchForces(p, 50.0, 0.0, Fz, 0.8).Fx;
  EXPECT_LT(fx, p.uMin * Fz);
  EXPECT_GT(fx, 0.99 * p.uMin * Fz);
  // Friction scaling: half the terrain mu, half the saturated force.
  EXPECT_NEAR(fialaPatchForces(p, 0.0, 0.8, Fz, 0.4).Fy, 0.5 * lat.Fy, 1e-9);
}

TEST(Fiala, ContinuousAcrossTheCriticalSlips) {
  const FialaParams p = reference();
  const double Fz = 4000;
  // Lateral: at alpha_c the adhesion law reaches U Fz.
  const double U = p.uMax - (p.uMax - p.uMin) * std::min(1.0, std::tan(0.4));
  const double ac = std::atan(3.0 * U * Fz / p.corneringStiffness);
  const double below = fialaPatchForces(p, 0, ac * (1 - 1e-9), Fz, 0.8).Fy;
  const double above = fialaPatchForces(p, 0, ac * (1 + 1e-9), Fz, 0.8).Fy;
  EXPECT_NEAR(below, above, 1e-3 * Fz);
  // Longitudinal: at kappa_c the linear law meets the saturation branch.
  const double Uk = p.uMax - (p.uMax - p.uMin) * 0.001;
  const double kc = Uk * Fz / (2 * p.slipStiffness);
  EXPECT_NEAR(fialaPatchForces(p, kc * (1 - 1e-9), 0, Fz, 0.8).Fx, fialaPatchForces(p, kc * (1 + 1e-9), 0, Fz, 0.8).Fx,
              1e-3 * Fz);
}

TEST(Fiala, SignConventions) {
  const FialaParams p = reference();
  // Sliding to the left (alpha > 0): force to the right, aligning moment positive.
  const PatchForces f = fialaPatchForces(p, 0, 0.05, 5000, 0.8);
  EXPECT_LT(f.Fy, 0);
  EXPECT_GT(f.Mz, 0);
  // Driving slip (kappa > 0): force forward.
  EXPECT_GT(fialaPatchForces(p, 0.01, 0, 5000, 0.8).Fx, 0);
}

TEST(Fiala, NormalLoadIsTheVerticalSpringDamperOnTheDeflection) {
  const FialaTyre t(reference());
  const double delta = 0.02;
  const TyreOutput o = t.evaluate(wheelAt(0.3099 - delta, 10, 0, 10 / (0.3099 - delta)), flat(), SlipState{}, 0.01);
  ASSERT_TRUE(o.inContact);
  // kz delta, with the contact corner rounded over 10 N: eps^2 / (4 Fz) below 0.01 N here.
  EXPECT_NEAR(o.Fz, 310000 * delta, 0.01);
  EXPECT_NEAR(o.deflection, delta, 1e-12);
  // Free rolling at the loaded radius: no longitudinal force.
  EXPECT_NEAR(o.Fx, 0.0, 1e-6);
  // Off the ground: nothing.
  EXPECT_FALSE(t.evaluate(wheelAt(0.4, 10, 0, 0), flat(), SlipState{}, 0.01).inContact);
}

TEST(Fiala, ALockedWheelSlidingSlowlyBrakesWithFrictionNotMore) {
  // Locked (omega = 0), sliding forward at 1 m/s, inside the low-speed range:
  // the braking force is bounded by the sliding friction U_min Fz.
  const FialaTyre t(reference());
  const TyreOutput o = t.evaluate(wheelAt(0.3099 - 0.02, 1.0, 0, 0), flat(), SlipState{}, 0.01);
  EXPECT_LT(o.Fx, 0);
  EXPECT_GE(o.Fx, -o.Fz * reference().uMax);
}

TEST(Fiala, StandstillIsFiniteAndHoldsLikeASpring) {
  const FialaTyre t(reference());
  const double z = 0.3099 - 0.02;
  // At rest, no slip: no tangential force, nothing undefined.
  TyreOutput o = t.evaluate(wheelAt(z, 0, 0, 0), flat(), SlipState{}, 0.01);
  EXPECT_TRUE(std::isfinite(o.Fx) && std::isfinite(o.Fy) && std::isfinite(o.Mz));
  EXPECT_DOUBLE_EQ(o.Fx, 0.0);
  EXPECT_DOUBLE_EQ(o.Fy, 0.0);
  // Creeping sideways at 1 mm/s for 1 s: the tyre deflects by the distance
  // travelled and pushes back like a spring (slip = deflection / sigma_y),
  // plus the low-speed damping: no creep at a constant force.
  SlipState s;
  double force = 0;
  for (int i = 0; i < 100; ++i) {
    o = t.evaluate(wheelAt(z, 0, 1e-3, 0), flat(), s, 0.01);
    s = o.slipState;
    force = o.Fy;
  }
  const double deflection = 1e-3 * 1.0;  // m of lateral travel
  EXPECT_NEAR(s.tanAlpha, deflection / 0.15, 1e-12);
  const double damping = reference().lowSpeed.dampingY * 1e-3 / reference().corneringStiffness;
  const double expected = fialaPatchForces(reference(), 0, std::atan(deflection / 0.15 + damping), o.Fz, 0.8).Fy;
  EXPECT_NEAR(force, expected, 1e-9 * std::abs(expected));
}
