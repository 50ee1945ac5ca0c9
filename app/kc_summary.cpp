#include "kc_summary.h"

#include <cmath>
#include <cstdio>

#include "config/units.h"
#include "vehicle/vehicle_sheet.h"

namespace bdfcar::app {

namespace {

using config::radToDeg;

template <typename... Args>
std::string format(const char* fmt, Args... args) {
  char text[512];
  std::snprintf(text, sizeof text, fmt, args...);
  return text;
}

// A row of four corner values, or '-' where there is none.
void cornerRow(std::string& out, const char* label, const vehicle::KcResult& r,
               double (*value)(const vehicle::KcCorner&), const char* numberFormat) {
  out += format("  %-44s", label);
  for (const vehicle::KcCorner& c : r.corner) {
    const double x = value(c);
    if (std::isfinite(x))
      out += format(numberFormat, x);
    else
      out += format("%10s", "-");
  }
  out += format("\n");
}

}  // namespace

std::string kcSummary(const vehicle::Vehicle& v, const std::string& path, const vehicle::KcResult& r) {
  std::string out;
  out += format("K&C rig: %s (%s)\n", v.spec.name.c_str(), path.c_str());
  out += format("  chassis held at design, the ground %.4f m under its frame; sweeps: parallel travel +-%.0f mm, "
              "body roll +-%.1f deg, full steer\n",
              v.spec.designHeight, 1000 * r.travelRange, radToDeg(r.rollRange));
  out += format("  wheelbase %.3f m, centre of mass %.3f m above the ground\n\n", r.wheelbase, r.comHeight);
  out += format("  %-44s%10s%10s%10s%10s\n", "at design (kinematics only)", "FL", "FR", "RL", "RR");
  using C = const vehicle::KcCorner&;
  cornerRow(out, "toe (deg, + in)", r, [](C c) { return radToDeg(c.toe); }, "%10.3f");
  cornerRow(out, "camber (deg, + top out)", r, [](C c) { return radToDeg(c.camber); }, "%10.3f");
  cornerRow(out, "bump steer (deg/m of toe)", r, [](C c) { return radToDeg(c.bumpSteer); }, "%10.2f");
  cornerRow(out, "camber gain (deg/m)", r, [](C c) { return radToDeg(c.camberGain); }, "%10.2f");
  cornerRow(out, "roll steer (deg of toe/deg of roll)", r, [](C c) { return c.rollSteer; }, "%10.4f");
  cornerRow(out, "roll camber (deg to ground/deg of roll)", r, [](C c) { return c.rollCamber; }, "%10.4f");
  cornerRow(out, "half-track change (mm/m, + outward)", r, [](C c) { return 1000 * c.halfTrackChange; }, "%10.1f");
  cornerRow(out, "wheel rate (N/m, springs)", r, [](C c) { return c.wheelRate; }, "%10.0f");
  cornerRow(out, "caster (deg, + top rearward)", r, [](C c) { return radToDeg(c.caster); }, "%10.3f");
  cornerRow(out, "kingpin inclination (deg, + top inboard)", r, [](C c) { return radToDeg(c.kingpinInclination); }, "%10.3f");
  cornerRow(out, "scrub radius (mm, + axis inboard)", r, [](C c) { return 1000 * c.scrubRadius; }, "%10.1f");
  cornerRow(out, "mechanical trail (mm, + axis ahead)", r, [](C c) { return 1000 * c.trail; }, "%10.1f");
  out += format("  motion ratios (dL/ds, spring-damper length per wheel travel):");
  for (const vehicle::KcCorner& c : r.corner)
    for (size_t k = 0; k < c.springNames.size(); ++k) out += format(" %s %.4f", c.springNames[k].c_str(), c.motionRatio[k]);
  out += format("\n\n  %-44s%10s%10s\n", "per axle", "front", "rear");
  out += format("  %-44s%10.4f%10.4f\n", "track (m)", r.axle[0].track, r.axle[1].track);
  out += format("  %-44s%10.1f%10.1f\n", "track change (mm/m of parallel travel)", 1000 * r.axle[0].trackChange,
              1000 * r.axle[1].trackChange);
  out += format("  %-44s%10.4f%10.4f\n", "roll centre (m above the ground)", r.axle[0].rollCentre, r.axle[1].rollCentre);
  out += format("  %-44s%10.3f%10.3f\n", "roll-centre migration (m/m of travel)", r.axle[0].rollCentreMigration,
              r.axle[1].rollCentreMigration);
  out += format("  %-44s%10.4f%10.4f\n", "roll steer (deg/deg, + toward the rising side)", r.axle[0].rollSteer,
              r.axle[1].rollSteer);
  out += format("\n  anti-dive (front, braking, %.0f %% of the brake torque front): %.1f %%\n", 100 * r.brakeFront,
              r.antiDive);
  out += format("  anti-squat (rear, driving): %.1f %%\n", r.antiSquat);
  out += format("  steering ratio %.2f:1 (wheels at design height); %s\n", r.steeringRatio,
              vehicle::ackermannText(r.ackermann).c_str());
  return out;
}

}  // namespace bdfcar::app
