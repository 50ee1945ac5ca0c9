// `bdfcar tyre`'s numbers (app/tyre_curves.h) against what does not come
// from its code:
//  - the shipped Sedan_Pac02Tire.tir in the chrono9 evaluation against
//    ../shared/reference/tyre-pac2002.md sections 5.2, 5.4, 5.5 and 5.6 (an
//    independent transcription of Chrono 9.0.1's ChPac02Tire), within the
//    precision those values are printed to, turned into the ISO convention
//    the curves use (alpha = -alpha_c, Fy = -Fy_c, Mz = -Mz_c, section 2.3);
//  - the Fiala tyre of sedan.toml against the closed forms of its law
//    (physics/tyre/fiala.h: Fx = C_kappa kappa below kappa_c = U Fz /
//    (2 C_kappa), U Fz - (U Fz)^2 / (4 |kappa| C_kappa) above; Fy = -U Fz
//    (1 - H^3) sgn(alpha), H = 1 - C_alpha |tan alpha| / (3 U Fz), U = u_max -
//    (u_max - u_min) S, S = the combined slip magnitude) at the reference
//    friction: its stiffnesses are C_alpha and C_kappa, and the peaks are
//    where the derivatives vanish, derived below by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "tyre/pac2002_file.h"
#include "tyre_curves.h"
#include "vehicle/vehicle_file.h"

