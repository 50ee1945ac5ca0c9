// The tyre models bdfcar has, as a closed set dispatched like the joint
// types (no virtual interface): a second model is one more alternative in
// TyreParams and Tyre, one more branch in tyre_model.cpp and one in the
// vehicle loader's [tyres] reader; nothing else changes.
#pragma once

#include <variant>

#include "tyre/fiala.h"
#include "tyre/pac2002.h"

namespace bdfcar::tyre {

// A tyre's data as read from a vehicle file.
using TyreParams = std::variant<FialaParams, Pac2002Params>;

double unloadedRadius(const TyreParams& p);
double width(const TyreParams& p);
double verticalStiffness(const TyreParams& p);  // N/m
double verticalDamping(const TyreParams& p);    // N s/m
// The largest force per unit load the tyre gives on ground of friction mu.
double peakFriction(const TyreParams& p, double mu);
// Its cornering stiffness (N/rad, the lateral force's slope at zero slip
// angle) at normal load Fz: Fiala's C_alpha, the Magic Formula's K_y there.
double corneringStiffness(const TyreParams& p, double Fz);
// Its contact geometry (point or enveloping, tyre/envelope.h).
const EnvelopeSpec& contact(const TyreParams& p);

// One tyre: its model with its data. `previous` are the transient slips at
// the last accepted step, h the time since then (the evaluation integrates
// them by backward Euler, so it is implicit in the current state). `load`:
// a normal load given by the model (the planar vehicle's load transfer)
// instead of the one from the tyre's deflection; the deflection is then
// load / vertical stiffness (the rolling radius follows the load).
class Tyre {
 public:
  explicit Tyre(const TyreParams& p);
  TyreOutput evaluate(const WheelKinematics& wheel, const ContactPlane& ground, const SlipState& previous,
                      double h, std::optional<double> load = std::nullopt) const;
  // The same into out, every field of it (the step's path: no output
  // copied); T double or ad::Dual (a closed form's Jacobian, autodiff.h).
  template <typename T>
  void evaluate(const WheelKinematicsT<T>& wheel, const ContactPlaneT<T>& ground, const SlipState& previous, double h,
                std::optional<T> load, TyreOutputT<T>& out) const;
  double unloadedRadius() const { return radius_; }

 private:
  std::variant<FialaTyre, Pac2002Tyre> model_;
  double radius_;
};

}  // namespace bdfcar::tyre
