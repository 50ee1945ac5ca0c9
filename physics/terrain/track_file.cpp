// Reading a generated track's centre line and cross-section from TOML.
#include "terrain/track_file.h"

#include <cstdio>
#include <numbers>

namespace bdfcar::terrain {

namespace {

using config::Range;
using config::Table;

constexpr double kDegree = std::numbers::pi / 180.0;

// One [[track.segments]] entry: a straight (`straight` = its length) or an
// arc (`radius` and `angle_deg`, positive to the left; `curbs` beside it).
TrackSegment readSegment(Table& t) {
  t.rejectUnknownKeys({"straight", "radius", "angle_deg", "curbs"});
  TrackSegment s;
  const bool straight = t.has("straight"), arc = t.has("radius") || t.has("angle_deg");
  t.require(straight != arc, straight ? "straight" : "radius",
            "either `straight` (a length) or `radius` and `angle_deg` (an arc), not both");
  if (straight) {
    s.length = t.numberIn("straight", {0.0, 1e5, true, false});
    t.require(!t.has("curbs"), "curbs", "curbs on arcs only");
    return s;
  }
  s.radius = t.numberIn("radius", {1.0, 1e5});
  s.angle = kDegree * t.numberIn("angle_deg", {-360.0, 360.0});
  t.require(s.angle != 0.0, "angle_deg", "a non-zero angle (positive turns left)");
  const std::string curbs = t.choice("curbs", {"none", "inside", "outside", "both"}, "none");
  s.curbs = curbs == "inside"    ? TrackSegment::Curbs::Inside
            : curbs == "outside" ? TrackSegment::Curbs::Outside
            : curbs == "both"    ? TrackSegment::Curbs::Both
                                 : TrackSegment::Curbs::None;
  return s;
}

}  // namespace

Track readTrack(Table t, Material surface) {
  t.rejectUnknownKeys({"width", "line_width", "curb_width", "curb_height", "cell", "closed", "segments"});
  Track track;
  track.surface = surface;
  track.width = t.numberIn("width", {1.0, 100.0});
  track.lineWidth = t.numberIn("line_width", {0.0, 1.0}, track.lineWidth);
  t.require(track.lineWidth <= 0.25 * track.width, "line_width", "at most a quarter of the width");
  track.curbWidth = t.numberIn("curb_width", {0.3, 5.0}, track.curbWidth);
  track.curbHeight = t.numberIn("curb_height", {0.0, 0.2}, track.curbHeight);
  track.cell = t.numberIn("cell", {0.1, 20.0}, track.cell);
  track.closed = t.boolean("closed", false);
  for (Table& s : t.tables("segments")) track.segments.push_back(readSegment(s));
  t.require(!track.segments.empty(), "segments", "at least one segment");
  for (const TrackSegment& s : track.segments)
    t.require(s.radius <= 0 || s.radius > 0.5 * track.width + (s.curbs != TrackSegment::Curbs::None ? track.curbWidth : 0.0),
              "segments", "arcs whose radius exceeds half the width (and the curb beside it)");
  if (track.closed) {
    double gap = 0, angle = 0;
    closureError(track, gap, angle);
    if (gap > kClosureGap || std::abs(angle) > kClosureAngle) {
      char what[200];
      std::snprintf(what, sizeof what,
                    "segments whose centre line ends where it starts, heading the same way (within %.1f m and "
                    "1 deg): it ends %.3f m away, %.3f deg off",
                    kClosureGap, gap, angle / kDegree);
      t.require(false, "closed", what);
    }
  }
  return track;
}

}  // namespace bdfcar::terrain
