#include "scenario/rung_certificate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <mutex>
#include <sstream>

#include "scenario/rung_runs.h"
#include "scenario/simulation.h"
#include "vehicle/derivation_cache.h"
#include "vehicle/ladder.h"
#include "vehicle/motion_ratio.h"

namespace bdfcar::scenario {

namespace {

constexpr double kG = 9.81;
constexpr double kSpeed = kRungRunSpeed;
constexpr double kRoadFriction = kRungRunFriction;

// Each quantity's difference is measured against the larger of the
// linkage's peak and a floor: a manoeuvre without a response in a quantity
// (no yaw in a straight-line stop) is measured against the quantity's
// scale, not against its noise.
constexpr double kYawRateFloor = 0.05;  // rad/s
constexpr double kAyFloor = 0.5;        // m/s^2
constexpr double kAngleFloor = 0.01;    // rad, roll and pitch

}  // namespace


std::vector<ScenarioSpec> certificateBattery(const ScenarioSpec& scene, const vehicle::Vehicle& linkage) {
  const double limit = tyre::peakFriction(linkage.wheel(0).tyre, kRoadFriction) * kG;
  const double full = 0.9 * std::abs(vehicle::roadWheelAnglePerSteer(linkage));
  const ScenarioSpec base = rungRunBase(scene);
  // The road-wheel angle for a share of the limit: a neutral-steering car's,
  // corrected once by the linkage's own steady response to it (an
  // understeering car needs more; the reached level is reported).
  auto steerFor = [&](double share) {
    const double neutral = std::min(full, linkage.spec.geometry.wheelbase * share * limit / (kSpeed * kSpeed));
    ScenarioSpec trial = base;
    trial.steering = roadWheelRamp(neutral);
    const double reached = std::abs(steadyState(runOnModel(trial, linkage, linkage)).ay);
    return reached > 0 ? std::min(full, neutral * share * limit / reached) : neutral;
  };
  std::vector<ScenarioSpec> b;
  const double low = steerFor(0.3);
  for (double share : {0.3, 0.6}) {
    ScenarioSpec s = base;
    s.name = "step steer " + std::string(share < 0.5 ? "0.3" : "0.6") + " of the limit";
    s.steering = roadWheelRamp(share < 0.5 ? low : steerFor(share));
    b.push_back(s);
  }
  {
    ScenarioSpec s = base;
    s.name = "sine steer 0.5 Hz";
    s.steering.kind = SignalSpec::Kind::Sine;
    s.steering.unit = SignalSpec::Unit::RoadWheelAngle;
    s.steering.start = 0.5;
    s.steering.duration = 2.0;
    s.steering.level = low * 0.4 / 0.3;
    b.push_back(s);
  }
  {
    // About 0.3 g of braking from the brakes' capacity (all four wheels).
    double capacity = 0;
    for (int w = 0; w < 4; ++w) capacity += linkage.wheel(w).brakeTorque;
    const double mass = linkage.model.totalMass(), radius = linkage.spec.geometry.wheelRadius;
    const double level = capacity > 0 ? std::clamp(0.3 * kG * mass * radius / capacity, 0.0, 1.0) : 0.0;
    ScenarioSpec s = base;
    s.name = "braking in a turn";
    s.duration = 4.5;
    s.steering = roadWheelRamp(low * 0.4 / 0.3);
    s.speedControl.profile.end = 2.0;
    s.brake = signalTable({2.0, 2.3}, {0.0, level});
    b.push_back(s);
  }
  {
    ScenarioSpec s = base;
    s.name = "full throttle from 5 m/s";
    s.initialSpeed = 5.0;
    s.speedControl.profile.target = 5.0;
    if (linkage.spec.powertrain || linkage.spec.maxDriveTorque > 0) {
      s.speedControl.enabled = false;
      s.throttle = signalTable({0.0, 0.2}, {0.0, 1.0});
    } else {
      // No engine: a speed hold asking for 0.4 g.
      s.speedControl.profile.rampTo = 5.0 + 0.4 * kG * s.duration;
      s.speedControl.profile.rampStart = 0.0;
      s.speedControl.profile.rampDuration = s.duration;
    }
    b.push_back(s);
  }
  {
    ScenarioSpec s = base;
    s.name = "stop and release on a 10 % grade";
    s.groundGrade = 0.10;
    s.initialSpeed = 0;
    s.settleTime = 0.5;
    s.duration = 6.0;
    s.speedControl.enabled = false;
    s.brake = signalTable({0.0, 3.0, 3.2}, {1.0, 1.0, 0.0});
    b.push_back(s);
  }
  return b;
}

double ManoeuvreError::worst(const char** quantity) const {
  const std::pair<double, const char*> q[] = {{yawRate, "yaw rate"}, {ay, "a_y"}, {roll, "roll"}, {z, "height"}};
  const auto* m = std::max_element(std::begin(q), std::end(q), [](auto& a, auto& b) { return a.first < b.first; });
  if (quantity) *quantity = m->second;
  return m->first;
}

const RungCertificate* LadderCertificate::find(vehicle::Fidelity f) const {
  for (const RungCertificate& r : rungs)
    if (r.rung == f) return &r;
  return nullptr;
}

namespace {

// RMS of the difference as % of the reference's peak (at least `floor`).
template <class Quantity>
double rmsPercent(const RunResult& ref, const RunResult& run, Quantity q, double floor) {
  const size_t n = std::min(ref.samples.size(), run.samples.size());
  double sum = 0, peak = floor;
  for (size_t i = 0; i < n; ++i) {
    const double d = q(ref.samples[i]) - q(run.samples[i]);
    sum += d * d;
    peak = std::max(peak, std::abs(q(ref.samples[i])));
  }
  return n ? 100.0 * std::sqrt(sum / n) / peak : 0.0;
}

ManoeuvreError compare(const std::string& name, const RunResult& ref, const RunResult& run, double limit) {
  using S = vehicle::VehicleSample;
  ManoeuvreError e;
  e.manoeuvre = name;
  e.yawRate = rmsPercent(ref, run, [](const S& s) { return s.yawRate; }, kYawRateFloor);
  e.ay = rmsPercent(ref, run, [](const S& s) { return s.ay; }, kAyFloor);
  e.roll = rmsPercent(ref, run, [](const S& s) { return s.roll; }, kAngleFloor);
  e.pitch = rmsPercent(ref, run, [](const S& s) { return s.pitch; }, kAngleFloor);
  // The chassis frame's height (the same frame in every rung).
  e.z = rmsPercent(ref, run, [](const S& s) { return s.chassisOrigin.z(); }, 0.0);
  for (const S& s : ref.samples) e.limitShare = std::max(e.limitShare, std::abs(s.ay) / limit);
  return e;
}

// The scene's vehicle and integrator, and the rungs themselves (a rung
// derived from another car, as in an ablation, is another certificate).
std::string certificateKey(const ScenarioSpec& scene, const vehicle::Vehicle& kinematic, const vehicle::Vehicle* planar) {
  std::ostringstream k;
  k.precision(17);
  k << vehicle::derivationFingerprint(kinematic) << ' ' << (planar ? vehicle::derivationFingerprint(*planar) : 0)
    << ' ';
  // The planar rung's own derived figures (the fingerprint covers its bodies and joints).
  if (planar && planar->planar) {
    const auto& P = planar->planar;
    for (int w = 0; w < 4; ++w)
      k << ' ' << P->staticLoad[w] << ' ' << P->rate[w] << ' ' << P->damping[w] << ' ' << P->turnPerTravel[w].transpose();
    k << ' ' << P->rollCentreHeight[0] << ' ' << P->rollCentreHeight[1] << ' ' << P->axisHeight << ' ' << P->barRate[0]
      << ' ' << P->barRate[1];
  }
  return k.str() + '|' + rungRunsKey(scene);
}

}  // namespace

LadderCertificate certifyLadder(const ScenarioSpec& scene, const vehicle::Vehicle& linkage,
                                const vehicle::PlanarDerivation& derived) {
  return certifyLadder(scene, linkage, derived.kinematic.vehicle, &derived.vehicle);
}

LadderCertificate certifyLadder(const ScenarioSpec& scene, const vehicle::Vehicle& linkage,
                                const vehicle::Vehicle& kinematic, const vehicle::Vehicle* planar) {
  static std::mutex mutex;
  static std::map<std::string, LadderCertificate> known;
  const std::string key = certificateKey(scene, kinematic, planar);
  {
    std::lock_guard<std::mutex> lock(mutex);
    if (auto it = known.find(key); it != known.end()) return it->second;
  }
  LadderCertificate c;
  c.step = scene.integrator.step;
  const double limit = tyre::peakFriction(linkage.wheel(0).tyre, kRoadFriction) * kG;
  std::vector<const vehicle::Vehicle*> rungs = {&kinematic};
  if (planar) rungs.push_back(planar);
  for (const vehicle::Vehicle* v : rungs) c.rungs.push_back(RungCertificate{v->fidelity, {}, 0, "", ""});
  for (const ScenarioSpec& s : certificateBattery(scene, linkage)) {
    const RunResult ref = runOnModel(s, linkage, linkage);
    if (!ref.ok) {
      c.failure = "the linkage failed '" + s.name + "': " + ref.failure;
      c.rungs.clear();
      break;
    }
    for (size_t k = 0; k < c.rungs.size(); ++k) {
      RungCertificate& rc = c.rungs[k];
      if (s.groundGrade != 0 && rc.rung == vehicle::Fidelity::Planar) {
        // Outside its validity: the run would be refused before it starts.
        ManoeuvreError e;
        e.manoeuvre = s.name;
        e.refused = "level ground only";
        rc.manoeuvres.push_back(e);
        continue;
      }
      const RunResult run = runOnModel(s, linkage, *rungs[k]);
      ManoeuvreError e = compare(s.name, ref, run, limit);
      if (!run.ok) {
        // A run the rung cannot finish is no certificate: over any budget.
        e.yawRate = e.ay = e.roll = e.pitch = e.z = INFINITY;
        rc.worst = INFINITY;
        rc.worstManoeuvre = s.name + " (failed: " + run.failure + ")";
        rc.worstQuantity = "every quantity";
        rc.manoeuvres.push_back(e);
        continue;
      }
      const char* q = nullptr;
      const double worst = e.worst(&q);
      if (std::isfinite(rc.worst) && (rc.worstManoeuvre.empty() || worst > rc.worst)) {
        rc.worst = worst;
        rc.worstManoeuvre = s.name;
        rc.worstQuantity = q;
      }
      rc.manoeuvres.push_back(e);
    }
  }
  std::lock_guard<std::mutex> lock(mutex);
  known.emplace(key, c);
  return c;
}

AutoRungChoice chooseAutoRungs(const LadderCertificate& c, double errorBudget) {
  AutoRungChoice choice;
  const double budget = 100.0 * errorBudget;
  auto why = [&](const char* rung, const char* quantity, double value, const std::string& manoeuvre) {
    char buf[400];
    std::snprintf(buf, sizeof buf, "%s %.1f %% over the %.3g %% budget on %s (it omits: %s)", quantity, value, budget,
                  manoeuvre.c_str(), vehicle::describeRung(*vehicle::rungByName(rung)).omits);
    return std::string(buf);
  };
  if (!c.failure.empty()) {
    choice.refusals.push_back("no derived rung used: no certificate (" + c.failure + ")");
    return choice;
  }
  const RungCertificate* k = c.find(vehicle::Fidelity::Kinematic);
  const RungCertificate* p = c.find(vehicle::Fidelity::Planar);
  if (k && k->worst <= budget) {
    choice.full = vehicle::Fidelity::Kinematic;
  } else if (k) {
    choice.refusals.push_back("kinematic not used: " + why("kinematic", k->worstQuantity.c_str(), k->worst, k->worstManoeuvre));
  }
  if (!p) return choice;
  if (choice.full != vehicle::Fidelity::Kinematic) {
    choice.refusals.push_back("planar not used: it switches to and from the kinematic rung, which is not used");
    return choice;
  }
  // The planar rung is used where it is certified: every manoeuvre but the
  // harder step steer within the budget; that one over it limits the rung to
  // lateral accelerations halfway between the two step steers' levels.
  const ManoeuvreError* harder = nullptr;
  const ManoeuvreError* easier = nullptr;
  for (const ManoeuvreError& e : p->manoeuvres) {
    if (e.manoeuvre.rfind("step steer 0.6", 0) == 0) harder = &e;
    if (e.manoeuvre.rfind("step steer 0.3", 0) == 0) easier = &e;
  }
  for (const ManoeuvreError& e : p->manoeuvres) {
    if (!e.refused.empty() || &e == harder) continue;
    const char* q = nullptr;
    const double worst = e.worst(&q);
    if (worst > budget) {
      choice.refusals.push_back("planar not used: " + why("planar", q, worst, e.manoeuvre));
      return choice;
    }
  }
  choice.planar = true;
  if (harder && easier) {
    const char* q = nullptr;
    const double worst = harder->worst(&q);
    if (worst > budget) {
      choice.planarLevel = 0.5 * (easier->limitShare + harder->limitShare);
      char buf[120];
      std::snprintf(buf, sizeof buf, "planar used below %.2f of the tyres' limit in lateral acceleration: ",
                    choice.planarLevel);
      choice.refusals.push_back(buf + why("planar", q, worst, harder->manoeuvre));
    }
  }
  return choice;
}

std::string describeCertificate(const LadderCertificate& c, double errorBudget) {
  std::ostringstream o;
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "certificate against the linkage at a %.3g ms step (RMS %% of the linkage's peak; budgeted: yaw "
                "rate, a_y, roll, height):\n",
                c.step * 1e3);
  o << buf;
  if (!c.failure.empty()) return o.str() + "  none: " + c.failure + "\n";
  for (const RungCertificate& r : c.rungs) {
    o << "  " << vehicle::fidelityName(r.rung) << ":\n";
    std::snprintf(buf, sizeof buf, "    %-34s %8s %8s %8s %8s %8s %7s\n", "manoeuvre", "yaw rate", "a_y", "roll",
                  "pitch", "height", "a_y/mu g");
    o << buf;
    for (const ManoeuvreError& e : r.manoeuvres) {
      if (!e.refused.empty()) {
        std::snprintf(buf, sizeof buf, "    %-34s outside the rung's validity: %.200s\n", e.manoeuvre.c_str(),
                      e.refused.c_str());
      } else {
        std::snprintf(buf, sizeof buf, "    %-34s %7.2f%% %7.2f%% %7.2f%% %7.2f%% %7.2f%% %7.2f\n",
                      e.manoeuvre.c_str(), e.yawRate, e.ay, e.roll, e.pitch, e.z, e.limitShare);
      }
      o << buf;
    }
    std::snprintf(buf, sizeof buf, "    worst: %.2f %% (%s, %s): %s the %.3g %% budget\n", r.worst,
                  r.worstQuantity.c_str(), r.worstManoeuvre.c_str(),
                  r.worst <= 100.0 * errorBudget ? "within" : "over", 100.0 * errorBudget);
    o << buf;
  }
  return o.str();
}

}  // namespace bdfcar::scenario
