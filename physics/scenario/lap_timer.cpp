#include "scenario/lap_timer.h"

#include "scenario/row_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace bdfcar::scenario {

namespace {

constexpr int kSearchWindow = 40;  // segments either side of the last nearest one
constexpr double kLost = 30.0;     // m: farther from the line near the last segment, search it all

}  // namespace

std::string lapClock(double seconds) {
  const long ms = std::lround(std::max(0.0, seconds) * 1000.0);
  char text[32];
  std::snprintf(text, sizeof text, "%ld:%02ld.%03ld", ms / 60000, (ms / 1000) % 60, ms % 1000);
  return text;
}

namespace {
int bestOf(const std::vector<LapRecord>& laps) {
  int best = -1;
  for (size_t i = 0; i < laps.size(); ++i)
    if (laps[i].valid && (best < 0 || laps[i].time < laps[best].time)) best = static_cast<int>(i);
  return best;
}
}  // namespace

std::string lapsCsv(const std::vector<LapRecord>& laps, int sectors) {
  std::string out = "lap,time_s";
  for (int k = 1; k <= sectors; ++k) out += ",sector_" + std::to_string(k) + "_s";
  out += ",valid,best\n";
  const int best = bestOf(laps);
  char text[32];
  for (size_t i = 0; i < laps.size(); ++i) {
    const LapRecord& r = laps[i];
    out += std::to_string(r.number);
    std::snprintf(text, sizeof text, ",%.3f", r.time);
    out += text;
    for (double s : r.sectors) {
      std::snprintf(text, sizeof text, ",%.3f", s);
      out += text;
    }
    out += r.valid ? ",1" : ",0";
    out += static_cast<int>(i) == best ? ",1\n" : ",0\n";
  }
  return out;
}

std::string lapsSummary(const std::vector<LapRecord>& laps) {
  std::string out;
  const int best = bestOf(laps);
  for (size_t i = 0; i < laps.size(); ++i) {
    const LapRecord& r = laps[i];
    out += "lap " + std::to_string(r.number) + ": " + lapClock(r.time) + " (sectors";
    char text[32];
    for (double s : r.sectors) {
      std::snprintf(text, sizeof text, " %.3f", s);
      out += text;
    }
    out += " s)";
    if (!r.valid) out += ", cut: not counted";
    if (static_cast<int>(i) == best) out += ", best";
    out += "\n";
  }
  return out;
}

void writeLapFile(const std::string& path, const std::vector<LapRecord>& laps, int sectors) {
  RowFile f(path);
  f.append(lapsCsv(laps, sectors));
  f.close();
}

LapTimer::LapTimer(const std::vector<Eigen::Vector2d>& line, double width, int sectors)
    : width_(width), sectorCount_(sectors) {
  if (line.size() < 3) throw std::invalid_argument("lap timing needs a closed centre line of at least 3 points");
  if (sectors < 1) throw std::invalid_argument("lap timing needs at least one sector");
  auto g = std::make_shared<Geometry>();
  g->points = line;
  if ((g->points.front() - g->points.back()).norm() < 1e-9) g->points.pop_back();  // closed by repeating the first
  g->along.resize(g->points.size());
  double s = 0;
  for (size_t i = 0; i < g->points.size(); ++i) {
    g->along[i] = s;
    s += (g->points[(i + 1) % g->points.size()] - g->points[i]).norm();
  }
  g->length = s;
  geometry_ = std::move(g);
}

void LapTimer::project(const Eigen::Vector2d& p, double& along, double& offset) {
  const Geometry& g = *geometry_;
  const int n = static_cast<int>(g.points.size());
  auto nearestIn = [&](int first, int count) {
    double best = std::numeric_limits<double>::infinity();
    for (int k = 0; k < count; ++k) {
      const int i = ((first + k) % n + n) % n;
      const Eigen::Vector2d a = g.points[i], d = g.points[(i + 1) % n] - a;
      const double u = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
      const Eigen::Vector2d r = p - (a + u * d);
      const double dist = r.norm();
      if (dist < best) {
        best = dist;
        segment_ = i;
        along = g.along[i] + u * d.norm();
        offset = d.x() * r.y() - d.y() * r.x() >= 0 ? dist : -dist;
      }
    }
    return best;
  };
  const int last = segment_;
  if (last < 0 || nearestIn(last - kSearchWindow, 2 * kSearchWindow + 1) > kLost) nearestIn(0, n);
}

void LapTimer::recordProfile(double from, double to, double tFrom, double tTo) {
  // The lap time at each profile distance passed between two samples.
  for (double x = profile_.size() * kProfileStep; x <= to && x >= from; x = profile_.size() * kProfileStep)
    profile_.push_back(tFrom + (to > from ? (x - from) / (to - from) : 0.0) * (tTo - tFrom) - lapStart_);
}

