#include "scenario/course_line.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scenario/course_judge.h"
#include "portable_math.h"

namespace bdfcar::scenario {

namespace {

// The quintic smoothstep and its first two derivatives.
double step(double u) { return u * u * u * (10 + u * (-15 + 6 * u)); }
double stepSlope(double u) { return 30 * u * u * (1 + u * (-2 + u)); }
double stepCurve(double u) { return 60 * u * (1 + u * (-3 + 2 * u)); }
constexpr double kPeakStepCurve = 5.773502691896258;  // max |s''| = 10 / sqrt(3), at u = (3 - sqrt(3)) / 6

struct Change {
  double y0, y1, xs, xe;
};

// Where x lies: before the first change's start, in a change, or after.
template <class F>
double piecewise(const CourseLine& l, double x, F f, double flat0, double flat1, double flat2) {
  const Change a{l.yEntry, l.ySide, l.xs1, l.xe1}, b{l.ySide, l.yExit, l.xs2, l.xe2};
  if (x <= a.xs) return flat0;
  if (x < a.xe) return f(a, (x - a.xs) / (a.xe - a.xs));
  if (x <= b.xs) return flat1;
  if (x < b.xe) return f(b, (x - b.xs) / (b.xe - b.xs));
  return flat2;
}

// The footprint carried along the line (heading its slope) through a judge
// over [x0, x1] of the reference point's x: clean?
bool clean(const Iso3888Course& course, const CourseLine& l, double length, double width, const Eigen::Vector2d& centre,
           double x0, double x1) {
  CourseJudge judge(course, length, width, Eigen::Vector3d(centre.x(), centre.y(), 0.0));
  vehicle::VehicleSample s;
  for (double x = x0; x <= x1; x += 0.05) {
    s.yaw = pm::atan(l.slope(x));
    s.chassisRotation = Eigen::Matrix3d::Identity();
    s.chassisRotation(0, 0) = s.chassisRotation(1, 1) = pm::cos(s.yaw);
    s.chassisRotation(1, 0) = pm::sin(s.yaw);
    s.chassisRotation(0, 1) = -s.chassisRotation(1, 0);
    s.chassisOrigin = Eigen::Vector3d(x, l.y(x), 0.0);
    judge.update(s);
    if (!judge.result().passed) return false;
  }
  return true;
}

}  // namespace

double CourseLine::y(double x) const {
  return piecewise(*this, x, [](const Change& c, double u) { return c.y0 + (c.y1 - c.y0) * step(u); }, yEntry, ySide,
                   yExit);
}

double CourseLine::slope(double x) const {
  return piecewise(*this, x, [](const Change& c, double u) { return (c.y1 - c.y0) * stepSlope(u) / (c.xe - c.xs); },
                   0.0, 0.0, 0.0);
}

double CourseLine::curvature(double x) const {
  const double d2 = piecewise(
      *this, x, [](const Change& c, double u) { return (c.y1 - c.y0) * stepCurve(u) / ((c.xe - c.xs) * (c.xe - c.xs)); },
      0.0, 0.0, 0.0);
  const double d1 = slope(x);
  return d2 / std::pow(1 + d1 * d1, 1.5);
}

namespace {
CourseLine lineWithMargin(const Iso3888Course& course, double length, double width, const Eigen::Vector2d& centre,
                          double margin) {
  const CourseLane &A = course.lanes[0], &B = course.lanes[1], &E = course.lanes[2];
  const double L = length + 2 * margin, W = width + 2 * margin;
  // A lane's lines: across its spare width (none when the grown car does not fit).
  auto across = [&](const CourseLane& lane) {
    std::vector<double> ys;
    const double spare = std::max(0.0, 0.5 * (lane.width - W));
    for (int i = -2; i <= 2; ++i) ys.push_back(lane.centreY + spare * i / 2.0);
    return ys;
  };
  // Each change's extent on a grid over the lanes it joins (its start in the
  // lane it leaves, its end in the lane it enters), the side lane split at its
  // middle so that the two changes are searched apart.
  const double mid = 0.5 * (B.x0 + B.x1);
  auto grid = [](double lo, double hi, int n) {
    std::vector<double> xs;
    for (int i = 0; i <= n; ++i) xs.push_back(lo + (hi - lo) * i / n);
    return xs;
  };
  constexpr int kSteps = 16;
  CourseLine best;
  best.peakCurvature = std::numeric_limits<double>::infinity();
  for (double ySide : across(B)) {
    // The first change: the least peak |y''| over the grid that is clean up to
    // the side lane's middle; then the second from there.
    double k1 = std::numeric_limits<double>::infinity(), k2 = k1;
    CourseLine c1, c2;
    for (double yEntry : across(A))
      for (double xs : grid(A.x0, A.x1, kSteps))
        for (double xe : grid(B.x0, mid, kSteps / 2)) {
          const double k = kPeakStepCurve * std::abs(ySide - yEntry) / ((xe - xs) * (xe - xs));
          if (k >= k1) continue;
          CourseLine l;
          l.yEntry = yEntry;
          l.ySide = l.yExit = ySide;
          l.xs1 = xs;
          l.xe1 = xe;
          l.xs2 = l.xe2 = course.endX + 1e3;  // no second change yet
          if (!clean(course, l, L, W, centre, course.startX - L, mid)) continue;
          k1 = k;
          c1 = l;
        }
    if (!std::isfinite(k1)) continue;
    for (double yExit : across(E))
      for (double xs : grid(mid, B.x1, kSteps / 2))
        for (double xe : grid(E.x0, E.x1, kSteps)) {
          const double k = kPeakStepCurve * std::abs(yExit - ySide) / ((xe - xs) * (xe - xs));
          if (k >= k2) continue;
          CourseLine l = c1;
          l.yExit = yExit;
          l.xs2 = xs;
          l.xe2 = xe;
          if (!clean(course, l, L, W, centre, mid, course.endX + L)) continue;
          k2 = k;
          c2 = l;
        }
    if (!std::isfinite(k2)) continue;
    const double peak = std::max(k1, k2);
    if (peak < best.peakCurvature) {
      best = c2;
      best.peakCurvature = peak;
      best.feasible = true;
    }
  }
  best.margin = margin;
  return best;
}
}  // namespace

CourseLine computeCourseLine(const Iso3888Course& course, double length, double width, const Eigen::Vector2d& centre,
                             double margin) {
  // The margin asked for, or the largest of its halvings that leaves a clean line.
  for (double m = margin; m > 0.01; m *= 0.5) {
    const CourseLine l = lineWithMargin(course, length, width, centre, m);
    if (l.feasible) return l;
  }
  CourseLine best = lineWithMargin(course, length, width, centre, 0.0);
  if (!best.feasible) {
    const CourseLane &A = course.lanes[0], &B = course.lanes[1], &E = course.lanes[2];
    // No clean line for this footprint and margin: the lane centres with the
    // changes over the free sections (the driver still gets a line to follow).
    best = CourseLine{};
    best.yEntry = A.centreY;
    best.ySide = B.centreY;
    best.yExit = E.centreY;
    best.xs1 = A.x1;
    best.xe1 = B.x0;
    best.xs2 = B.x1;
    best.xe2 = E.x0;
    best.peakCurvature = std::max(kPeakStepCurve * std::abs(B.centreY - A.centreY) / ((B.x0 - A.x1) * (B.x0 - A.x1)),
                                  kPeakStepCurve * std::abs(E.centreY - B.centreY) / ((E.x0 - B.x1) * (E.x0 - B.x1)));
  }
  return best;
}

}  // namespace bdfcar::scenario
