// The Magic Formula tyre (physics/tyre/pac2002.h) against what does not
// come from its code:
//  - the chrono9 evaluation against the check values of
//    ../shared/reference/tyre-pac2002.md section 5 (an independent
//    transcription of Chrono 9.0.1's ChPac02Tire), within 0.1 %;
//  - the textbook evaluation against the same values where the two
//    evaluations are the same equations (pure slip, small slips: no clamp,
//    the 0.1 N in B negligible), and against limits that hold in closed
//    form: cornering and slip stiffness = B C D at zero slip, peak = D,
//    odd symmetry with the offsets zeroed, a camber shift that is a slip
//    angle shift, the combined-slip weighting cos(C atan(B alpha));
//  - the .tir reader: the shipped file, CRLF, and bad files named by file,
//    line and key.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>

#include "tyre/pac2002.h"
#include "tyre/pac2002_file.h"
#include "tyre/tir_file.h"

namespace bdfcar::tyre {
namespace {

const std::string kTir = std::string(BDFCAR_SOURCE_DIR) + "/assets/tyres/Sedan_Pac02Tire.tir";
constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kFnom = 4850.0;

Pac2002Params sedan(Pac2002Variant v) { return readPac2002(kTir, v).params; }

// Within 0.1 % of the check value (the spec's values carry 5-6 digits).
void near(double got, double want, const char* what, double rel = 1e-3) {
  EXPECT_NEAR(got, want, rel * std::abs(want)) << what;
}

TEST(Pac2002Chrono9, IntermediatesAtTheNominalLoad) {
  const Pac2002Params p = sedan(Pac2002Variant::Chrono9);
  const MagicFormulaForces f = magicFormula(p, 0.0, 0.0, 0.0, kFnom, 0.8);
  near(f.Kx, 114283.48, "Kx");
  near(f.Dx, 5506.897, "Dx");
  near(f.Ky, -76958.99, "Ky");
  near(f.Dy, 4882.012, "Dy");
}

TEST(Pac2002Chrono9, LateralAndLongitudinalSweeps) {
  Pac2002Params pure = sedan(Pac2002Variant::Chrono9);
  pure.combined = false;
  const Pac2002Params mode4 = sedan(Pac2002Variant::Chrono9);
  ASSERT_TRUE(mode4.combined && mode4.ellipse);
  struct Row {
    double alphaDeg, Fy0, Mz0, Fy, Fx, Mz;
  };
  // tyre-pac2002.md 5.2, kappa = 0.
  for (const Row& r : {Row{1, -1331.26, 40.312, -1330.99, 140.18, 40.302}, Row{2, -2429.41, 72.922, -2429.03, 117.09, 72.909},
                       Row{4, -3828.81, 79.002, -3828.45, 79.01, 78.993}, Row{8, -4617.42, 18.328, -4617.26, 44.48, 18.328},
                       Row{-1, 1283.48, -58.354, 1283.32, 141.32, -58.348}, Row{-2, 2441.82, -96.847, 2441.51, 118.42, -96.836},
                       Row{-4, 3961.58, -114.274, 3961.24, 79.82, -114.265}, Row{-8, 4915.27, -50.262, 4915.10, 44.76, -50.260}}) {
    const MagicFormulaForces a = magicFormula(pure, 0.0, r.alphaDeg * kDeg, 0.0, kFnom, 0.8);
    const MagicFormulaForces b = magicFormula(mode4, 0.0, r.alphaDeg * kDeg, 0.0, kFnom, 0.8);
    SCOPED_TRACE("alpha_c = " + std::to_string(r.alphaDeg) + " deg");
    near(a.Fy, r.Fy0, "Fy0");
    near(a.Mz, r.Mz0, "Mz0");
    near(b.Fy, r.Fy, "Fy mode 4");
    near(b.Fx, r.Fx, "Fx mode 4");
    near(b.Mz, r.Mz, "Mz mode 4");
  }
  struct Col {
    double kappa, Fx0, Fx, Fy;
  };
  // alpha_c = 0.
  for (const Col& c : {Col{0.02, 2282.26, 2282.12, -19.738}, Col{0.05, 4311.88, 4311.73, -9.323},
                       Col{0.10, 5379.95, 5379.88, -4.834}, Col{0.20, 5484.55, 5484.53, -2.448},
                       Col{-0.02, -2027.23, -2027.11, -21.666}, Col{-0.05, -4190.76, -4190.60, -9.800},
                       Col{-0.10, -5358.80, -5358.72, -4.962}, Col{-0.20, -5484.60, -5484.58, -2.480}}) {
    SCOPED_TRACE("kappa = " + std::to_string(c.kappa));
    near(magicFormula(pure, c.kappa, 0.0, 0.0, kFnom, 0.8).Fx, c.Fx0, "Fx0");
    const MagicFormulaForces b = magicFormula(mode4, c.kappa, 0.0, 0.0, kFnom, 0.8);
    near(b.Fx, c.Fx, "Fx mode 4");
    near(b.Fy, c.Fy, "Fy mode 4");
  }
  // At zero slip: the offsets.
  const MagicFormulaForces z0 = magicFormula(pure, 0, 0, 0, kFnom, 0.8), z4 = magicFormula(mode4, 0, 0, 0, kFnom, 0.8);
  near(z0.Fx, 152.045, "Fx0(0, 0)");
  near(z0.Fy, -37.763, "Fy0(0, 0)");
  near(z0.Mz, -7.8022, "Mz0(0, 0)");
  near(z4.Fx, 152.035, "Fx mode 4 (0, 0)");
  near(z4.Fy, -37.569, "Fy mode 4 (0, 0)");
  near(z4.Mz, -7.8097, "Mz mode 4 (0, 0)");
}

TEST(Pac2002Chrono9, CombinedSlipAndOtherLoads) {
  const Pac2002Params p = sedan(Pac2002Variant::Chrono9);
  struct Row {
    double kappa, alphaDeg, Fx, Fy, Mz;
  };
  // tyre-pac2002.md 5.4 (the friction ellipse).
  for (const Row& r : {Row{0.05, 4, 2748.60, -3382.27, 68.877}, Row{-0.05, 4, -2632.05, -3420.43, 69.742},
                       Row{0.05, -4, 2771.54, 3528.69, -102.644}, Row{0.10, 8, 2958.48, -3905.53, 14.623}}) {
    SCOPED_TRACE("kappa " + std::to_string(r.kappa) + ", alpha_c " + std::to_string(r.alphaDeg) + " deg");
    const MagicFormulaForces f = magicFormula(p, r.kappa, r.alphaDeg * kDeg, 0.0, kFnom, 0.8);
    near(f.Fx, r.Fx, "Fx");
    near(f.Fy, r.Fy, "Fy");
    near(f.Mz, r.Mz, "Mz");
  }
  // 5.6: Ky, pure Fy0 and Mz0 at 2 and 4 deg, Fx0 at kappa 0.05, mode 4 at (0.05, 4 deg).
  Pac2002Params pure = p;
  pure.combined = false;
  struct Load {
    double Fz, Ky, Fy2, Fy4, Mz2, Mz4, Fx05, Fx, Fy, Mz;
  };
  for (const Load& l : {Load{3000, -57367.0, -1769.47, -2684.30, 30.020, 28.860, 2588.10, 1752.00, -2341.90, 24.289},
                        Load{3928.5, -68865.4, -2148.01, -3315.44, 50.625, 51.575, 3451.13, 2265.30, -2908.65, 44.299},
                        Load{6300, -84043.4, -2701.08, -4409.97, 108.273, 129.508, 5631.79, 3441.40, -3945.37, 115.166}}) {
    SCOPED_TRACE("Fz = " + std::to_string(l.Fz));
    near(magicFormula(pure, 0, 0, 0, l.Fz, 0.8).Ky, l.Ky, "Ky");
    near(magicFormula(pure, 0, 2 * kDeg, 0, l.Fz, 0.8).Fy, l.Fy2, "Fy0(2 deg)");
    near(magicFormula(pure, 0, 4 * kDeg, 0, l.Fz, 0.8).Fy, l.Fy4, "Fy0(4 deg)");
    near(magicFormula(pure, 0, 2 * kDeg, 0, l.Fz, 0.8).Mz, l.Mz2, "Mz0(2 deg)");
    near(magicFormula(pure, 0, 4 * kDeg, 0, l.Fz, 0.8).Mz, l.Mz4, "Mz0(4 deg)");
    near(magicFormula(pure, 0.05, 0, 0, l.Fz, 0.8).Fx, l.Fx05, "Fx0(0.05)");
    const MagicFormulaForces c = magicFormula(p, 0.05, 4 * kDeg, 0, l.Fz, 0.8);
    near(c.Fx, l.Fx, "Fx mode 4");
    near(c.Fy, l.Fy, "Fy mode 4");
    near(c.Mz, l.Mz, "Mz mode 4");
  }
}

// The whole tyre: the contact's normal load (5.6) and the output frame
// (2.3): a left tyre sliding to the right (v_y < 0) is pushed left, and its
// moment turns it toward its velocity; the right tyre is its mirror image.
TEST(Pac2002Chrono9, NormalLoadAndTheContactFrame) {
  Pac2002Params p = sedan(Pac2002Variant::Chrono9);
  const Pac2002Tyre left(p);
  WheelKinematics w;
  ContactPlane g;
  g.valid = true;
  w.centre = Vec3(0, 0, 0.344 - 0.02);
  w.spinAxis = Vec3::UnitY();
  TyreOutput o = left.evaluate(w, g, {}, 0.01);
  near(o.Fz, 5616.71, "Fz at 20 mm");
  w.centreVelocity = Vec3(0, 0, -0.1);
  near(left.evaluate(w, g, {}, 0.01).Fz, 5816.71, "Fz at 20 mm, closing at 0.1 m/s");
  w.centreVelocity = Vec3(22.0, -22.0 * std::tan(2 * kDeg), 0.0);
  const double Reff = 0.344 - 0.02 / 3.0;
  w.spinRate = 22.0 / Reff;  // free rolling: kappa = 0
  o = left.evaluate(w, g, {}, 0.01);
  EXPECT_GT(o.Fy, 0);
  EXPECT_LT(o.Mz, 0);
  p.mountedLeft = false;
  const Pac2002Tyre right(p);
  WheelKinematics m = w;
  m.centreVelocity.y() = -w.centreVelocity.y();  // the mirror image of the left tyre's motion
  const TyreOutput r = right.evaluate(m, g, {}, 0.01);
  EXPECT_NEAR(r.Fy, -o.Fy, 1e-9 * std::abs(o.Fy));
  EXPECT_NEAR(r.Mz, -o.Mz, 1e-9 * std::abs(o.Mz));
  EXPECT_NEAR(r.Fx, o.Fx, 1e-9 * std::abs(o.Fx));
}

// The peak friction the fidelity policy reads (in closed form) is the
// largest D / Fz the Magic Formula itself gives over the loads it names,
// scaled by the road's friction.
TEST(Pac2002Textbook, PeakFrictionIsTheFormulasPeakFactor) {
  const Pac2002Params p = sedan(Pac2002Variant::Textbook);
  for (double mu : {0.3, 0.8}) {
    double best = 0;
    for (double share : {0.25, 0.5, 1.0, 2.0}) {
      const MagicFormulaForces f = magicFormula(p, 0, 0, 0, share * kFnom, mu);
      best = std::max({best, f.Dx / (share * kFnom), f.Dy / (share * kFnom)});
    }
    EXPECT_NEAR(pac2002PeakFriction(p, mu), best, 1e-12) << "mu " << mu;
  }
}

// Where the textbook and Chrono's evaluation are one set of equations
// (pure slip, small slips, left tyre, no camber), the textbook meets the
// same check values.
TEST(Pac2002Textbook, PureSlipMeetsTheIndependentValues) {
  Pac2002Params p = sedan(Pac2002Variant::Textbook);
  p.combined = false;
  near(magicFormula(p, 0, 2 * kDeg, 0, kFnom, 0.8).Fy, -2429.41, "Fy0(2 deg)");
  near(magicFormula(p, 0, -4 * kDeg, 0, kFnom, 0.8).Fy, 3961.58, "Fy0(-4 deg)");
  near(magicFormula(p, 0, 2 * kDeg, 0, kFnom, 0.8).Mz, 72.922, "Mz0(2 deg)");
  near(magicFormula(p, 0.05, 0, 0, kFnom, 0.8).Fx, 4311.88, "Fx0(0.05)");
  near(magicFormula(p, -0.02, 0, 0, kFnom, 0.8).Fx, -2027.23, "Fx0(-0.02)");
}

// The file's data with every offset zeroed: the curves are odd, their
// slopes at zero are B C D, their peaks D (E <= 1, the textbook has no clamp).
TEST(Pac2002Textbook, ClosedFormLimitsWithTheOffsetsZeroed) {
  Pac2002Params p = sedan(Pac2002Variant::Textbook);
  p.combined = false;
  Pac2002Coefficients& c = p.c;
  c.PHX1 = c.PHX2 = c.PVX1 = c.PVX2 = c.PHY1 = c.PHY2 = c.PVY1 = c.PVY2 = 0;
  c.PEX4 = c.PEY3 = 0;  // the curvature's sign dependence
  for (double Fz : {3000.0, kFnom, 6300.0}) {
    SCOPED_TRACE("Fz = " + std::to_string(Fz));
    const MagicFormulaForces at0 = magicFormula(p, 0, 0, 0, Fz, 0.8);
    const double h = 1e-7;
    const double Ky = (magicFormula(p, 0, h, 0, Fz, 0.8).Fy - magicFormula(p, 0, -h, 0, Fz, 0.8).Fy) / (2 * h);
    const double Kx = (magicFormula(p, h, 0, 0, Fz, 0.8).Fx - magicFormula(p, -h, 0, 0, Fz, 0.8).Fx) / (2 * h);
    near(Ky, at0.Ky, "dFy/dalpha = By Cy Dy = Ky", 1e-6);
    near(Kx, at0.Kx, "dFx/dkappa = Bx Cx Dx = Kx", 1e-6);
    double peakY = 0, peakX = 0;
    for (int i = 1; i <= 40000; ++i) {
      peakY = std::max(peakY, std::abs(magicFormula(p, 0, i * 1e-5, 0, Fz, 0.8).Fy));
      peakX = std::max(peakX, std::abs(magicFormula(p, i * 1e-5, 0, 0, Fz, 0.8).Fx));
    }
    near(peakY, at0.Dy, "max |Fy| = Dy", 1e-6);
    near(peakX, at0.Dx, "max |Fx| = Dx", 1e-6);
    for (double s : {0.01, 0.05, 0.2}) {
      EXPECT_NEAR(magicFormula(p, 0, -s, 0, Fz, 0.8).Fy, -magicFormula(p, 0, s, 0, Fz, 0.8).Fy, 1e-9 * Fz);
      EXPECT_NEAR(magicFormula(p, -s, 0, 0, Fz, 0.8).Fx, -magicFormula(p, s, 0, 0, Fz, 0.8).Fx, 1e-9 * Fz);
    }
  }
}

// Camber through PHY3 alone is a shift of the slip angle; the combined-slip
// weighting with E = 0 and no shift is cos(C atan(B alpha)) of the pure force.
TEST(Pac2002Textbook, CamberShiftAndCombinedWeightingInClosedForm) {
  Pac2002Params p = sedan(Pac2002Variant::Textbook);
  p.combined = false;
  Pac2002Coefficients& c = p.c;
  c.PDY3 = c.PEY4 = c.PKY3 = c.PVY3 = c.PVY4 = 0;  // camber only through PHY3
  const double gamma = 0.03;
  for (double a : {-0.05, 0.01, 0.08})
    EXPECT_NEAR(magicFormula(p, 0, a, gamma, kFnom, 0.8).Fy, magicFormula(p, 0, a + c.PHY3 * gamma, 0, kFnom, 0.8).Fy,
                1e-9 * kFnom);
  Pac2002Params w = sedan(Pac2002Variant::Textbook);
  ASSERT_TRUE(w.combined && !w.ellipse);
  w.c.RBX1 = 13.0;
  w.c.RCX1 = 1.1;
  w.c.RBY1 = 10.0;
  w.c.RCY1 = 1.05;
  Pac2002Params wPure = w;
  wPure.combined = false;
  for (double a : {0.02, -0.06})
    for (double k : {0.03, -0.08}) {
      const double gx = std::cos(1.1 * std::atan(13.0 * a));  // RBX2 = 0: B = RBX1; RHX1 = REX = 0
      EXPECT_NEAR(magicFormula(w, k, a, 0, kFnom, 0.8).Fx, gx * magicFormula(wPure, k, a, 0, kFnom, 0.8).Fx, 1e-9 * kFnom);
      const double kS = k + w.c.RHY1;  // 0
      const double gy = std::cos(1.05 * std::atan(10.0 * kS));
      EXPECT_NEAR(magicFormula(w, k, a, 0, kFnom, 0.8).Fy, gy * magicFormula(wPure, k, a, 0, kFnom, 0.8).Fy, 1e-9 * kFnom);
    }
}

TEST(TirFile, TheShippedFileAndCrLf) {
  const TirFile f = TirFile::read(kTir);
  EXPECT_EQ(f.word("MODEL", "PROPERTY_FILE_FORMAT", ""), "PAC2002");
  EXPECT_EQ(f.number("DIMENSION", "UNLOADED_RADIUS"), 0.344);
  EXPECT_EQ(f.number("LONGITUDINAL_COEFFICIENTS", "PEX4"), -3.7604e-5);  // "-3.7604e-005"
  const TirFile crlf = TirFile::parse("[UNITS]\r\nLENGTH = 'mm'\r\n[DIMENSION]\r\nUNLOADED_RADIUS = 344 $ r\r\n", "x.tir");
  EXPECT_DOUBLE_EQ(crlf.number("DIMENSION", "UNLOADED_RADIUS") * crlf.unitFactor("LENGTH"), 0.344);
}

// A bad file is named by file, line and key.
void expectError(const std::string& text, const std::string& message) {
  try {
    (void)readPac2002(TirFile::parse(text, "bad.tir"), Pac2002Variant::Textbook);
    ADD_FAILURE() << "accepted: " << text;
  } catch (const TirError& e) {
    EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
  }
}

TEST(TirFile, BadFilesNameTheLineAndKey) {
  std::string good;
  {
    std::ifstream in(kTir);
    good.assign(std::istreambuf_iterator<char>(in), {});
  }
  auto with = [&](const std::string& from, const std::string& to) {
    std::string s = good;
    const auto at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return s.replace(at, from.size(), to);
  };
  expectError(with("[VERTICAL]", "[VERTICAL_X]"), "key 'VERTICAL_STIFFNESS' in [VERTICAL]: missing, and so is its section");
  expectError(with("PDY1                     = 1.0489", "PDY1 = one"), "key 'PDY1' in [LATERAL_COEFFICIENTS]: expected a finite number, got 'one'");
  expectError(with("'PAC2002'", "'MF_61'"), "bad.tir:12: key 'PROPERTY_FILE_FORMAT' in [MODEL]: unknown tyre model type 'MF_61'");
  expectError(with("PDX1                     = 1.1739", "PDX1 = -1.1739"), "key 'PDX1' in [LONGITUDINAL_COEFFICIENTS]: expected a positive peak factor");
  expectError(with("USE_MODE                 = 4", "USE_MODE = 2"), "key 'USE_MODE' in [MODEL]: USE_MODE 2 is not evaluated");
  expectError(with("LENGTH                   ='meter'", "LENGTH = 'furlong'"), "bad.tir:5: key 'LENGTH' in [UNITS]: unknown unit 'furlong'");
  expectError(with("PKY1                     = -21.92", "PKY1 = 21.92"), "expected a negative cornering stiffness factor");
  // Coefficients that pass every single check but overflow together: the sampled curves are refused.
  expectError(with("PKX3                     = 0.21253", "PKX3 = 800"), "the coefficients give a non-finite force at Fz = ");
}

}  // namespace
}  // namespace bdfcar::tyre
