#include "tyre/fiala.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include "portable_math.h"
#include "tyre/contact_geometry.h"

namespace bdfcar::tyre {

namespace {

double sgn(double x) { return (x > 0) - (x < 0); }

// Chrono's ChFunctionSineStep from (x0, 0) to (x1, 1).
double sineStep(double x, double x0, double x1) {
  if (x <= x0) return 0.0;
  if (x >= x1) return 1.0;
  const double xi = (x - x0) / (x1 - x0);
  return xi - pm::sin(2 * std::numbers::pi * xi) / (2 * std::numbers::pi);
}

}  // namespace

// The law written in tan(alpha): the combined slip and H take the tangent,
// and |alpha| <= alpha_c is |tan alpha| <= tan alpha_c = 3 U Fz / C_alpha
// (alpha within +-pi/2), so the evaluation needs neither tan nor atan.
PatchForces fialaPatchForcesTan(const FialaParams& p, double kappa, double tanA, double Fz, double mu) {
  PatchForces out;
  if (!(Fz > 0)) return out;
  const double S = std::min(1.0, std::sqrt(kappa * kappa + tanA * tanA));
  double U = p.uMax - (p.uMax - p.uMin) * S;
  // Critical slips use U before friction scaling (as the reference codes it).
  const double kappaC = std::abs(U * Fz / (2.0 * p.slipStiffness));
  const double tanAlphaC = 3.0 * U * Fz / p.corneringStiffness;
  U *= std::clamp(mu, 0.1, 1.0) / p.referenceFriction;
  const double UFz = U * Fz;
  if (std::abs(kappa) < kappaC)
    out.Fx = p.slipStiffness * kappa;
  else
    out.Fx = sgn(kappa) * (UFz - std::abs(UFz * UFz / (4.0 * kappa * p.slipStiffness)));
  if (std::abs(tanA) <= tanAlphaC) {
    const double H = 1.0 - p.corneringStiffness * std::abs(tanA) / (3.0 * UFz);
    const double H3 = H * H * H;
    out.Fy = -UFz * (1.0 - H3) * sgn(tanA);
    out.Mz = UFz * p.width * (1.0 - H) * H3 * sgn(tanA);
  } else {
    out.Fy = -UFz * sgn(tanA);
    out.Mz = 0.0;
  }
  return out;
}

PatchForces fialaPatchForces(const FialaParams& p, double kappa, double alpha, double Fz, double mu) {
  return fialaPatchForcesTan(p, kappa, pm::tan(alpha), Fz, mu);
}

void FialaTyre::evaluate(const WheelKinematics& w, const ContactPlane& g, const SlipState& prevIn,
                               double h, std::optional<double> load, TyreOutput& out) const {
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
  const Vec3& ez = g.normal;
  const Vec3& xc = geo->xc;
  const Vec3& yc = geo->yc;
  const Vec3& d = geo->down;
  const double R0 = p_.unloadedRadius;
  double delta = geo->delta;
  const double vx = geo->vx, vy = geo->vy, vz = geo->vz;
  const double raw = load ? *load : p_.verticalStiffness * delta - p_.verticalDamping * vz;
  const std::optional<double> Fzo = smoothedLoad(raw, delta, load.has_value());
  if (!Fzo) {
    out.slipState = SlipState{};
    return;
  }
  const double Fz = *Fzo;
  if (load) delta = Fz / p_.verticalStiffness;

  const double vsx = vx - w.spinRate * (R0 - delta);
  const double vsy = vy;
  const double absVx = std::abs(vx);
  // Slips: exact above lowSpeed.blend1, transient below, blended in between.
  const double beta = exactSlipWeight(p_.lowSpeed, absVx);
  double kappa, tanAlpha;
  SlipState next = prev;
  if (beta < 1.0) {
    // The tread deflection is bounded by friction: once the patch slides it
    // stays where its force is the friction force (slips U Fz / C_kappa and,
    // for the lateral law, 3 U Fz / C_alpha, full sliding).
    const double Upeak = p_.uMax * std::clamp(g.friction, 0.1, 1.0) / p_.referenceFriction;
    const double limX = std::min(p_.lowSpeed.maxTransientSlip, Upeak * Fz / p_.slipStiffness);
    const double limY = std::min(p_.lowSpeed.maxTransientSlip, 3.0 * Upeak * Fz / p_.corneringStiffness);
    const BlendedSlips s =
        lowSpeedSlips(p_.lowSpeed, beta, vsx, vsy, absVx, prev, h, p_.lowSpeed.relaxationLengthX,
                      p_.lowSpeed.relaxationLengthY, limX, limY, p_.slipStiffness, p_.corneringStiffness,
                      std::max(absVx, p_.lowSpeed.blend0));
    kappa = s.kappa;
    tanAlpha = s.tanAlpha;
    next = s.next;
  } else {
    kappa = -vsx / absVx;
    tanAlpha = vsy / absVx;
    next.active = false;  // algebraic slips: no transient state to carry
  }
  PatchForces f = fialaPatchForcesTan(p_, kappa, tanAlpha, Fz, g.friction);
  // Rolling resistance opposes the spin: sign(omega) made smooth below
  // 0.5 rad/s (a locked wheel's omega dithers about zero; a jump there would
  // stop Newton from converging). Exactly +-1 at road speeds.
  const double My = -sineStep(absVx, 0.125, 0.5) * p_.rollingResistance * Fz * pm::tanh(w.spinRate / 0.5);

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
  return;
}

}  // namespace bdfcar::tyre
