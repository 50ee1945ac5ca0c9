#include "scenario/iso3888_course.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include "portable_math.h"

namespace bdfcar::scenario {

Iso3888Course makeIso3888Course(double w, double startX, double centreY, int part) {
  Iso3888Course c;
  c.vehicleWidth = w;
  c.part = part;
  if (part == 2) {
    const double w1 = 1.1 * w + 0.25, w3 = w + 1.0, w5 = std::min(1.3 * w + 0.25, 3.0);
    const double rightEdge = centreY - 0.5 * w1;
    double x = startX;
    c.lanes[0] = {x, x + 12.0, centreY, w1};
    x += 12.0 + 13.5;
    c.lanes[1] = {x, x + 11.0, rightEdge + w1 + 1.0 + 0.5 * w3, w3};
    x += 11.0 + 12.5;
    c.lanes[2] = {x, x + 12.0, rightEdge + 0.5 * w5, w5};
    c.startX = startX;
    c.endX = x + 12.0;
    return c;
  }
  const double w1 = 1.1 * w + 0.25, w3 = 1.2 * w + 0.25, w5 = 1.3 * w + 0.25;
  const double rightEdge = centreY - 0.5 * w1;  // datum: entry lane right-hand cone line
  double x = startX;
  c.lanes[0] = {x, x + 15.0, centreY, w1};
  x += 15.0 + 30.0;
  c.lanes[1] = {x, x + 25.0, rightEdge + 3.5 + 0.5 * w3, w3};
  x += 25.0 + 25.0;
  c.lanes[2] = {x, x + 15.0, rightEdge + 0.5 * w5, w5};
  c.startX = startX;
  c.endX = x + 15.0;
  return c;
}

const CourseLane* Iso3888Course::laneAt(double x) const {
  for (const CourseLane& l : lanes)
    if (x >= l.x0 && x <= l.x1) return &l;
  return nullptr;
}

bool Iso3888Course::contains(double x, double y) const {
  const CourseLane* l = laneAt(x);
  return !l || std::abs(y - l->centreY) <= 0.5 * l->width;
}

std::vector<Eigen::Vector3d> Iso3888Course::cones(double spacing) const {
  std::vector<Eigen::Vector3d> out;
  for (const CourseLane& l : lanes) {
    const int n = std::max(1, static_cast<int>(std::ceil((l.x1 - l.x0) / spacing)));
    for (int i = 0; i <= n; ++i) {
      const double x = l.x0 + (l.x1 - l.x0) * i / n;
      out.emplace_back(x, l.centreY + 0.5 * l.width + kConeBaseRadius, 0.0);
      out.emplace_back(x, l.centreY - 0.5 * l.width - kConeBaseRadius, 0.0);
    }
  }
  return out;
}

double Iso3888Course::referenceY(double x) const {
  auto blend = [](double y0, double y1, double s) { return y0 + (y1 - y0) * 0.5 * (1 - pm::cos(std::numbers::pi * s)); };
  const CourseLane &a = lanes[0], &b = lanes[1], &e = lanes[2];
  if (x <= a.x1) return a.centreY;
  if (x < b.x0) return blend(a.centreY, b.centreY, (x - a.x1) / (b.x0 - a.x1));
  if (x <= b.x1) return b.centreY;
  if (x < e.x0) return blend(b.centreY, e.centreY, (x - b.x1) / (e.x0 - b.x1));
  return e.centreY;
}

double Iso3888Course::drivingLineY(double x, double carWidth, double marginUse) const {
  auto blend = [](double y0, double y1, double s) { return y0 + (y1 - y0) * 0.5 * (1 - pm::cos(std::numbers::pi * s)); };
  const CourseLane &a = lanes[0], &b = lanes[1], &e = lanes[2];
  auto spare = [&](const CourseLane& l) { return marginUse * std::max(0.0, 0.5 * (l.width - carWidth)); };
  const double side = b.centreY > a.centreY ? 1.0 : -1.0;  // the side lane lies to this side
  // Lane positions: towards the next lane on entry and exit of the side lane.
  const double yA = a.centreY + side * spare(a);
  const double yB1 = b.centreY - side * spare(b), yB2 = b.centreY - side * spare(b);
  const double yE = e.centreY + side * spare(e);
  if (x <= a.x1) return yA;
  if (x < b.x0) return blend(yA, yB1, (x - a.x1) / (b.x0 - a.x1));
  if (x <= b.x1) return yB2;
  if (x < e.x0) return blend(yB2, yE, (x - b.x1) / (e.x0 - b.x1));
  return yE;
}

}  // namespace bdfcar::scenario
