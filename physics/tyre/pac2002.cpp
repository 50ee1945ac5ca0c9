#include "tyre/pac2002.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "autodiff.h"
#include "portable_math.h"
#include "tyre/contact_geometry.h"

namespace bdfcar::tyre {

namespace {

constexpr double kPi = std::numbers::pi;
// Chrono9: the arguments of the sine laws, and the slip angle, held inside
// +-(pi/2 - 0.01) (tyre-pac2002.md 3.2, 3.3).
constexpr double kChronoClamp = kPi / 2 - 0.01;

// D sin(C atan(B x - E (B x - atan(B x)))): the Magic Formula's sine law,
// with B x given (clamped by the caller where the variant does).
template <typename T>
T sineLaw(const T& Bx, const T& C, const T& D, const T& E) {
  return D * pm::sin(T(C * pm::atan(T(Bx - E * (Bx - pm::atan(Bx))))));
}

// cos(C atan(B x - E (B x - atan(B x)))): the trail's and the weighting functions' cosine law.
template <typename T>
T cosineLaw(const T& Bx, const T& C, const T& E) {
  return pm::cos(T(C * pm::atan(T(Bx - E * (Bx - pm::atan(Bx))))));
}

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

template <typename T>
MagicFormulaForcesT<T> magicFormula(const Pac2002Params& p, const T& kappa, const T& alpha, const T& gamma, const T& Fz,
                                    double mu, const T& vx) {
  using std::abs;
  const Pac2002Coefficients& c = p.c;
  const bool chrono = p.variant == Pac2002Variant::Chrono9;
  const T eps = chrono ? 0.1 : 1e-6;  // in B = K / (C D + eps)
  auto held = [&](const T& x) -> T { return chrono ? ad::clamp(x, -kChronoClamp, kChronoClamp) : x; };
  auto peak = [&](const T& x) -> T { return chrono ? T(abs(x)) : x; };  // Chrono takes |mu| (and |Bt|)
  MagicFormulaForcesT<T> out;
  const T Fz0 = p.nominalLoad * c.LFZO;  // Fz0', the scaled nominal load
  const T dfz = (Fz - Fz0) / Fz0;
  const T muRoad = std::clamp(mu, 0.1, 1.0) / p.referenceFriction;

  // Pure longitudinal slip (4.E9-4.E18).
  const T gx = gamma * c.LGAX;
  const T SHx = (c.PHX1 + c.PHX2 * dfz) * c.LHX;
  const T kx = kappa + SHx;
  const T Cx = c.PCX1 * c.LCX;
  const T mux = peak(muRoad * (c.PDX1 + c.PDX2 * dfz) * (chrono ? T(1.0) : T(1.0 - c.PDX3 * gx * gx)) * c.LMUX);
  const T Dx = mux * Fz;
  const T Ex = ad::min(1.0, (c.PEX1 + c.PEX2 * dfz + c.PEX3 * dfz * dfz) * (1.0 - c.PEX4 * ad::sign(kx)) * c.LEX);
  const T Kx = Fz * (c.PKX1 + c.PKX2 * dfz) * pm::exp(c.PKX3 * dfz) * c.LKX;
  const T Bx = Kx / (Cx * Dx + eps);
  const T SVx = Fz * (c.PVX1 + c.PVX2 * dfz) * c.LVX * c.LMUX;
  const T Fx0 = sineLaw<T>(held(Bx * kx), Cx, Dx, Ex) + SVx;

  // Pure lateral slip (4.E19-4.E30). Chrono9 scales Ky by LMUY where the textbook has LKY.
  const T gy = gamma * c.LGAY;
  const T SHy = (c.PHY1 + c.PHY2 * dfz) * c.LHY + c.PHY3 * gy;
  const T ay = alpha + SHy;
  const T Cy = c.PCY1 * c.LCY;
  const T muy = peak(muRoad * (c.PDY1 + c.PDY2 * dfz) * (1.0 - c.PDY3 * gy * gy) * c.LMUY);
  const T Dy = muy * Fz;
  const T Ey = ad::min(1.0, (c.PEY1 + c.PEY2 * dfz) * (1.0 - (c.PEY3 + c.PEY4 * gy) * ad::sign(ay)) * c.LEY);
  const T Ky = c.PKY1 * Fz0 * pm::sin(2.0 * pm::atan(Fz / (c.PKY2 * Fz0))) * (1.0 - c.PKY3 * abs(gy)) *
                    (chrono ? c.LMUY : c.LKY);
  const T By = Ky / (Cy * Dy + eps);
  const T SVy = Fz * ((c.PVY1 + c.PVY2 * dfz) * c.LVY + (c.PVY3 + c.PVY4 * dfz) * gy) * c.LMUY;
  const T Fy0 = sineLaw<T>(held(By * ay), Cy, Dy, Ey) + SVy;

  // Pure aligning moment (4.E31-4.E49): trail t and residual moment Mzr.
  const T gz = gamma * c.LGAZ;
  const T SHt = c.QHZ1 + c.QHZ2 * dfz + (c.QHZ3 + c.QHZ4 * dfz) * gz;
  const T at = alpha + SHt;
  const T ar = alpha + SHy + SVy / Ky;
  const T Bt =
      peak((c.QBZ1 + c.QBZ2 * dfz + c.QBZ3 * dfz * dfz) * (1.0 + c.QBZ4 * gz + c.QBZ5 * abs(gz)) * c.LKY / c.LMUY);
  const T Ct = c.QCZ1;
  const T Dt = Fz * (c.QDZ1 + c.QDZ2 * dfz) * (1.0 + c.QDZ3 * gz + c.QDZ4 * gz * gz) * (p.unloadedRadius / Fz0) *
                    c.LTR;
  const T Et = ad::min(
      1.0, (c.QEZ1 + c.QEZ2 * dfz + c.QEZ3 * dfz * dfz) * (1.0 + (c.QEZ4 + c.QEZ5 * gz) * (2.0 / kPi) * pm::atan(Bt * Ct * at)));
  const T Br = c.QBZ9 * c.LKY / c.LMUY + c.QBZ10 * By * Cy;
  const T Dr = Fz * ((c.QDZ6 + c.QDZ7 * dfz) * c.LRES + (c.QDZ8 + c.QDZ9 * dfz) * gz) * p.unloadedRadius * c.LMUY;
  const T cosAlpha = pm::cos(alpha);
  auto trail = [&](const T& a) -> T { return Dt * cosineLaw<T>(Bt * a, Ct, Et) * cosAlpha; };
  auto residualMoment = [&](const T& a) -> T { return Dr * pm::cos(pm::atan(Br * a)) * cosAlpha; };

  if (!p.combined) {
    out.Fx = Fx0;
    out.Fy = Fy0;
    out.Mz = -trail(at) * Fy0 + residualMoment(ar);
  } else if (p.ellipse) {
    // Chrono's friction ellipse (tyre-pac2002.md 3.5), in its finite form.
    const T kc = kappa + SHx + SVx / Kx;
    const T sa = pm::sin(alpha + SHy + SVy / Ky);
    const T muxAct = abs(Fx0 - SVx) / Fz, muyAct = abs(Fy0 - SVy) / Fz;
    const T muxMax = Dx / Fz, muyMax = Dy / Fz;
    const T nx = ad::hypot(muyMax * kc, muxAct * sa), ny = ad::hypot(muxMax * sa, muyAct * kc);
    out.Fx = nx > 0 ? Fx0 * muyMax * abs(kc) / nx : Fx0;
    out.Fy = ny > 0 ? Fy0 * muxMax * abs(sa) / ny : Fy0;
    out.Mz = -trail(at) * out.Fy + residualMoment(ar);
  } else {
    // The PAC2002 weighting functions (4.E50-4.E78).
    const T SHxa = c.RHX1, aS = alpha + SHxa;
    const T Bxa = peak(c.RBX1 * pm::cos(pm::atan(c.RBX2 * kappa)) * c.LXAL);
    const T Cxa = c.RCX1, Exa = ad::min(1.0, c.REX1 + c.REX2 * dfz);
    const T Gxa = cosineLaw<T>(Bxa * aS, Cxa, Exa) / cosineLaw<T>(Bxa * SHxa, Cxa, Exa);
    out.Fx = Gxa * Fx0;
    const T SHyk = c.RHY1 + c.RHY2 * dfz, kS = kappa + SHyk;
    const T Byk = peak(c.RBY1 * pm::cos(pm::atan(c.RBY2 * (alpha - c.RBY3))) * c.LYKA);
    const T Cyk = c.RCY1, Eyk = ad::min(1.0, c.REY1 + c.REY2 * dfz);
    const T DVyk = muy * Fz * (c.RVY1 + c.RVY2 * dfz + c.RVY3 * gamma) * pm::cos(pm::atan(c.RVY4 * alpha));
    const T SVyk = DVyk * pm::sin(c.RVY5 * pm::atan(c.RVY6 * kappa)) * c.LVYKA;
    const T Gyk = cosineLaw<T>(Byk * kS, Cyk, Eyk) / cosineLaw<T>(Byk * SHyk, Cyk, Eyk);
    out.Fy = Gyk * Fy0 + SVyk;
    // Equivalent slip angles for the trail and the residual moment (Chrono signs the first with kappa).
    const T r = Kx / Ky * kappa;
    const T atEq = pm::atan(ad::sqrt0(T(pm::tan(at) * pm::tan(at) + r * r))) * (chrono ? ad::sign(kappa) : ad::sign(at));
    const T arEq = pm::atan(ad::sqrt0(T(pm::tan(ar) * pm::tan(ar) + r * r))) * ad::sign(ar);
    const T s = (c.SSZ1 + c.SSZ2 * out.Fy / Fz0 + (c.SSZ3 + c.SSZ4 * dfz) * gamma) * p.unloadedRadius * c.LS;
    out.Mz = -trail(atEq) * (out.Fy - SVyk) + residualMoment(arEq) + s * out.Fx;
  }

  // Overturning and rolling-resistance moments (4.E69, 4.E70); Chrono9
  // zeroes QSY1 and QSY2 (its reader's bug, tyre-pac2002.md 1.3). My opposes
  // the rolling, its sign smooth below 0.5 m/s.
  out.Mx = p.unloadedRadius * Fz * (c.QSX1 * c.LVMX - c.QSX2 * gamma + c.QSX3 * out.Fy / Fz0) * c.LMX;
  const T v = vx / p.longvl;
  const T rolling = (chrono ? T(0.0) : T(c.QSY1 + c.QSY2 * out.Fx / Fz0)) + c.QSY3 * abs(v) + c.QSY4 * v * v * v * v;
  out.My = -p.unloadedRadius * Fz * rolling * c.LMY * pm::tanh(vx / 0.5);
  out.Kx = Kx;
  out.Ky = Ky;
  out.Dx = Dx;
  out.Dy = Dy;
  return out;
}

template MagicFormulaForcesT<double> magicFormula(const Pac2002Params&, const double&, const double&, const double&,
                                                  const double&, double, const double&);

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

template <typename T>
void Pac2002Tyre::evaluate(const WheelKinematicsT<T>& w, const ContactPlaneT<T>& g, const SlipState& prevIn, double h,
                           std::optional<T> load, TyreOutputT<T>& out) const {
  using std::abs;
  // Every field written: the caller's output from an earlier evaluation is
  // overwritten as a whole (the slips copied first: they may be the caller's).
  const SlipState prev = prevIn;
  out = TyreOutputT<T>{};
  out.slipState = prev;
  const std::optional<ContactGeometryT<T>> geo = contactGeometry(w, g, p_.unloadedRadius);
  if (!geo) {
    out.slipState = SlipState{};
    return;
  }
  const Pac2002Coefficients& c = p_.c;
  const bool chrono = p_.variant == Pac2002Variant::Chrono9;
  const double Cz = p_.verticalStiffness * c.LCZ;
  T delta = geo->delta;
  const T raw = load ? *load : T(Cz * delta - p_.verticalDamping * geo->vz);
  const std::optional<T> Fzo = smoothedLoad(raw, delta, load.has_value());
  if (!Fzo) {
    out.slipState = SlipState{};
    return;
  }
  const T Fz = *Fzo;
  if (load) delta = Fz / Cz;

  // Effective rolling radius: the MF law when the file has it (textbook), else R0 - delta / 3.
  const double R0 = p_.unloadedRadius;
  T Reff = R0 - delta / 3.0;
  if (!chrono && (p_.breff != 0 || p_.dreff != 0 || p_.freff != 0)) {
    const T rho = delta * Cz / p_.nominalLoad;
    Reff = R0 - p_.nominalLoad / Cz * (p_.dreff * pm::atan(p_.breff * rho) + p_.freff * rho);
  }
  const T vx = geo->vx, vy = geo->vy;
  const T vsx = vx - w.spinRate * Reff, vsy = vy;
  const T absVx = abs(vx);
  // Chrono9 softens every slip by 0.1 m/s (tyre-pac2002.md 2.2).
  const double soft = chrono ? 0.1 : 0.0;

  // Slips (ISO: kappa driving > 0, tan(alpha) = v_y / |v_x|): exact above
  // the low-speed range, transient below, blended in between.
  const T beta = exactSlipWeight(p_.lowSpeed, absVx);
  T kappa, tanAlpha;
  SlipState next = prev;
  if (ad::value(beta) < 1.0) {
    // Relaxation lengths (the file's, textbook: 4.E79, 4.E80) and the slips
    // where the force laws peak (the transient slips' bounds).
    const double Fz0 = p_.nominalLoad * c.LFZO;
    const T dfz = (Fz - Fz0) / Fz0;
    T sx = p_.lowSpeed.relaxationLengthX, sy = p_.lowSpeed.relaxationLengthY;
    if (!chrono && c.PTX1 > 0 && c.PTY1 > 0) {
      sx = Fz * (c.PTX1 + c.PTX2 * dfz) * pm::exp(-c.PTX3 * dfz) * (R0 / Fz0) * c.LSGKP;
      sy = c.PTY1 * pm::sin(2.0 * pm::atan(Fz / (c.PTY2 * Fz0))) * R0 * c.LFZO * c.LSGAL;
    }
    const MagicFormulaForcesT<T> at0 = magicFormula<T>(p_, 0.0, 0.0, 0.0, Fz, g.friction);
    const double Cx = c.PCX1 * c.LCX, Cy = c.PCY1 * c.LCY;
    auto peakSlip = [&](const T& K, double C, const T& D) -> T {
      const T B = abs(K) / (C * D + 1e-6);
      return C > 1.0 && B > 0 ? ad::min(p_.lowSpeed.maxTransientSlip, T(pm::tan(kPi / (2.0 * C)) / B))
                              : T(p_.lowSpeed.maxTransientSlip);
    };
    const BlendedSlipsT<T> s =
        lowSpeedSlips<T>(p_.lowSpeed, beta, vsx, vsy, absVx, prev, h, ad::max(0.01, sx), ad::max(0.01, sy),
                         peakSlip(at0.Kx, Cx, at0.Dx), peakSlip(at0.Ky, Cy, at0.Dy), ad::max(at0.Kx, 1.0),
                         ad::max(T(abs(at0.Ky)), 1.0), T(ad::max(absVx, p_.lowSpeed.blend0) + soft));
    kappa = s.kappa;
    tanAlpha = s.tanAlpha;
    next = s.next;
  } else {
    kappa = -vsx / (absVx + soft);
    tanAlpha = vsy / (absVx + soft);
    next.active = false;
  }

  MagicFormulaForcesT<T> f;
  T Fy, Mz, My, gamma = T(0.0);
  if (chrono) {
    // Its internal slip angle alpha_c = -alpha_ISO, clamps, no camber, and
    // its outputs back into the contact frame: (Fx, -Fy), (Mx, -My, -Mz).
    kappa = ad::clamp(kappa, -1.0, 1.0);
    const T alphaC = ad::clamp(T(-pm::atan(tanAlpha)), -kChronoClamp, kChronoClamp);
    f = magicFormula<T>(p_, kappa, alphaC, 0.0, Fz, g.friction, vx);
    Fy = -f.Fy;
    Mz = -f.Mz;
    My = -f.My;
  } else {
    // Camber (ISO: + with the wheel's top leaning to the right of its heading).
    gamma = pm::atan2(w.spinAxis.dot(g.normal), w.spinAxis.dot(geo->yc));
    f = magicFormula<T>(p_, kappa, pm::atan(tanAlpha), gamma, Fz, g.friction, vx);
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
}

template void Pac2002Tyre::evaluate(const WheelKinematicsT<double>&, const ContactPlaneT<double>&, const SlipState&,
                                    double, std::optional<double>, TyreOutputT<double>&) const;
template void Pac2002Tyre::evaluate(const WheelKinematicsT<ad::Dual>&, const ContactPlaneT<ad::Dual>&,
                                    const SlipState&, double, std::optional<ad::Dual>, TyreOutputT<ad::Dual>&) const;

}  // namespace bdfcar::tyre
