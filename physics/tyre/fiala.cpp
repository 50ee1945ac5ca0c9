#include "tyre/fiala.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include "portable_math.h"

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

constexpr double FialaTyre::kContactSmoothing;
constexpr double FialaTyre::kAirborneClearance;

double highSpeedWeight(const FialaParams& p, double absVx) {
  if (absVx <= p.lowSpeedBlend0) return 0.0;
  if (absVx >= p.lowSpeedBlend1) return 1.0;
  const double s = (absVx - p.lowSpeedBlend0) / (p.lowSpeedBlend1 - p.lowSpeedBlend0);
  return s * s * (3.0 - 2.0 * s);
}

TyreOutput FialaTyre::evaluate(const WheelKinematics& w, const ContactPlane& g, const SlipState& prev,
                               double h, std::optional<double> load) const {
  TyreOutput out;
  out.slipState = prev;
  if (!g.valid) {
    out.slipState = SlipState{};
    return out;
  }
  // Contact geometry (spec 7.1, with the local ground normal in place of e_z).
  const Vec3& n = w.spinAxis;
  const Vec3& ez = g.normal;
  const Vec3 nxz = n.cross(ez);
  const double heightOfCentre = (w.centre - g.point).dot(ez);
  if (nxz.squaredNorm() < 1e-3 || heightOfCentre <= 0) {
    out.slipState = SlipState{};
    return out;
  }
  const Vec3 xc = nxz.normalized();  // wheel heading in the ground plane
  const Vec3 d = n.cross(xc);         // down in the wheel plane
  const double R0 = p_.unloadedRadius;
  const Vec3 bottom = w.centre + R0 * d;
  double delta = (g.point - bottom).dot(ez);
  const Vec3 yc = ez.cross(xc);
  const Vec3& v = w.centreVelocity;
  const double vx = v.dot(xc), vy = v.dot(yc), vz = v.dot(ez);
  // Normal load max(0, kz delta - cz vz) with the corner at zero rounded over
  // kContactSmoothing newtons: a wheel striking a curb or landing switches
  // contact inside a step, and Newton cannot converge across a kink. The
  // difference is eps^2 / (4 Fz): below 0.01 N at the loads of a manoeuvre.
  const double raw = load ? *load : p_.verticalStiffness * delta - p_.verticalDamping * vz;
  if ((!load && delta <= -kAirborneClearance) || raw < -1e3 * kContactSmoothing) {
    out.slipState = SlipState{};
    return out;
  }
  const double Fz = 0.5 * (raw + std::sqrt(raw * raw + kContactSmoothing * kContactSmoothing));
  if (load) delta = Fz / p_.verticalStiffness;

  const double vsx = vx - w.spinRate * (R0 - delta);
  const double vsy = vy;
  const double absVx = std::abs(vx);
  // Slips: exact above lowSpeedBlend1, transient below, blended in between.
  const double beta = highSpeedWeight(p_, absVx);
  double kappa, tanAlpha;
  SlipState next = prev;
  if (beta < 1.0) {
    // Backward Euler over the step from the last accepted transient slips
    // (from the algebraic ones when the wheel has just slowed into this range).
    // The tread deflection is bounded by friction: once the patch slides it
    // stays where its force is the friction force (slips U Fz / C_kappa and,
    // for the lateral law, 3 U Fz / C_alpha, full sliding).
    const double sx = p_.relaxationLengthX, sy = p_.relaxationLengthY;
    const double Upeak = p_.uMax * std::clamp(g.friction, 0.1, 1.0) / p_.referenceFriction;
    const double limX = std::min(p_.maxTransientSlip, Upeak * Fz / p_.slipStiffness);
    const double limY = std::min(p_.maxTransientSlip, 3.0 * Upeak * Fz / p_.corneringStiffness);
    const double denom = std::max(absVx, p_.lowSpeedBlend0);
    SlipState from = prev;
    if (!prev.active) {
      from.kappa = -vsx / denom;
      from.tanAlpha = vsy / denom;
    }
    next.kappa = std::clamp((from.kappa - h * vsx / sx) / (1.0 + h * absVx / sx), -limX, limX);
    next.tanAlpha = std::clamp((from.tanAlpha + h * vsy / sy) / (1.0 + h * absVx / sy), -limY, limY);
    next.active = true;
    // Damping of the slip velocities enters as slip, ahead of the force law,
    // so that the total force stays within friction (a locked wheel sliding
    // at walking pace must not brake harder than mu Fz).
    const double dampX = -p_.lowSpeedDampingX * vsx / p_.slipStiffness;
    const double dampY = p_.lowSpeedDampingY * vsy / p_.corneringStiffness;
    kappa = beta * (-vsx / denom) + (1.0 - beta) * (next.kappa + dampX);
    tanAlpha = beta * (vsy / denom) + (1.0 - beta) * (next.tanAlpha + dampY);
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
  return out;
}

}  // namespace bdfcar::tyre