namespace bdfcar::app {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
const std::string kSource = BDFCAR_SOURCE_DIR;

tyre::TyreParams chrono9() {
  return tyre::readPac2002(kSource + "/assets/tyres/Sedan_Pac02Tire.tir", tyre::Pac2002Variant::Chrono9).params;
}

tyre::FialaParams sedanFiala() {
  const vehicle::VehicleSpec s = vehicle::loadVehicleFile(kSource + "/assets/vehicles/sedan.toml");
  return std::get<tyre::FialaParams>(s.wheels.at(0).tyre);
}

// The sample of a uniform grid at x.
double at(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
  const double step = xs[1] - xs[0];
  const long i = std::lround((x - xs[0]) / step);
  EXPECT_NEAR(xs.at(i), x, 1e-9);
  return ys.at(i);
}

// tyre-pac2002.md 5.5, Fz = FNOMIN = 4850 N, mu = mu0 (mu_s = 1).
TEST(TyreCurvesChrono9, StiffnessAndPeaksAtTheNominalLoad) {
  const tyre::TyreParams p = chrono9();
  const TyreCurves c = tyreCurves(p, 4850, 0.8);
  EXPECT_EQ(c.model, "PAC2002 (chrono9)");
  EXPECT_DOUBLE_EQ(c.unloadedRadius, 0.344);
  // Slope at zero: -76820 N/rad = -1340.8 N/deg (printed to 5 digits).
  EXPECT_NEAR(c.atNominal.cornering, 76820, 0.5);
  EXPECT_NEAR(c.atNominal.cornering * kDeg, 1340.8, 0.05);
  EXPECT_NEAR(c.atNominal.corneringModel, 76959, 0.5);  // |Ky| = |By Cy Dy|
  EXPECT_NEAR(c.atNominal.slip, 114189, 0.5);
  EXPECT_NEAR(c.atNominal.slipModel, 114283, 0.5);
  // Pure-slip maxima (the clamp's plateaus). alpha_c > 0 is alpha_ISO < 0:
  // |Fy0|/Fz = 0.9521 (plateau -4617.42 N internal, +4617.42 N in ISO, from
  // alpha_c = 7.51 deg); alpha_c < 0: 1.0135 (+4915.27 N, from -7.82 deg).
  // The ratio 4617.42 / 4850 = 0.952045 is printed as 0.9521: a tolerance of
  // one unit in the last digit.
  const CurvePeak& neg = c.lateral[1];
  const CurvePeak& pos = c.lateral[0];
  EXPECT_NEAR(neg.mu, 0.9521, 1e-4);
  EXPECT_NEAR(neg.value, 4617.42, 0.01);
  EXPECT_NEAR(neg.slip / kDeg, -7.51, 0.006);
  EXPECT_NEAR(pos.mu, 1.0135, 5e-5);
  EXPECT_NEAR(pos.value, -4915.27, 0.01);
  EXPECT_NEAR(pos.slip / kDeg, 7.82, 0.006);
  // Fx0 plateaus at +-5484.6 N (|Fx|/Fz = 1.1308) for kappa > 0.1221 or < -0.1248.
  EXPECT_NEAR(c.longitudinal[0].value, 5484.6, 0.05);
  EXPECT_NEAR(c.longitudinal[1].value, -5484.6, 0.05);
  EXPECT_NEAR(c.longitudinal[0].mu, 1.1308, 5e-5);
  EXPECT_NEAR(c.longitudinal[1].mu, 1.1308, 5e-5);
  EXPECT_NEAR(c.longitudinal[0].slip, 0.1221, 6e-5);
  EXPECT_NEAR(c.longitudinal[1].slip, -0.1248, 6e-5);
}

// tyre-pac2002.md 5.2 and 5.4 in ISO: the curves' signs and values.
TEST(TyreCurvesChrono9, CurvesInTheIsoConvention) {
  const TyreCurves c = tyreCurves(chrono9(), 4850, 0.8);
  // Nominal load is the middle of the three; alpha_ISO = +2 deg is alpha_c = -2 deg.
  EXPECT_NEAR(at(c.alpha, c.Fy[1], 2 * kDeg), -2441.82, 0.01);
  EXPECT_NEAR(at(c.alpha, c.Mz[1], 2 * kDeg), 96.847, 0.001);
  EXPECT_NEAR(at(c.alpha, c.Fy[1], -4 * kDeg), 3828.81, 0.01);
  EXPECT_NEAR(at(c.alpha, c.Mz[1], -4 * kDeg), -79.002, 0.001);
  EXPECT_NEAR(at(c.kappa, c.Fx[1], 0.05), 4311.88, 0.01);
  EXPECT_NEAR(at(c.kappa, c.Fx[1], -0.10), -5358.80, 0.01);
  // Combined (ellipse), kappa = 0.05 at alpha_ISO = 4 deg (alpha_c = -4 deg): Fx 2771.54, Fy_c -3528.69.
  EXPECT_EQ(TyreCurves::combinedAlphaDeg[2], 4);
  EXPECT_NEAR(at(c.kappa, c.combinedFx[2], 0.05), 2771.54, 0.01);
  EXPECT_NEAR(at(c.kappa, c.combinedFy[2], 0.05), -3528.69, 0.01);
}

// A tyre mounted on the side it was not measured on is its mirror image
// (tyre-pac2002.md 1.1): Fy_R(alpha) = -Fy_L(-alpha), Mz_R(alpha) = -Mz_L(-alpha),
// so the right tyre at alpha_ISO = +2 deg has the left one's values at
// alpha_c = +2 deg (table 5.2) in the contact frame, and the peaks change sides.
TEST(TyreCurvesChrono9, TheRightTyreIsTheMirrorImage) {
  tyre::TyreParams p = chrono9();
  std::get<tyre::Pac2002Params>(p).mountedLeft = false;
  const TyreCurves c = tyreCurves(p, 4850, 0.8);
  EXPECT_NEAR(at(c.alpha, c.Fy[1], 2 * kDeg), -2429.41, 0.01);
  EXPECT_NEAR(at(c.alpha, c.Mz[1], 2 * kDeg), 72.922, 0.001);
  EXPECT_NEAR(c.lateral[0].value, -4617.42, 0.01);
  EXPECT_NEAR(c.lateral[0].slip / kDeg, 7.51, 0.006);
  EXPECT_NEAR(c.lateral[1].value, 4915.27, 0.01);
  EXPECT_NEAR(c.atNominal.cornering, 76820, 0.5);
}

// tyre-pac2002.md 5.6: the slope at alpha = 0 at other loads, 0.5x-2x rows.
TEST(TyreCurvesChrono9, CorneringStiffnessOverTheLoad) {
  EXPECT_NEAR(tyreCurves(chrono9(), 6300, 0.8).atNominal.cornering, 83919, 0.5);
  EXPECT_NEAR(tyreCurves(chrono9(), 3000, 0.8).atNominal.cornering, 57240, 0.5);
  const TyreCurves c = tyreCurves(chrono9(), 4850, 0.8);
  EXPECT_DOUBLE_EQ(stiffnessAt(c, 1.0).Fz, 4850);
  EXPECT_DOUBLE_EQ(stiffnessAt(c, 2.0).Fz, 9700);
  EXPECT_EQ(stiffnessAt(c, 1.0).cornering, c.atNominal.cornering);
  // Sub-linear in the load (sin(2 atan(Fz / (PKY2 Fz0')))).
  EXPECT_LT(stiffnessAt(c, 2.0).cornering, 2 * stiffnessAt(c, 1.0).cornering);
}

// The Fiala tyre's stiffnesses at zero slip: exactly its parameters.
TEST(TyreCurvesFiala, StiffnessesAreItsParameters) {
  const tyre::FialaParams f = sedanFiala();
  for (double Fz : {2500.0, 4000.0}) {
    const TyreCurves c = tyreCurves(f, Fz, f.referenceFriction);
    EXPECT_EQ(c.model, "Fiala");
    EXPECT_NEAR(c.atNominal.cornering, f.corneringStiffness, 2e-6 * f.corneringStiffness);
    EXPECT_NEAR(c.atNominal.slip, f.slipStiffness, 1e-6 * f.slipStiffness);
    EXPECT_EQ(c.atNominal.corneringModel, f.corneringStiffness);
    EXPECT_EQ(c.atNominal.slipModel, f.slipStiffness);
    // Load-independent: the same at 2 x.
    EXPECT_NEAR(stiffnessAt(c, 2.0).cornering, f.corneringStiffness, 2e-6 * f.corneringStiffness);
  }
}

// The Fiala peaks in closed form, mu = mu0, a = u_max, d = u_max - u_min.
// Lateral (kappa = 0, t = tan alpha, x = C_alpha t / (3 Fz), U = a - d t,
// H = 1 - x / U): Fy / Fz = -U (1 - H^3) up to saturation. dH/dt = -a c / U^2
// with c = C_alpha / (3 Fz), so d(U (1 - H^3))/dt = 0 is
// 3 a c H^2 = d U (1 - H^3); with t and U in H, t = a (1 - H) / (c + d (1 - H)),
// U = a c / (c + d (1 - H)), this is the cubic -2 d H^3 + 3 (c + d) H^2 - d = 0
// (one root in (0, 1)), and the peak is U (1 - H^3).
// Longitudinal (alpha = 0): above kappa_c, Fx / Fz = U - U^2 b / kappa with
// b = Fz / (4 C_kappa), U = a - d kappa; its maximum is at
// kappa = a sqrt(b / (d (1 + b d))), the value U (1 - U b / kappa) there.
TEST(TyreCurvesFiala, PeaksInClosedForm) {
  const tyre::FialaParams f = sedanFiala();
  const double a = f.uMax, d = f.uMax - f.uMin;
  ASSERT_GT(d, 0);
  for (double Fz : {2500.0, 4000.0, 6000.0}) {
    const TyreCurves curves = tyreCurves(f, Fz, f.referenceFriction);
    const double c = f.corneringStiffness / (3 * Fz);
    double lo = 0, hi = 1;  // the cubic is -d < 0 at H = 0 and 3c > 0 at H = 1
    for (int i = 0; i < 200; ++i) {
      const double H = 0.5 * (lo + hi);
      (-2 * d * H * H * H + 3 * (c + d) * H * H - d < 0 ? lo : hi) = H;
    }
    const double H = 0.5 * (lo + hi);
    const double U = a * c / (c + d * (1 - H));
    const double muY = U * (1 - H * H * H);
    const double alphaY = std::atan(a * (1 - H) / (c + d * (1 - H)));
    for (int s = 0; s < 2; ++s) {
      const double side = s == 0 ? 1 : -1;
      EXPECT_NEAR(curves.lateral[s].mu, muY, 1e-9) << Fz;
      EXPECT_NEAR(curves.lateral[s].slip, side * alphaY, 1e-6) << Fz;
      EXPECT_LT(side * curves.lateral[s].value, 0) << "ISO: Fy opposes alpha";
    }
    // Below u_max (the brief's u_max mu / mu0 is only the bound: U falls with the slip).
    EXPECT_LT(muY, a);
    const double b = Fz / (4 * f.slipStiffness);
    const double kappaX = a * std::sqrt(b / (d * (1 + b * d)));
    const double Ux = a - d * kappaX;
    const double muX = Ux * (1 - Ux * b / kappaX);
    ASSERT_GT(kappaX, Ux * Fz / (2 * f.slipStiffness));  // past kappa_c
    for (int s = 0; s < 2; ++s) {
      const double side = s == 0 ? 1 : -1;
      EXPECT_NEAR(curves.longitudinal[s].mu, muX, 1e-9) << Fz;
      EXPECT_NEAR(curves.longitudinal[s].slip, side * kappaX, 1e-6) << Fz;
      EXPECT_GT(side * curves.longitudinal[s].value, 0);
    }
    // Aligning moment: positive for alpha > 0 (ISO, toward the velocity), odd.
    EXPECT_GT(curves.aligning[0].value, 0);
    EXPECT_NEAR(curves.aligning[1].value, -curves.aligning[0].value, 1e-9 * curves.aligning[0].value);
  }
}

// The wheels that share a tyre: the Fiala sedan has one for all four; a
// PAC2002 tyre mounted on the right is another tyre (mirrored coefficients).
TEST(TyreCurves, DistinctTyresOfAVehicle) {
  const vehicle::VehicleSpec fiala = vehicle::loadVehicleFile(kSource + "/assets/vehicles/sedan.toml");
  for (const vehicle::WheelSpec& w : fiala.wheels) EXPECT_TRUE(sameTyre(w.tyre, fiala.wheels[0].tyre)) << w.position;
  const vehicle::VehicleSpec pac = vehicle::loadVehicleFile(kSource + "/assets/vehicles/sedan_pac2002.toml");
  EXPECT_TRUE(sameTyre(pac.wheels[0].tyre, pac.wheels[2].tyre));
  EXPECT_FALSE(sameTyre(pac.wheels[0].tyre, pac.wheels[1].tyre));
  EXPECT_FALSE(sameTyre(pac.wheels[0].tyre, fiala.wheels[0].tyre));
}

}  // namespace
}  // namespace bdfcar::app
