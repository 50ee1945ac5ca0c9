#include "tyre/fiala.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include "autodiff.h"
#include "portable_math.h"
#include "tyre/contact_geometry.h"

namespace bdfcar::tyre {

namespace {

// Chrono's ChFunctionSineStep from (x0, 0) to (x1, 1).
template <typename T>
T sineStep(const T& x, double x0, double x1) {
  if (ad::value(x) <= x0) return T(0.0);
  if (ad::value(x) >= x1) return T(1.0);
  const T xi = (x - x0) / (x1 - x0);
  return T(xi - pm::sin(T(2 * std::numbers::pi * xi)) / (2 * std::numbers::pi));
}

}  // namespace

// The law written in tan(alpha): the combined slip and H take the tangent,
// and |alpha| <= alpha_c is |tan alpha| <= tan alpha_c = 3 U Fz / C_alpha
// (alpha within +-pi/2), so the evaluation needs neither tan nor atan.
template <typename T>
PatchForcesT<T> fialaPatchForcesTan(const FialaParams& p, const T& kappa, const T& tanA, const T& Fz, double mu) {
  using std::abs;
  PatchForcesT<T> out;
  if (!(ad::value(Fz) > 0)) return out;
  const T S = ad::min(1.0, ad::sqrt0(T(kappa * kappa + tanA * tanA)));
  T U = p.uMax - (p.uMax - p.uMin) * S;
  // Critical slips use U before friction scaling (as the reference codes it).
  const T kappaC = abs(T(U * Fz / (2.0 * p.slipStiffness)));
  const T tanAlphaC = 3.0 * U * Fz / p.corneringStiffness;
  U *= std::clamp(mu, 0.1, 1.0) / p.referenceFriction;
  const T UFz = U * Fz;
  if (ad::value(abs(kappa)) < ad::value(kappaC))
    out.Fx = p.slipStiffness * kappa;
  else
    out.Fx = ad::sign(kappa) * (UFz - abs(T(UFz * UFz / (4.0 * kappa * p.slipStiffness))));
  if (ad::value(abs(tanA)) <= ad::value(tanAlphaC)) {
    const T H = 1.0 - p.corneringStiffness * abs(tanA) / (3.0 * UFz);
    const T H3 = H * H * H;
    out.Fy = -UFz * (1.0 - H3) * ad::sign(tanA);
    out.Mz = UFz * p.width * (1.0 - H) * H3 * ad::sign(tanA);
  } else {
    out.Fy = -UFz * ad::sign(tanA);
    out.Mz = T(0.0);
  }
  return out;
}

PatchForces fialaPatchForces(const FialaParams& p, double kappa, double alpha, double Fz, double mu) {
  return fialaPatchForcesTan(p, kappa, pm::tan(alpha), Fz, mu);
}

template <typename T>
void FialaTyre::evaluate(const WheelKinematicsT<T>& w, const ContactPlaneT<T>& g, const SlipState& prevIn, double h,
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
  const Vec3T<T>& ez = g.normal;
  const Vec3T<T>& xc = geo->xc;
  const Vec3T<T>& yc = geo->yc;
  const Vec3T<T>& d = geo->down;
  const double R0 = p_.unloadedRadius;
  T delta = geo->delta;
  const T vx = geo->vx, vy = geo->vy, vz = geo->vz;
  const T raw = load ? *load : T(p_.verticalStiffness * delta - p_.verticalDamping * vz);
  const std::optional<T> Fzo = smoothedLoad(raw, delta, load.has_value());
  if (!Fzo) {
    out.slipState = SlipState{};
    return;
  }
  const T Fz = *Fzo;
  if (load) delta = Fz / p_.verticalStiffness;

  const T vsx = vx - w.spinRate * (R0 - delta);
  const T vsy = vy;
  const T absVx = abs(vx);
  // Slips: exact above lowSpeed.blend1, transient below, blended in between.
  const T beta = exactSlipWeight(p_.lowSpeed, absVx);
  T kappa, tanAlpha;
  SlipState next = prev;
  if (ad::value(beta) < 1.0) {
    // The tread deflection is bounded by friction: once the patch slides it
    // stays where its force is the friction force (slips U Fz / C_kappa and,
    // for the lateral law, 3 U Fz / C_alpha, full sliding).
    const double Upeak = p_.uMax * std::clamp(g.friction, 0.1, 1.0) / p_.referenceFriction;
    const T limX = ad::min(p_.lowSpeed.maxTransientSlip, T(Upeak * Fz / p_.slipStiffness));
    const T limY = ad::min(p_.lowSpeed.maxTransientSlip, T(3.0 * Upeak * Fz / p_.corneringStiffness));
    const BlendedSlipsT<T> s = lowSpeedSlips<T>(
        p_.lowSpeed, beta, vsx, vsy, absVx, prev, h, T(p_.lowSpeed.relaxationLengthX),
        T(p_.lowSpeed.relaxationLengthY), limX, limY, T(p_.slipStiffness), T(p_.corneringStiffness),
        ad::max(absVx, p_.lowSpeed.blend0));
    kappa = s.kappa;
    tanAlpha = s.tanAlpha;
    next = s.next;
  } else {
    kappa = -vsx / absVx;
    tanAlpha = vsy / absVx;
    next.active = false;  // algebraic slips: no transient state to carry
  }
  const PatchForcesT<T> f = fialaPatchForcesTan(p_, kappa, tanAlpha, Fz, g.friction);
  // Rolling resistance opposes the spin: sign(omega) made smooth below
  // 0.5 rad/s (a locked wheel's omega dithers about zero; a jump there would
  // stop Newton from converging). Exactly +-1 at road speeds.
  const T My = -sineStep(absVx, 0.125, 0.5) * p_.rollingResistance * Fz * pm::tanh(T(w.spinRate / 0.5));

  out.inContact = true;
  out.deflection = delta;
  out.contactPoint = w.centre + (R0 - delta) * d;
  out.point = out.contactPoint + delta * ez;  // as the reference applies it
  out.force = f.Fx * xc + f.Fy * yc + Fz * ez;
  out.moment = My * yc + f.Mz * ez;
  out.Fx = f.Fx;
  out.Fy = f.Fy;
  out.Fz = Fz;
  out.My = My;
  out.Mz = f.Mz;
  out.kappa = kappa;
  out.tanAlpha = tanAlpha;
  out.vx = vx;
  out.vsx = vsx;
  out.vsy = vsy;
  out.slipState = next;
}

template PatchForcesT<double> fialaPatchForcesTan(const FialaParams&, const double&, const double&, const double&,
                                                  double);
template void FialaTyre::evaluate(const WheelKinematicsT<double>&, const ContactPlaneT<double>&, const SlipState&,
                                  double, std::optional<double>, TyreOutputT<double>&) const;
template void FialaTyre::evaluate(const WheelKinematicsT<ad::Dual>&, const ContactPlaneT<ad::Dual>&, const SlipState&,
                                  double, std::optional<ad::Dual>, TyreOutputT<ad::Dual>&) const;

}  // namespace bdfcar::tyre
