#include "tyre/envelope.h"

#include <algorithm>
#include <cmath>

#include "autodiff.h"

namespace bdfcar::tyre {

double staticContactLength(double R0, double kz, double load) {
  const double delta = std::clamp(load / kz, 0.0, R0);
  return 2.0 * std::sqrt(std::max(0.0, 2.0 * R0 * delta - delta * delta));
}

Envelope resolveEnvelope(const EnvelopeSpec& s, double R0, double kz, double staticLoad) {
  Envelope e;
  e.on = s.on;
  e.a = s.halfLength > 0 ? s.halfLength : R0;
  e.b = s.halfHeight > 0 ? s.halfHeight : R0;
  e.c = s.order;
  e.base = s.base > 0 ? s.base : staticContactLength(R0, kz, staticLoad);
  e.spacing = s.spacing;
  e.dual = e.c / (e.c - 1.0);
  return e;
}

namespace {

// The functions below take the cam's position s as a scalar type T (double
// on the step's path, ad::Dual for a closed form's Jacobian): the profile's
// samples are data, the cams' heights and slopes functions of s.

// The cam's lower contour below its centre at u = x / a: b (1 - g(u)), with
// g = (1 - |u|^c)^(1/c). Returned: -b (1 - g), the contour's height over
// its lowest point (<= 0).
template <typename T>
T contourRise(const Envelope& e, const T& u) {
  using std::abs;
  using std::pow;
  if (e.c == 2.0) return e.b * (ad::sqrt0(ad::max(0.0, T(1.0 - u * u))) - 1.0);
  const T x = pow(T(abs(u)), e.c);
  return e.b * (pow(ad::max(0.0, T(1.0 - x)), 1.0 / e.c) - 1.0);
}

// An upper bound of contourRise: 1 - (1 - x)^(1/c) >= x / c for x in [0, 1].
double contourRiseBound(const Envelope& e, double u) {
  if (e.c == 2.0) return -0.5 * e.b * u * u;
  return -e.b * std::pow(std::abs(u), e.c) / e.c;
}

// The cam's support function in direction (a m, b): the dual norm of the
// superellipse's, exponent q = c / (c - 1). Resting on a line of slope m the
// cam's lowest point stands this less b above the line under its centre.
template <typename T>
T support(const Envelope& e, const T& m) {
  using std::abs;
  using std::pow;
  // The square root of the sum of squares, not hypot (glibc's costs several
  // times more, and camHeight takes one per segment under the cam): a m and
  // b are slopes times tenths of a metre, far from overflow or underflow.
  if (e.c == 2.0) {
    const T x = e.a * m;
    return ad::sqrt0(T(x * x + e.b * e.b));
  }
  return pow(T(pow(T(abs(T(e.a * m))), e.dual) + std::pow(e.b, e.dual)), 1.0 / e.dual);
}

template <typename T>
T slopeOffset(const Envelope& e, const T& m) {
  return ad::value(m) == 0.0 ? T(0.0) : T(support(e, m) - e.b);
}

// Where on the cam (u = x / a) its contour has slope m: the support
// function's maximiser, sign(m) |a m|^(q-1) / support^(q-1).
double tangentPoint(const Envelope& e, double m, double sup) {
  if (e.c == 2.0) return e.a * m / sup;
  return std::copysign(std::pow(std::abs(e.a * m) / sup, e.dual - 1.0), m);
}

}  // namespace

void findLine(RoadProfile& p) {
  p.linear = false;
  p.slope = 0;
  if (!p.valid || p.n < 2) return;
  const double m = (p.z[p.n - 1] - p.z[0]) / ((p.n - 1) * p.ds);
  for (int k = 0; k < p.n; ++k)
    if (!(std::abs(p.z[k] - (p.z[0] + m * (k * p.ds))) <= 1e-9)) return;  // no ground fails too
  p.linear = true;
  p.slope = m;
}

template <typename T>
T camHeight(const Envelope& e, const RoadProfile& p, const T& sT) {
  const double s = ad::value(sT);
  // On a straight road the cam stands its support function less b above it.
  if (p.linear && s - e.a >= p.s0 && s + e.a <= p.s0 + (p.n - 1) * p.ds)
    return p.z[0] + p.slope * (sT - p.s0) + slopeOffset(e, p.slope);
  // The cam rests on the profile, linear between its samples: its lowest
  // point as high as any point of the road under it asks. On a segment the
  // highest such point is where the contour's slope is the segment's (when
  // that falls inside it, in closed form: the support function) or an end
  // (a sample: z_k plus the contour's rise there). Exact for the piecewise
  // linear road, so a level or evenly sloped road reads without a ripple
  // between samples. The bounds and the choice of the highest by value: a
  // Dual s carries the derivative of the term that wins.
  const int lo = std::max(0, static_cast<int>(std::ceil((s - e.a - p.s0) / p.ds)));
  const int hi = std::min(p.n - 1, static_cast<int>(std::floor((s + e.a - p.s0) / p.ds)));
  if (lo > hi) return T(RoadProfile::kNoGround);
  // The samples around the cam's centre first: the bounds then skip most others.
  const int mid = std::clamp(static_cast<int>(std::floor((s - p.s0) / p.ds)), lo, hi);
  const double inv = 1.0 / e.a;
  T best = T(RoadProfile::kNoGround);
  const auto sample = [&](int k) {
    if (p.z[k] <= ad::value(best)) return;  // the rise is never positive
    const double u = (p.s0 + k * p.ds - s) * inv;
    if (p.z[k] + contourRiseBound(e, u) <= ad::value(best)) return;
    best = ad::max(best, T(p.z[k] + contourRise(e, T((p.s0 + k * p.ds - sT) * inv))));
  };
  const auto segment = [&](int k) {  // from sample k to k + 1, both under the cam
    const double z0 = p.z[k], z1 = p.z[k + 1];
    if (std::max(z0, z1) <= ad::value(best) || std::min(z0, z1) <= 0.5 * RoadProfile::kNoGround) return;
    const double m = (z1 - z0) / p.ds, sup = support(e, m);
    const double x = s + e.a * tangentPoint(e, m, sup) - (p.s0 + k * p.ds);  // the tangent point along the segment
    if (x < 0 || x > p.ds) return;
    best = ad::max(best, T(z0 + m * (sT - (p.s0 + k * p.ds)) + sup - e.b));
  };
  // Outward from the centre, each side until what is left on it cannot
  // win: no road under the cam is above the highest sample, and an item
  // (a sample and the segment on its inner side) at distance d from the
  // centre stands at most that plus the rise bound at d (a nanometre's
  // margin for rounding, so that what is left out never ties). On relief of
  // a few centimetres the cam's middle decides, and the rest is not read.
  double top = RoadProfile::kNoGround;
  for (int k = lo; k <= hi; ++k) top = std::max(top, p.z[k]);
  constexpr double kMargin = 1e-9;
  sample(mid);
  if (mid + 1 <= hi) {
    sample(mid + 1);
    segment(mid);
  }
  // An item: a sample and the segment on its inner side, over
  // [x_seg, x_seg + ds]; false (and nothing read) where it cannot win.
  const auto item = [&](int at, int seg) {
    const double x0 = p.s0 + seg * p.ds, d = std::max({0.0, x0 - s, s - (x0 + p.ds)});
    if (top + contourRiseBound(e, d * inv) + kMargin <= ad::value(best)) return false;
    sample(at);
    segment(seg);
    return true;
  };
  for (int left = mid - 1, right = mid + 2; left >= lo || right <= hi;) {
    if (left >= lo) left = item(left, left) ? left - 1 : lo - 1;
    if (right <= hi) right = item(right, right - 1) ? right + 1 : hi + 1;
  }
  return best;
}

template double camHeight(const Envelope&, const RoadProfile&, const double&);

template <typename T>
bool effectiveRoad(const Envelope& e, const RoadProfile& p, const Vec3T<T>& centre, EffectiveRoadT<T>& out) {
  if (!p.valid) return false;
  const Eigen::Matrix<T, 2, 1> r = centre.template head<2>() - p.origin;
  const T s = r.dot(p.heading);
  // A wheel far off its step's profile (or a diverged state) finds no road.
  if (!(std::abs(ad::value(s)) < 1e3)) return false;
  const T lateral = p.heading.x() * r.y() - p.heading.y() * r.x();  // to the heading's left
  const T front = camHeight(e, p, T(s + 0.5 * e.base));
  const T rear = camHeight(e, p, T(s - 0.5 * e.base));
  const bool hasFront = ad::value(front) > 0.5 * RoadProfile::kNoGround;
  const bool hasRear = ad::value(rear) > 0.5 * RoadProfile::kNoGround;
  if (!hasFront && !hasRear) return false;
  // One cam over a void (a wheel rolling off an edge): the other alone, level.
  const T slope = hasFront && hasRear ? T((front - rear) / e.base) : T(0.0);
  const T mean = hasFront && hasRear ? T(0.5 * (front + rear)) : (hasFront ? front : rear);
  // The lateral slope where the wheel is, between the profile's samples.
  const T x = ad::clamp(T((s - p.s0) / p.ds), 0.0, static_cast<double>(p.n - 1));
  const int k = std::min(static_cast<int>(ad::value(x)), p.n - 2);
  const T f = x - k;
  out.lateralSlope = p.n > 1 ? T((1 - f) * p.cross[k] + f * p.cross[k + 1]) : T(p.cross[0]);
  out.forwardSlope = slope;
  out.height = mean - slopeOffset(e, slope) + out.lateralSlope * lateral;
  return true;
}

template <typename T>
ContactPlaneT<T> effectivePlane(const Envelope& e, const RoadProfile& p, const Vec3T<T>& centre) {
  ContactPlaneT<T> plane;
  EffectiveRoadT<T> road;
  if (!effectiveRoad(e, p, centre, road)) return plane;
  plane.valid = true;
  plane.point = Vec3T<T>(centre.x(), centre.y(), road.height);
  const Eigen::Vector3d forward(p.heading.x(), p.heading.y(), 0), left(-p.heading.y(), p.heading.x(), 0);
  plane.normal = (Vec3T<T>(Eigen::Vector3d::UnitZ()) - road.forwardSlope * forward - road.lateralSlope * left).normalized();
  plane.friction = p.friction;
  return plane;
}

template bool effectiveRoad(const Envelope&, const RoadProfile&, const Vec3T<double>&, EffectiveRoadT<double>&);
template ContactPlaneT<double> effectivePlane(const Envelope&, const RoadProfile&, const Vec3T<double>&);
template ContactPlaneT<ad::Dual> effectivePlane(const Envelope&, const RoadProfile&, const Vec3T<ad::Dual>&);

}  // namespace bdfcar::tyre
