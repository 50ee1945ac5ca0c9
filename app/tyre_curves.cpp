#include "tyre_curves.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "config/units.h"

namespace bdfcar::app {

namespace {

using tyre::FialaParams;
using tyre::Pac2002Params;
using tyre::Pac2002Variant;

// The sweeps: slip angle +-30 deg by 0.1 deg, slip ratio +-0.5 by 0.0025
// (both past the peaks of road tyres up to 1.5 x nominal load: the Fiala
// tyre saturates at tan(alpha) = 3 U Fz / C_alpha, about 21 deg for the
// sedan's at its static load), loads 0.1 to 2.5 x nominal by 0.1.
constexpr int kAlphaSteps = 300;
const double kAlphaStep = config::degToRad(0.1);
constexpr int kKappaSteps = 200;
constexpr double kKappaStep = 0.0025;
constexpr int kLoadSteps = 25;
// Central-difference step for the slopes at zero slip (rad, 1): small
// enough that the Fiala law's |slip| terms (an O(h) error of the central
// difference there, C_alpha h / (3 U Fz) relative) stay below 1e-6 of
// the stiffness; the Magic Formula's is O(h^2).
constexpr double kSlopeStep = 1e-7;

SteadyTyreForces fiala(const FialaParams& p, double kappa, double alpha, double Fz, double mu, bool pureSlip) {
  // Fiala's own convention is ISO's (its Fy = -C_alpha tan(alpha) at small slip).
  if (!pureSlip) {
    const tyre::PatchForces f = tyre::fialaPatchForces(p, kappa, alpha, Fz, mu);
    return {f.Fx, f.Fy, f.Mz};
  }
  const tyre::PatchForces x = tyre::fialaPatchForces(p, kappa, 0.0, Fz, mu);
  const tyre::PatchForces y = tyre::fialaPatchForces(p, 0.0, alpha, Fz, mu);
  return {x.Fx, y.Fy, y.Mz};
}

// PAC2002 in ISO: Chrono9 takes alpha_c = -alpha and gives Fy, Mz negated.
// magicFormula evaluates the coefficients as given: a tyre mounted on the
// side it was not measured on has its odd coefficients mirrored first, as
// Pac2002Tyre does.
tyre::MagicFormulaForces magicFormulaIso(Pac2002Params p, double kappa, double alpha, double Fz, double mu) {
  p.c = tyre::mountedCoefficients(p);
  p.measuredLeft = p.mountedLeft;
  const bool chrono = p.variant == Pac2002Variant::Chrono9;
  tyre::MagicFormulaForces f = tyre::magicFormula(p, kappa, chrono ? -alpha : alpha, 0.0, Fz, mu);
  if (chrono) {
    f.Fy = -f.Fy;
    f.Mz = -f.Mz;
  }
  return f;
}

// The steepest slope of f at zero, by central difference.
double slopeAtZero(const std::function<double(double)>& f) {
  return (f(kSlopeStep) - f(-kSlopeStep)) / (2 * kSlopeStep);
}

LoadStiffness stiffnessAtLoad(const tyre::TyreParams& p, double Fz, double mu) {
  LoadStiffness s;
  s.Fz = Fz;
  s.cornering = -slopeAtZero([&](double a) { return steadyTyreForces(p, 0, a, Fz, mu, true).Fy; });
  s.slip = slopeAtZero([&](double k) { return steadyTyreForces(p, k, 0, Fz, mu, true).Fx; });
  if (const auto* f = std::get_if<FialaParams>(&p)) {
    s.corneringModel = f->corneringStiffness;
    s.slipModel = f->slipStiffness;
  } else {
    const tyre::MagicFormulaForces m = magicFormulaIso(std::get<Pac2002Params>(p), 0, 0, Fz, mu);
    s.corneringModel = std::abs(m.Ky);
    s.slipModel = std::abs(m.Kx);
  }
  return s;
}

// The peak of |g| for slip of sign `side` on the grid xs (values gs): the
// sample of the largest |g| nearest zero, then the interval about it
// resampled three times, so that a rounded maximum is found to ~1e-9 of the
// step and a flat top (Chrono9's clamp) from where it begins.
CurvePeak peakOf(const std::vector<double>& xs, const std::vector<double>& gs, int side,
                 const std::function<double(double)>& g, double Fz) {
  const double tiny = 1e-12;
  const int n = static_cast<int>(xs.size());
  int best = -1;
  for (int j = 0; j < n; ++j) {  // outward from zero slip: the first of equal maxima wins
    const int i = side > 0 ? j : n - 1 - j;
    if (side * xs[i] <= 0) continue;
    if (best < 0 || std::abs(gs[i]) > std::abs(gs[best]) * (1 + tiny)) best = i;
  }
  if (best < 0) throw std::logic_error("peakOf: no samples on the side");
  double lo = xs[std::max(best - 1, 0)], hi = xs[std::min(best + 1, n - 1)];
  double x = xs[best], v = gs[best];
  for (int pass = 0; pass < 3; ++pass) {
    constexpr int m = 200;
    const double step = (hi - lo) / m;
    double bx = x, bv = v;
    for (int k = 0; k <= m; ++k) {
      const double xk = side > 0 ? lo + k * step : hi - k * step;
      const double vk = g(xk);
      if (std::abs(vk) > std::abs(bv) * (1 + tiny) || (std::abs(vk) >= std::abs(bv) * (1 - tiny) && std::abs(xk) < std::abs(bx))) {
        bx = xk;
        bv = vk;
      }
    }
    x = bx;
    v = bv;
    lo = x - step;
    hi = x + step;
  }
  const bool end = best == 0 || best == n - 1;
  return {std::abs(v) / Fz, x, v, end};
}

std::vector<double> grid(int steps, double step) {
  std::vector<double> xs;
  for (int i = -steps; i <= steps; ++i) xs.push_back(i * step);
  return xs;
}

}  // namespace

SteadyTyreForces steadyTyreForces(const tyre::TyreParams& p, double kappa, double alpha, double Fz, double mu,
                                  bool pureSlip) {
  if (const auto* f = std::get_if<FialaParams>(&p)) return fiala(*f, kappa, alpha, Fz, mu, pureSlip);
  Pac2002Params pac = std::get<Pac2002Params>(p);
  if (pureSlip) pac.combined = false;  // USE_MODE 3: Fx0(kappa), Fy0(alpha), Mz0(alpha)
  const tyre::MagicFormulaForces m = magicFormulaIso(pac, kappa, alpha, Fz, mu);
  return {m.Fx, m.Fy, m.Mz};
}

std::string tyreModelName(const tyre::TyreParams& p) {
  if (std::holds_alternative<FialaParams>(p)) return "Fiala";
  return std::get<Pac2002Params>(p).variant == Pac2002Variant::Chrono9 ? "PAC2002 (chrono9)" : "PAC2002 (textbook)";
}

bool sameTyre(const tyre::TyreParams& a, const tyre::TyreParams& b) {
  if (a.index() != b.index()) return false;
  if (const auto* pa = std::get_if<Pac2002Params>(&a)) return *pa == std::get<Pac2002Params>(b);
  const FialaParams& x = std::get<FialaParams>(a);
  const FialaParams& y = std::get<FialaParams>(b);
  return x.unloadedRadius == y.unloadedRadius && x.width == y.width && x.verticalStiffness == y.verticalStiffness &&
         x.verticalDamping == y.verticalDamping && x.rollingResistance == y.rollingResistance &&
         x.slipStiffness == y.slipStiffness && x.corneringStiffness == y.corneringStiffness && x.uMin == y.uMin &&
         x.uMax == y.uMax && x.referenceFriction == y.referenceFriction && x.lowSpeed == y.lowSpeed &&
         x.contact == y.contact;
}

const LoadStiffness& stiffnessAt(const TyreCurves& c, double factor) {
  const long i = std::lround(factor * 10) - 1;
  if (i < 0 || i >= static_cast<long>(c.stiffness.size())) throw std::out_of_range("stiffnessAt: load factor");
  return c.stiffness[i];
}

TyreCurves tyreCurves(const tyre::TyreParams& p, double nominalLoad, double friction) {
  if (!(nominalLoad > 0)) throw std::invalid_argument("tyre curves: the nominal load must be positive");
  TyreCurves c;
  c.model = tyreModelName(p);
  c.unloadedRadius = tyre::unloadedRadius(p);
  c.nominalLoad = nominalLoad;
  c.friction = friction;
  c.referenceFriction = std::visit([](const auto& m) { return m.referenceFriction; }, p);
  const double Fz0 = nominalLoad, mu = friction;
  auto force = [&](double kappa, double alpha, double Fz, bool pure) {
    return steadyTyreForces(p, kappa, alpha, Fz, mu, pure);
  };

  c.alpha = grid(kAlphaSteps, kAlphaStep);
  c.kappa = grid(kKappaSteps, kKappaStep);
  for (size_t l = 0; l < TyreCurves::loadFactors.size(); ++l) {
    const double Fz = TyreCurves::loadFactors[l] * Fz0;
    for (double a : c.alpha) {
      const SteadyTyreForces f = force(0, a, Fz, true);
      c.Fy[l].push_back(f.Fy);
      c.Mz[l].push_back(f.Mz);
    }
    for (double k : c.kappa) c.Fx[l].push_back(force(k, 0, Fz, true).Fx);
  }
  for (size_t j = 0; j < TyreCurves::combinedAlphaDeg.size(); ++j) {
    const double a = config::degToRad(TyreCurves::combinedAlphaDeg[j]);
    for (double k : c.kappa) {
      const SteadyTyreForces f = force(k, a, Fz0, false);
      c.combinedFx[j].push_back(f.Fx);
      c.combinedFy[j].push_back(f.Fy);
    }
  }
  for (int i = 1; i <= kLoadSteps; ++i) c.stiffness.push_back(stiffnessAtLoad(p, i / 10.0 * Fz0, mu));
  c.atNominal = stiffnessAt(c, 1.0);

  // Peaks at the nominal load (index 1 of loadFactors), each side of zero slip.
  const auto fy = [&](double a) { return force(0, a, Fz0, true).Fy; };
  const auto mz = [&](double a) { return force(0, a, Fz0, true).Mz; };
  const auto fx = [&](double k) { return force(k, 0, Fz0, true).Fx; };
  for (int s = 0; s < 2; ++s) {
    const int side = s == 0 ? 1 : -1;
    c.lateral[s] = peakOf(c.alpha, c.Fy[1], side, fy, Fz0);
    c.longitudinal[s] = peakOf(c.kappa, c.Fx[1], side, fx, Fz0);
    c.aligning[s] = peakOf(c.alpha, c.Mz[1], side, mz, 1.0);
  }
  return c;
}

}  // namespace bdfcar::app
