#include "tyre/pac2002.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "portable_math.h"
#include "tyre/contact_geometry.h"

namespace bdfcar::tyre {

namespace {

constexpr double kPi = std::numbers::pi;
// Chrono9: the arguments of the sine laws, and the slip angle, held inside
// +-(pi/2 - 0.01) (tyre-pac2002.md 3.2, 3.3).
constexpr double kChronoClamp = kPi / 2 - 0.01;

double sgn(double x) { return (x > 0) - (x < 0); }

// D sin(C atan(B x - E (B x - atan(B x)))): the Magic Formula's sine law,
// with B x given (clamped by the caller where the variant does).
double sineLaw(double Bx, double C, double D, double E) {
  return D * pm::sin(C * pm::atan(Bx - E * (Bx - pm::atan(Bx))));
}

// cos(C atan(B x - E (B x - atan(B x)))): the trail's and the weighting functions' cosine law.
double cosineLaw(double Bx, double C, double E) { return pm::cos(C * pm::atan(Bx - E * (Bx - pm::atan(Bx)))); }

}  // namespace

Pac2002Coefficients mountedCoefficients(const Pac2002Params& p) {
  Pac2002Coefficients c = p.c;
  if (p.mountedLeft == p.measuredLeft) return c;
  // The coefficients of the terms odd in the slip angle and camber (Chrono's
  // list, tyre-pac2002.md 1.1): with them negated the tyre is the mirror
  // image of the one measured, Fy(alpha, gamma) -> -Fy(-alpha, -gamma).
  for (double* x : {&c.RHX1, &c.QSX1, &c.PEY3, &c.PHY1, &c.PHY2, &c.PVY1, &c.PVY2, &c.RBY3, &c.RVY1, &c.RVY2, &c.QBZ4,
                    &c.QDZ3, &c.QDZ6, &c.QDZ7, &c.QEZ4, &c.QHZ1, &c.QHZ2, &c.SSZ1})
    *x = -*x;
  return c;
}

MagicFormulaForces magicFormula(const Pac2002Params& p, double kappa, double alpha, double gamma, double Fz, double mu,
                                double vx) {
  const Pac2002Coefficients& c = p.c;
  const bool chrono = p.variant == Pac2002Variant::Chrono9;
  const double eps = chrono ? 0.1 : 1e-6;  // in B = K / (C D + eps)
  auto held = [&](double x) { return chrono ? std::clamp(x, -kChronoClamp, kChronoClamp) : x; };
  auto peak = [&](double x) { return chrono ? std::abs(x) : x; };  // Chrono takes |mu| (and |Bt|)
  MagicFormulaForces out;
  const double Fz0 = p.nominalLoad * c.LFZO;  // Fz0', the scaled nominal load
  const double dfz = (Fz - Fz0) / Fz0;
  const double muRoad = std::clamp(mu, 0.1, 1.0) / p.referenceFriction;

  // Pure longitudinal slip (4.E9-4.E18).
  const double gx = gamma * c.LGAX;
  const double SHx = (c.PHX1 + c.PHX2 * dfz) * c.LHX;
  const double kx = kappa + SHx;
  const double Cx = c.PCX1 * c.LCX;
  const double mux = peak(muRoad * (c.PDX1 + c.PDX2 * dfz) * (chrono ? 1.0 : 1.0 - c.PDX3 * gx * gx) * c.LMUX);
  const double Dx = mux * Fz;
  const double Ex = std::min(1.0, (c.PEX1 + c.PEX2 * dfz + c.PEX3 * dfz * dfz) * (1.0 - c.PEX4 * sgn(kx)) * c.LEX);
  const double Kx = Fz * (c.PKX1 + c.PKX2 * dfz) * pm::exp(c.PKX3 * dfz) * c.LKX;
  const double Bx = Kx / (Cx * Dx + eps);
  const double SVx = Fz * (c.PVX1 + c.PVX2 * dfz) * c.LVX * c.LMUX;
  const double Fx0 = sineLaw(held(Bx * kx), Cx, Dx, Ex) + SVx;

  // Pure lateral slip (4.E19-4.E30). Chrono9 scales Ky by LMUY where the textbook has LKY.
  const double gy = gamma * c.LGAY;
  const double SHy = (c.PHY1 + c.PHY2 * dfz) * c.LHY + c.PHY3 * gy;
  const double ay = alpha + SHy;
  const double Cy = c.PCY1 * c.LCY;
  const double muy = peak(muRoad * (c.PDY1 + c.PDY2 * dfz) * (1.0 - c.PDY3 * gy * gy) * c.LMUY);
  const double Dy = muy * Fz;
  const double Ey = std::min(1.0, (c.PEY1 + c.PEY2 * dfz) * (1.0 - (c.PEY3 + c.PEY4 * gy) * sgn(ay)) * c.LEY);
  const double Ky = c.PKY1 * Fz0 * pm::sin(2.0 * pm::atan(Fz / (c.PKY2 * Fz0))) * (1.0 - c.PKY3 * std::abs(gy)) *
                    (chrono ? c.LMUY : c.LKY);
  const double By = Ky / (Cy * Dy + eps);
  const double SVy = Fz * ((c.PVY1 + c.PVY2 * dfz) * c.LVY + (c.PVY3 + c.PVY4 * dfz) * gy) * c.LMUY;
  const double Fy0 = sineLaw(held(By * ay), Cy, Dy, Ey) + SVy;

  // Pure aligning moment (4.E31-4.E49): trail t and residual moment Mzr.
  const double gz = gamma * c.LGAZ;
  const double SHt = c.QHZ1 + c.QHZ2 * dfz + (c.QHZ3 + c.QHZ4 * dfz) * gz;
  const double at = alpha + SHt;
  const double ar = alpha + SHy + SVy / Ky;
  const double Bt =
      peak((c.QBZ1 + c.QBZ2 * dfz + c.QBZ3 * dfz * dfz) * (1.0 + c.QBZ4 * gz + c.QBZ5 * std::abs(gz)) * c.LKY / c.LMUY);
  const double Ct = c.QCZ1;
  const double Dt = Fz * (c.QDZ1 + c.QDZ2 * dfz) * (1.0 + c.QDZ3 * gz + c.QDZ4 * gz * gz) * (p.unloadedRadius / Fz0) *
                    c.LTR;
  const double Et = std::min(
      1.0, (c.QEZ1 + c.QEZ2 * dfz + c.QEZ3 * dfz * dfz) * (1.0 + (c.QEZ4 + c.QEZ5 * gz) * (2.0 / kPi) * pm::atan(Bt * Ct * at)));
  const double Br = c.QBZ9 * c.LKY / c.LMUY + c.QBZ10 * By * Cy;
  const double Dr = Fz * ((c.QDZ6 + c.QDZ7 * dfz) * c.LRES + (c.QDZ8 + c.QDZ9 * dfz) * gz) * p.unloadedRadius * c.LMUY;
  const double cosAlpha = pm::cos(alpha);
  auto trail = [&](double a) { return Dt * cosineLaw(Bt * a, Ct, Et) * cosAlpha; };
  auto residualMoment = [&](double a) { return Dr * pm::cos(pm::atan(Br * a)) * cosAlpha; };

  if (!p.combined) {
    out.Fx = Fx0;
    out.Fy = Fy0;
    out.Mz = -trail(at) * Fy0 + residualMoment(ar);
  } else if (p.ellipse) {
    // Chrono's friction ellipse (tyre-pac2002.md 3.5), in its finite form.
    const double kc = kappa + SHx + SVx / Kx;
    const double sa = pm::sin(alpha + SHy + SVy / Ky);
    const double muxAct = std::abs(Fx0 - SVx) / Fz, muyAct = std::abs(Fy0 - SVy) / Fz;
    const double muxMax = Dx / Fz, muyMax = Dy / Fz;
    const double nx = std::hypot(muyMax * kc, muxAct * sa), ny = std::hypot(muxMax * sa, muyAct * kc);
    out.Fx = nx > 0 ? Fx0 * muyMax * std::abs(kc) / nx : Fx0;
    out.Fy = ny > 0 ? Fy0 * muxMax * std::abs(sa) / ny : Fy0;
    out.Mz = -trail(at) * out.Fy + residualMoment(ar);
  } else {
    // The PAC2002 weighting functions (4.E50-4.E78).
    const double SHxa = c.RHX1, aS = alpha + SHxa;
    const double Bxa = peak(c.RBX1 * pm::cos(pm::atan(c.RBX2 * kappa)) * c.LXAL);
    const double Cxa = c.RCX1, Exa = std::min(1.0, c.REX1 + c.REX2 * dfz);
    const double Gxa = cosineLaw(Bxa * aS, Cxa, Exa) / cosineLaw(Bxa * SHxa, Cxa, Exa);
    out.Fx = Gxa * Fx0;
    const double SHyk = c.RHY1 + c.RHY2 * dfz, kS = kappa + SHyk;
    const double Byk = peak(c.RBY1 * pm::cos(pm::atan(c.RBY2 * (alpha - c.RBY3))) * c.LYKA);
    const double Cyk = c.RCY1, Eyk = std::min(1.0, c.REY1 + c.REY2 * dfz);
    const double DVyk = muy * Fz * (c.RVY1 + c.RVY2 * dfz + c.RVY3 * gamma) * pm::cos(pm::atan(c.RVY4 * alpha));
    const double SVyk = DVyk * pm::sin(c.RVY5 * pm::atan(c.RVY6 * kappa)) * c.LVYKA;
    const double Gyk = cosineLaw(Byk * kS, Cyk, Eyk) / cosineLaw(Byk * SHyk, Cyk, Eyk);
    out.Fy = Gyk * Fy0 + SVyk;
    // Equivalent slip angles for the trail and the residual moment (Chrono signs the first with kappa).
    const double r = Kx / Ky * kappa;
    const double atEq = pm::atan(std::sqrt(pm::tan(at) * pm::tan(at) + r * r)) * (chrono ? sgn(kappa) : sgn(at));
    const double arEq = pm::atan(std::sqrt(pm::tan(ar) * pm::tan(ar) + r * r)) * sgn(ar);
    const double s = (c.SSZ1 + c.SSZ2 * out.Fy / Fz0 + (c.SSZ3 + c.SSZ4 * dfz) * gamma) * p.unloadedRadius * c.LS;
    out.Mz = -trail(atEq) * (out.Fy - SVyk) + residualMoment(arEq) + s * out.Fx;
  }

  // Overturning and rolling-resistance moments (4.E69, 4.E70); Chrono9
  // zeroes QSY1 and QSY2 (its reader's bug, tyre-pac2002.md 1.3). My opposes
  // the rolling, its sign smooth below 0.5 m/s.
  out.Mx = p.unloadedRadius * Fz * (c.QSX1 * c.LVMX - c.QSX2 * gamma + c.QSX3 * out.Fy / Fz0) * c.LMX;
  const double v = vx / p.longvl;
  const double rolling = (chrono ? 0.0 : c.QSY1 + c.QSY2 * out.Fx / Fz0) + c.QSY3 * std::abs(v) + c.QSY4 * v * v * v * v;
  out.My = -p.unloadedRadius * Fz * rolling * c.LMY * pm::tanh(vx / 0.5);
  out.Kx = Kx;
  out.Ky = Ky;
  out.Dx = Dx;
  out.Dy = Dy;
  return out;
}

double pac2002PeakFriction(const Pac2002Params& p, double mu) {
  // The D factors over the load (their closed form: no Magic Formula
  // evaluation; `auto`'s policy asks it of every wheel at every tick), the
  // largest at a quarter to twice the nominal load, scaled as the peak
  // factors are by the road's friction over the file's reference.
  const Pac2002Coefficients& c = p.c;
  const double Fz0 = p.nominalLoad * c.LFZO;
  double best = 0;
  for (double share : {0.25, 0.5, 1.0, 2.0}) {
    const double dfz = (share * p.nominalLoad - Fz0) / Fz0;
    best = std::max({best, std::abs((c.PDX1 + c.PDX2 * dfz) * c.LMUX), std::abs((c.PDY1 + c.PDY2 * dfz) * c.LMUY)});
  }
  return best * std::clamp(mu, 0.1, 1.0) / p.referenceFriction;
}

Pac2002Tyre::Pac2002Tyre(const Pac2002Params& p) : p_(p) {
  p_.c = mountedCoefficients(p);
  p_.measuredLeft = p_.mountedLeft;  // mirrored once, here
}

void Pac2002Tyre::evaluate(const WheelKinematics& w, const ContactPlane& g, const SlipState& prevIn, double h,
                                 std::optional<double> load, TyreOutput& out) const {
  // Every field written: the caller's output from an earlier evaluation is
  // overwritten as a whole (the slips copied first: they may be the caller's).
  const SlipState prev = prevIn;
  out = TyreOutput{};
  out.slipState = prev;
  const std::optional<ContactGeometry> geo = contactGeometry(w, g, p_.unloadedRadius);
  if (!geo) {
    out.slipState = SlipState{};
    return;
  }
  const Pac2002Coefficients& c = p_.c;
  const bool chrono = p_.variant == Pac2002Variant::Chrono9;
  const double Cz = p_.verticalStiffness * c.LCZ;
  double delta = geo->delta;
  const double raw = load ? *load : Cz * delta - p_.verticalDamping * geo->vz;
  const std::optional<double> Fzo = smoothedLoad(raw, delta, load.has_value());
  if (!Fzo) {
    out.slipState = SlipState{};
    return;
  }
  const double Fz = *Fzo;
  if (load) delta = Fz / Cz;

  // Effective rolling radius: the MF law when the file has it (textbook), else R0 - delta / 3.
  const double R0 = p_.unloadedRadius;
  double Reff = R0 - delta / 3.0;
  if (!chrono && (p_.breff != 0 || p_.dreff != 0 || p_.freff != 0)) {
    const double rho = delta * Cz / p_.nominalLoad;
    Reff = R0 - p_.nominalLoad / Cz * (p_.dreff * pm::atan(p_.breff * rho) + p_.freff * rho);
  }
  const double vx = geo->vx, vy = geo->vy;
  const double vsx = vx - w.spinRate * Reff, vsy = vy;
  const double absVx = std::abs(vx);
  // Chrono9 softens every slip by 0.1 m/s (tyre-pac2002.md 2.2).
  const double soft = chrono ? 0.1 : 0.0;

  // Slips (ISO: kappa driving > 0, tan(alpha) = v_y / |v_x|): exact above
  // the low-speed range, transient below, blended in between.
  const double beta = exactSlipWeight(p_.lowSpeed, absVx);
  double kappa, tanAlpha;
  SlipState next = prev;
  if (beta < 1.0) {
    // Relaxation lengths (the file's, textbook: 4.E79, 4.E80) and the slips
    // where the force laws peak (the transient slips' bounds).
    const double Fz0 = p_.nominalLoad * c.LFZO, dfz = (Fz - Fz0) / Fz0;
    double sx = p_.lowSpeed.relaxationLengthX, sy = p_.lowSpeed.relaxationLengthY;
    if (!chrono && c.PTX1 > 0 && c.PTY1 > 0) {
      sx = Fz * (c.PTX1 + c.PTX2 * dfz) * pm::exp(-c.PTX3 * dfz) * (R0 / Fz0) * c.LSGKP;
      sy = c.PTY1 * pm::sin(2.0 * pm::atan(Fz / (c.PTY2 * Fz0))) * R0 * c.LFZO * c.LSGAL;
    }
    const MagicFormulaForces at0 = magicFormula(p_, 0.0, 0.0, 0.0, Fz, g.friction);
    const double Cx = c.PCX1 * c.LCX, Cy = c.PCY1 * c.LCY;
    auto peakSlip = [&](double K, double C, double D) {
      const double B = std::abs(K) / (C * D + 1e-6);
      return C > 1.0 && B > 0 ? std::min(p_.lowSpeed.maxTransientSlip, pm::tan(kPi / (2.0 * C)) / B)
                              : p_.lowSpeed.maxTransientSlip;
    };
    const BlendedSlips s = lowSpeedSlips(p_.lowSpeed, beta, vsx, vsy, absVx, prev, h, std::max(0.01, sx),
                                         std::max(0.01, sy), peakSlip(at0.Kx, Cx, at0.Dx),
                                         peakSlip(at0.Ky, Cy, at0.Dy), std::max(at0.Kx, 1.0),
                                         std::max(std::abs(at0.Ky), 1.0), std::max(absVx, p_.lowSpeed.blend0) + soft);
    kappa = s.kappa;
    tanAlpha = s.tanAlpha;
    next = s.next;
  } else {
    kappa = -vsx / (absVx + soft);
    tanAlpha = vsy / (absVx + soft);
    next.active = false;
  }

  MagicFormulaForces f;
  double Fy, Mz, My, gamma = 0;
  if (chrono) {
    // Its internal slip angle alpha_c = -alpha_ISO, clamps, no camber, and
    // its outputs back into the contact frame: (Fx, -Fy), (Mx, -My, -Mz).
    kappa = std::clamp(kappa, -1.0, 1.0);
    const double alphaC = std::clamp(-pm::atan(tanAlpha), -kChronoClamp, kChronoClamp);
    f = magicFormula(p_, kappa, alphaC, 0.0, Fz, g.friction, vx);
    Fy = -f.Fy;
    Mz = -f.Mz;
    My = -f.My;
  } else {
    // Camber (ISO: + with the wheel's top leaning to the right of its heading).
    gamma = pm::atan2(w.spinAxis.dot(g.normal), w.spinAxis.dot(geo->yc));
    f = magicFormula(p_, kappa, pm::atan(tanAlpha), gamma, Fz, g.friction, vx);
    Fy = f.Fy;
    Mz = f.Mz;
    My = f.My;
  }

  out.inContact = true;
  out.deflection = delta;
  out.contactPoint = w.centre + (R0 - delta) * geo->down;
  // Chrono applies the force delta above the contact point (as its Fiala tyre); the textbook at it.
  out.point = chrono ? out.contactPoint + delta * g.normal : out.contactPoint;
  out.force = f.Fx * geo->xc + Fy * geo->yc + Fz * g.normal;
  out.moment = f.Mx * geo->xc + My * geo->yc + Mz * g.normal;
  out.Fx = f.Fx;
  out.Fy = Fy;
  out.Fz = Fz;
  out.My = My;
  out.Mz = Mz;
  out.kappa = kappa;
  out.tanAlpha = tanAlpha;
  out.vx = vx;
  out.vsx = vsx;
  out.vsy = vsy;
  out.slipState = next;
  return;
}

}  // namespace bdfcar::tyre
