#include "tyre/tyre_model.h"

#include <algorithm>
#include <cmath>

#include "autodiff.h"
#include "portable_math.h"

namespace bdfcar::tyre {

template <>
double TyreOutput::slipAngle() const {
  return pm::atan(tanAlpha);
}

double unloadedRadius(const TyreParams& p) {
  return std::visit([](const auto& m) { return m.unloadedRadius; }, p);
}

double verticalStiffness(const TyreParams& p) {
  return std::visit([](const auto& m) { return m.verticalStiffness; }, p);
}

double verticalDamping(const TyreParams& p) {
  return std::visit([](const auto& m) { return m.verticalDamping; }, p);
}

double peakFriction(const TyreParams& p, double mu) {
  if (const auto* pac = std::get_if<Pac2002Params>(&p)) return pac2002PeakFriction(*pac, mu);
  const FialaParams& f = std::get<FialaParams>(p);
  return f.uMax * std::clamp(mu, 0.1, 1.0) / f.referenceFriction;
}

double corneringStiffness(const TyreParams& p, double Fz) {
  if (const auto* pac = std::get_if<Pac2002Params>(&p))
    return std::abs(magicFormula(*pac, 0.0, 0.0, 0.0, Fz, pac->referenceFriction).Ky);
  return std::get<FialaParams>(p).corneringStiffness;
}

const EnvelopeSpec& contact(const TyreParams& p) {
  return std::visit([](const auto& m) -> const EnvelopeSpec& { return m.contact; }, p);
}

double width(const TyreParams& p) {
  return std::visit([](const auto& m) { return m.width; }, p);
}

namespace {
// The model of each kind of tyre data (one overload per alternative).
FialaTyre modelFor(const FialaParams& p) { return FialaTyre(p); }
Pac2002Tyre modelFor(const Pac2002Params& p) { return Pac2002Tyre(p); }
}  // namespace

Tyre::Tyre(const TyreParams& p)
    : model_(std::visit([](const auto& m) { return std::variant<FialaTyre, Pac2002Tyre>(modelFor(m)); }, p)),
      radius_(tyre::unloadedRadius(p)) {}

TyreOutput Tyre::evaluate(const WheelKinematics& wheel, const ContactPlane& ground, const SlipState& previous,
                          double h, std::optional<double> load) const {
  TyreOutput out;
  evaluate(wheel, ground, previous, h, load, out);
  return out;
}

template <typename T>
void Tyre::evaluate(const WheelKinematicsT<T>& wheel, const ContactPlaneT<T>& ground, const SlipState& previous,
                    double h, std::optional<T> load, TyreOutputT<T>& out) const {
  if (const FialaTyre* fiala = std::get_if<FialaTyre>(&model_))
    fiala->evaluate(wheel, ground, previous, h, load, out);
  else
    std::get<Pac2002Tyre>(model_).evaluate(wheel, ground, previous, h, load, out);
}

template void Tyre::evaluate(const WheelKinematicsT<double>&, const ContactPlaneT<double>&, const SlipState&, double,
                             std::optional<double>, TyreOutputT<double>&) const;
template void Tyre::evaluate(const WheelKinematicsT<ad::Dual>&, const ContactPlaneT<ad::Dual>&, const SlipState&,
                             double, std::optional<ad::Dual>, TyreOutputT<ad::Dual>&) const;

}  // namespace bdfcar::tyre
