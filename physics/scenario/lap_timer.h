// Lap timing on a closed track (issue 30): the car's progress along the
// track's centre line, laps timed at the start line (the centre line's first
// point), sectors at equal distances, the best lap, and the delta of the lap
// under way against the best at the same distance.
//
// Times are interpolated between samples to the instant the car's centre of
// mass crosses a line (a 10 ms tick at 60 km/h is 17 cm: without it the
// times would jitter by a tick). The lap before the first crossing is the
// out lap, not timed, unless the car starts on the grid: within
// kStandingStart past the line, lap 1 starts with the first sample. A lap counts when it passed every sector in order;
// it is invalid (timed, shown, never the best) when the centre of mass went
// more than kCutMargin beyond the road's edge (all four wheels off: a cut).
// Driving back over the start line abandons the lap under way.
//
// The ghost: the best lap's path (the centre of mass and heading every
// kGhostStep of lap time), for a car drawn where the best lap was at the
// same time into the lap.
//
// A value type, copied into a run's snapshots: a rewind rewinds the timing
// too. The track geometry and the best lap's path are shared between the copies.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace bdfcar::scenario {

// A lap time as a timing screen shows it: "1:52.341" (m:ss.sss).
std::string lapClock(double seconds);

struct LapRecord {
  int number = 0;               // 1 = the first timed lap
  double time = 0;              // s
  std::vector<double> sectors;  // s, each sector's own time
  bool valid = true;            // false: cut the track
};

// The laps as a CSV table (lap, time_s, sector_1_s ..., valid, best: the
// results file of `--laps`), and as lines for a terminal ("" with none).
std::string lapsCsv(const std::vector<LapRecord>& laps, int sectors);
std::string lapsSummary(const std::vector<LapRecord>& laps);
// Writes lapsCsv to `path` as every output is written (row_file.h: whole or
// not at all); throws OutputError.
void writeLapFile(const std::string& path, const std::vector<LapRecord>& laps, int sectors);

// Where the ghost is: the best lap's car at a time into the lap.
struct GhostPose {
  double x = 0, y = 0, yaw = 0;  // m, m, rad (world)
};

class LapTimer {
 public:
  static constexpr double kCutMargin = 1.0;  // m beyond the road's edge
  static constexpr double kProfileStep = 5.0;  // m between the delta's samples
  static constexpr double kStandingStart = 20.0;  // m past the line: the first sample starts lap 1
  static constexpr double kGhostStep = 0.1;       // s of lap time between the ghost's points

  // line: the centre line, closed (its last point joins its first), the
  // start line at its first point, driven in the order of its points;
  // width: the road's (0: unknown, no cut is judged); sectors >= 1.
  LapTimer(const std::vector<Eigen::Vector2d>& line, double width, int sectors);

  // The car's centre of mass (world x, y) and heading at time t; times increase.
  void update(double t, const Eigen::Vector2d& com, double yaw = 0.0);
  // The best lap's car at the same time into the lap under way as t (none
  // without a best lap, on the out lap, or once the lap under way is slower
  // than the whole best lap).
  std::optional<GhostPose> ghost(double t) const;

  int lap() const { return lap_; }  // the lap under way: 0 the out lap, then 1, 2, ...
  // Time into the lap under way at t (s); negative on the out lap.
  double lapTime(double t) const { return lap_ > 0 && running_ ? t - lapStart_ : -1.0; }
  int sector() const { return sectorsDone_ + 1; }  // the sector under way, 1..sectors
  int sectors() const { return sectorCount_; }
  bool valid() const { return valid_; }            // the lap under way, so far
  double distance() const { return s_; }           // m along the line from the start
  double length() const { return geometry_->length; }
  double offset() const { return offset_; }         // m from the centre line, + left
  // The lap under way's time less the best lap's at the same distance (s,
  // + slower); NaN without a best lap or on the out lap.
  double delta(double t) const;
  const std::vector<LapRecord>& laps() const { return laps_; }
  // The fastest valid lap, and the last lap completed (nullptr: none yet).
  const LapRecord* best() const { return best_ < 0 ? nullptr : &laps_[best_]; }
  const LapRecord* last() const { return laps_.empty() ? nullptr : &laps_.back(); }

 private:
  struct Geometry {
    std::vector<Eigen::Vector2d> points;  // closed: the last segment joins the last point to the first
    std::vector<double> along;            // distance of each point from the first
    double length = 0;
  };
  // The nearest point of the line: its distance along and signed offset;
  // searched near the last one, or along the whole line when far from it.
  void project(const Eigen::Vector2d& p, double& along, double& offset);
  void crossStart(double at);
  void recordProfile(double from, double to, double tFrom, double tTo);

  std::shared_ptr<const Geometry> geometry_;
  double width_ = 0;
  int sectorCount_ = 1;
  int segment_ = -1;  // the segment the car was nearest last time
  double s_ = 0, offset_ = 0, t_ = 0;
  Eigen::Vector2d lastCom_ = Eigen::Vector2d::Zero();  // the last sample's, for the ghost's path
  double lastYaw_ = 0;
  bool started_ = false;  // a sample seen
  int lap_ = 0;
  bool running_ = false;  // a timed lap under way (false on the out lap and after driving back over the line)
  double lapStart_ = 0, lastSplit_ = 0;
  int sectorsDone_ = 0;
  std::vector<double> splits_;
  bool valid_ = true;
  std::vector<double> profile_, bestProfile_;  // lap time at each kProfileStep of distance
  std::vector<GhostPose> path_;                // the lap under way's, every kGhostStep from its start
  std::shared_ptr<const std::vector<GhostPose>> bestPath_;
  std::vector<LapRecord> laps_;
  int best_ = -1;
};

}  // namespace bdfcar::scenario