void LapTimer::crossStart(double at) {
  if (running_ && sectorsDone_ == sectorCount_ - 1) {
    LapRecord r;
    r.number = lap_;
    r.time = at - lapStart_;
    r.sectors = splits_;
    r.sectors.push_back(at - lastSplit_);
    r.valid = valid_;
    laps_.push_back(r);
    if (r.valid && (best_ < 0 || r.time < laps_[best_].time)) {
      best_ = static_cast<int>(laps_.size()) - 1;
      bestProfile_ = profile_;
      bestPath_ = std::make_shared<const std::vector<GhostPose>>(path_);
    }
  }
  ++lap_;
  running_ = true;
  lapStart_ = lastSplit_ = at;
  sectorsDone_ = 0;
  splits_.clear();
  valid_ = true;
  profile_.clear();
  path_.clear();
}

void LapTimer::update(double t, const Eigen::Vector2d& com, double yaw) {
  double s = 0, off = 0;
  project(com, s, off);
  offset_ = off;
  // The ghost's path: the pose at each kGhostStep of lap time, interpolated
  // between this sample and the last (heading the short way round).
  auto recordPath = [&](double until) {
    if (!running_) return;
    for (double at = lapStart_ + path_.size() * kGhostStep; at <= until; at = lapStart_ + path_.size() * kGhostStep) {
      const double u = t > t_ ? std::clamp((at - t_) / (t - t_), 0.0, 1.0) : 1.0;
      const double turn = std::remainder(yaw - lastYaw_, 2 * M_PI);
      path_.push_back({lastCom_.x() + u * (com.x() - lastCom_.x()), lastCom_.y() + u * (com.y() - lastCom_.y()),
                       lastYaw_ + u * turn});
    }
  };
  if (!started_) {
    started_ = true;
    s_ = s;
    t_ = t;
    lastCom_ = com;
    lastYaw_ = yaw;
    if (s < kStandingStart) {  // on the grid: a standing start, timed from here
      crossStart(t);
      recordProfile(0.0, s, t, t);
      recordPath(t);
    }
    return;
  }
  const double L = geometry_->length;
  double ds = s - s_;  // unwrapped: the car moves far less than half a lap between samples
  if (ds < -0.5 * L) ds += L;
  if (ds > 0.5 * L) ds -= L;
  const double from = s_, to = s_ + ds, t0 = t_;
  auto timeAt = [&](double x) { return t0 + (ds != 0.0 ? (x - from) / ds : 0.0) * (t - t0); };
  if (to >= L) {  // forward over the start line
    if (running_) {
      recordProfile(from, L, t0, timeAt(L));
      recordPath(timeAt(L));
    }
    crossStart(timeAt(L));
    recordProfile(0.0, to - L, timeAt(L), t);
    recordPath(t);
  } else if (to < 0.0) {  // back over it: the lap under way is abandoned
    running_ = false;
  } else if (running_) {
    // Sectors at equal distances, passed in order.
    const double boundary = (sectorsDone_ + 1) * L / sectorCount_;
    if (sectorsDone_ < sectorCount_ - 1 && from < boundary && to >= boundary) {
      const double at = timeAt(boundary);
      splits_.push_back(at - lastSplit_);
      lastSplit_ = at;
      ++sectorsDone_;
    }
    if (ds > 0) recordProfile(from, to, t0, t);
    recordPath(t);
  }
  if (width_ > 0 && std::abs(off) > 0.5 * width_ + kCutMargin) valid_ = false;
  s_ = s;
  t_ = t;
  lastCom_ = com;
  lastYaw_ = yaw;
}

std::optional<GhostPose> LapTimer::ghost(double t) const {
  if (!running_ || !bestPath_ || bestPath_->size() < 2) return std::nullopt;
  const double x = (t - lapStart_) / kGhostStep;
  if (x < 0) return std::nullopt;
  const size_t i = static_cast<size_t>(x);
  if (i + 1 >= bestPath_->size()) return std::nullopt;
  const GhostPose& a = (*bestPath_)[i];
  const GhostPose& b = (*bestPath_)[i + 1];
  const double u = x - static_cast<double>(i);
  return GhostPose{a.x + u * (b.x - a.x), a.y + u * (b.y - a.y), a.yaw + u * std::remainder(b.yaw - a.yaw, 2 * M_PI)};
}

double LapTimer::delta(double t) const {
  if (!running_ || bestProfile_.empty()) return std::numeric_limits<double>::quiet_NaN();
  const double x = s_ / kProfileStep;
  const size_t i = static_cast<size_t>(x);
  if (i + 1 >= bestProfile_.size()) return std::numeric_limits<double>::quiet_NaN();
  const double best = bestProfile_[i] + (x - i) * (bestProfile_[i + 1] - bestProfile_[i]);
  return (t - lapStart_) - best;
}

}  // namespace bdfcar::scenario
