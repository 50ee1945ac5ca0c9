// A track described by its centre line instead of a mesh file: straights and
// arcs joined tangentially from the origin heading along +x, a flat ribbon
// of a given width at z = 0 with painted edge lines, and optional curbs
// beside the arcs. Built at load into a triangle mesh whose triangles carry
// their material (asphalt, paint, red and white curb) for the renderer; the
// tyres read one friction over it all. A circuit (closed) must end where it
// started, heading the same way, within kClosureGap / kClosureAngle.
// Deterministic: same parameters, same bits.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "terrain/terrain_data.h"

namespace bdfcar::terrain {

constexpr double kClosureGap = 0.5;        // m
constexpr double kClosureAngle = 0.01745;  // rad (1 degree)

struct TrackSegment {
  enum class Curbs { None, Inside, Outside, Both };
  double length = 0.0;  // straight: its length, m; arc: 0 (radius * |angle|)
  double radius = 0.0;  // arc radius of the centre line, m; 0: a straight
  double angle = 0.0;   // arc: turn angle, rad, positive to the left
  Curbs curbs = Curbs::None;  // arcs only: inside and/or outside of the turn
  double arcLength() const { return radius > 0 ? radius * std::abs(angle) : length; }
};

struct Track {
  double width = 10.0;       // asphalt from edge to edge, m
  double lineWidth = 0.15;   // painted edge lines, m (0: none)
  double curbWidth = 1.0;    // m, beyond the edge
  double curbHeight = 0.04;  // m, flat top; its faces rise over kCurbRise
  double cell = 2.0;         // longest chord along an arc, m
  bool closed = false;
  Material surface = Material::Asphalt;
  std::vector<TrackSegment> segments;
};

// A point of the centre line: position, heading (rad), arc length (m) and segment.
struct CentreLinePoint {
  Eigen::Vector2d p = Eigen::Vector2d::Zero();
  double heading = 0.0, s = 0.0;
  int segment = 0;
};

// The centre line sampled at every segment end and at most `cell` apart
// along arcs (1 m where curbs are drawn, for their stripes).
std::vector<CentreLinePoint> sampleCentreLine(const Track& track);

// Where the centre line ends against where it began: distance (m) and
// heading difference wrapped to (-pi, pi] (rad).
void closureError(const Track& track, double& gap, double& angle);

// The ribbon, its edge lines and its curbs as a mesh in `data` (kind Mesh,
// triangleMaterials filled), and the centre line in data.centreLine.
// std::invalid_argument if the track has no segments or a circuit does not close.
void buildTrackMesh(const Track& track, TerrainData& data);

}  // namespace bdfcar::terrain
