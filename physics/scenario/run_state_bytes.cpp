#include "scenario/run_state_bytes.h"

#include <cstdio>
#include <cstring>
#include <string>
#include <type_traits>

#include "vehicle/derivation_cache.h"

namespace bdfcar::scenario {

namespace {

constexpr char kMagic[8] = {'B', 'D', 'F', 'C', 'A', 'R', 'R', 'S'};
// A history longer than the BDF's (order 5 + 2: the ring's slots) or a
// vector longer than any model's is not a run state: refused before anything
// is allocated for it.
constexpr std::uint64_t kMaxHistory = integ::IntegratorState::kSlots;
constexpr std::uint64_t kMaxVector = 1u << 16;

// Writes every field it is shown, in order.
class Writer {
 public:
  vehicle::ByteBuffer out;
  template <class T>
  void field(const char*, const T& v) {
    if constexpr (std::is_same_v<T, Eigen::VectorXd>) {
      out.put(static_cast<std::uint64_t>(v.size()));
      for (Eigen::Index i = 0; i < v.size(); ++i) out.put(v(i));
    } else if constexpr (std::is_same_v<T, Eigen::Vector3d>) {
      for (int i = 0; i < 3; ++i) out.put(v(i));
    } else {
      static_assert(std::is_arithmetic_v<T>, "a run state field of an unlisted type");
      out.put(v);
    }
  }
  std::uint64_t count(const char*, std::uint64_t n, std::uint64_t) {
    out.put(n);
    return n;
  }
};

// Reads every field it is shown, in the same order; the field's name goes
// into the message when the bytes run out or a count is impossible.
class Reader {
 public:
  explicit Reader(vehicle::ByteBuffer in) : in_(std::move(in)) {}
  template <class T>
  void field(const char* name, T& v) {
    if constexpr (std::is_same_v<T, Eigen::VectorXd>) {
      std::uint64_t n = 0;
      get(name, n);
      if (n > kMaxVector) fail(std::string(name) + " claims " + std::to_string(n) + " numbers");
      v.resize(static_cast<Eigen::Index>(n));
      for (Eigen::Index i = 0; i < v.size(); ++i) get(name, v(i));
    } else if constexpr (std::is_same_v<T, Eigen::Vector3d>) {
      for (int i = 0; i < 3; ++i) get(name, v(i));
    } else {
      get(name, v);
    }
  }
  std::uint64_t count(const char* name, std::uint64_t, std::uint64_t limit) {
    std::uint64_t n = 0;
    get(name, n);
    if (n > limit) fail(std::string(name) + " claims " + std::to_string(n) + " entries (at most " + std::to_string(limit) + ")");
    return n;
  }
  bool atEnd() const { return in_.atEnd(); }
  [[noreturn]] static void fail(const std::string& what) {
    throw RunStateBytesError("run state bytes: " + what);
  }

 private:
  template <class T>
  void get(const char* name, T& v) {
    if constexpr (std::is_same_v<T, bool>) {
      std::uint8_t b = 0;
      if (!in_.get(b)) fail(std::string("truncated in ") + name);
      if (b > 1) fail(std::string(name) + " is neither true nor false");
      v = b == 1;
    } else {
      if (!in_.get(v)) fail(std::string("truncated in ") + name);
    }
  }
  vehicle::ByteBuffer in_;
};

// A bool as one byte 0 / 1 whatever the platform's bool holds.
template <class IO>
void flag(IO& io, const char* name, bool& b) {
  io.field(name, b);
}
void flag(Writer& io, const char*, const bool& b) { io.out.put(static_cast<std::uint8_t>(b ? 1 : 0)); }

// Every field of the state, once, in the byte form's order. S is RunState
// (reading) or const RunState (writing); the nested structs likewise.
template <class IO, class P>
void solutionPoint(IO& io, P& p) {
  io.field("integrator history t", p.t);
  io.field("integrator history q", p.q);
  io.field("integrator history v", p.v);
  io.field("integrator history a", p.a);
  io.field("integrator history lambda", p.lambda);
}

template <class IO, class C>
void counters(IO& io, C& c) {
  for (auto* n : {&c.steps, &c.substeps, &c.newtonIterations, &c.residuals, &c.jacobianResiduals, &c.jacobians,
                  &c.columnRefreshes, &c.factorizations, &c.solves, &c.refreshes, &c.rescues, &c.splits, &c.refinements})
    io.field("integrator counters", *n);
}

// An enveloping tyre's road for the step (its samples beyond n are zero).
template <class IO, class P>
void roadProfile(IO& io, P& p) {
  flag(io, "road profile valid", p.valid);
  for (auto* x : {&p.origin.x(), &p.origin.y(), &p.heading.x(), &p.heading.y(), &p.s0, &p.ds, &p.friction, &p.slope})
    io.field("road profile line", *x);
  flag(io, "road profile linear", p.linear);
  const std::uint64_t n = io.count("road profile samples", static_cast<std::uint64_t>(p.n), tyre::RoadProfile::kCapacity);
  if constexpr (!std::is_const_v<P>) p.n = static_cast<int>(n);
  for (std::uint64_t k = 0; k < n; ++k) {
    io.field("road profile height", p.z[k]);
    io.field("road profile cross slope", p.cross[k]);
  }
}

template <class IO, class W>
void wheel(IO& io, W& w) {
  flag(io, "contact plane valid", w.plane.valid);
  io.field("contact plane point", w.plane.point);
  io.field("contact plane normal", w.plane.normal);
  io.field("contact plane friction", w.plane.friction);
  roadProfile(io, w.profile);
  io.field("slip kappa", w.slip.kappa);
  io.field("slip tan alpha", w.slip.tanAlpha);
  flag(io, "slip active", w.slip.active);
  for (auto* x : {&w.brakeDeflection, &w.driveTorque, &w.brakeCapacity})
    io.field("wheel brake and drive", *x);
  io.field("wheel accepted force", w.acceptedForce);
  flag(io, "wheel accepted in contact", w.acceptedInContact);
  for (auto* x : {&w.acceptedFx, &w.acceptedFy, &w.acceptedFz}) io.field("wheel accepted tyre force", *x);
}

template <class IO, class S>
void fields(IO& io, S& s) {
  io.field("model fingerprint", s.model);
  // The history newest first, wherever the ring starts (read: from slot 0).
  const std::uint64_t points = io.count("integrator history", s.integrator.count, kMaxHistory);
  if constexpr (!std::is_const_v<S>) {
    s.integrator.head = 0;
    s.integrator.count = static_cast<int>(points);
  }
  for (int i = 0; i < s.integrator.count; ++i) solutionPoint(io, s.integrator.node(i));
  counters(io, s.integrator.counters);
  for (auto& w : s.forces.wheels) wheel(io, w);
  auto& d = s.forces.driveline;
  for (auto* x : {&d.command.throttle, &d.command.clutchCapacity, &d.command.ratio, &d.clutchDeflection, &d.engineSpeed,
                  &d.engineTorque, &d.clutchTorque, &d.outputSpeed})
    io.field("driveline", *x);
  io.field("forces last accepted time", s.forces.lastAccepted);
  flag(io, "forces planes ready", s.forces.planesReady);
  io.field("forces planes for", s.forces.planesFor);
  flag(io, "rack scripted", s.rack.scripted);
  for (auto* x : {&s.rack.t0, &s.rack.s0, &s.rack.r0, &s.rack.a}) io.field("rack segment", *x);
  io.field("speed controller integral", s.speedIntegral);
  io.field("path follower gain", s.follower.gain);
  io.field("path follower curvature", s.follower.lastCurvature);
  for (auto* x : {&s.input.steer, &s.input.throttle, &s.input.brake, &s.input.handbrake, &s.input.clutch})
    io.field("driver input", *x);
  flag(io, "driver input clutch pedal", s.input.clutchPedal);
  io.field("driver input shift", s.input.shift);
  flag(io, "scripted driver", s.scriptedDriver);
  io.field("airborne time", s.airborne);
  io.field("rung", s.rung);
  auto& f = s.fidelity;
  for (auto* x : {&f.odometer, &f.scanned, &f.fullUntil, &f.calm, &f.maxJump, &f.maxTurn}) io.field("fidelity policy", *x);
  for (auto* x : {&f.switches, &f.missed, &f.refused}) io.field("fidelity policy counts", *x);
  io.field("transmission gear", s.transmission.gear);
  io.field("transmission next gear", s.transmission.nextGear);
  io.field("transmission shift clock", s.transmission.shiftClock);
  io.field("transmission engagement", s.transmission.engagement);
}

}  // namespace

std::vector<char> runStateToBytes(const RunState& s) {
  Writer w;
  fields(w, s);
  vehicle::ByteBuffer all;
  for (char c : kMagic) all.put(c);
  all.put(kRunStateFormat);
  all.put(static_cast<std::uint64_t>(w.out.bytes.size()));
  all.bytes.insert(all.bytes.end(), w.out.bytes.begin(), w.out.bytes.end());
  all.put(vehicle::hashBytes(w.out.bytes));
  return std::move(all.bytes);
}

RunState runStateFromBytes(const std::vector<char>& bytes) {
  constexpr std::size_t kHeader = sizeof kMagic + sizeof(std::uint32_t) + sizeof(std::uint64_t);
  if (bytes.size() < kHeader + sizeof(std::uint64_t) || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    Reader::fail("not a bdfcar run state (no BDFCARRS header)");
  std::uint32_t format = 0;
  std::uint64_t length = 0;
  std::memcpy(&format, bytes.data() + sizeof kMagic, sizeof format);
  std::memcpy(&length, bytes.data() + sizeof kMagic + sizeof format, sizeof length);
  if (format != kRunStateFormat)
    Reader::fail("format version " + std::to_string(format) + ", this build reads version " +
                 std::to_string(kRunStateFormat));
  if (length != bytes.size() - kHeader - sizeof(std::uint64_t))
    Reader::fail("the header says " + std::to_string(length) + " bytes of state, there are " +
                 std::to_string(bytes.size() - kHeader - sizeof(std::uint64_t)) + " (truncated or extended)");
  vehicle::ByteBuffer payload;
  payload.bytes.assign(bytes.begin() + kHeader, bytes.end() - sizeof(std::uint64_t));
  std::uint64_t sum = 0;
  std::memcpy(&sum, bytes.data() + bytes.size() - sizeof sum, sizeof sum);
  if (sum != vehicle::hashBytes(payload.bytes)) Reader::fail("the checksum does not match (corrupted)");
  Reader r(std::move(payload));
  RunState s;
  fields(r, s);
  if (!r.atEnd()) Reader::fail("bytes left over after the last field");
  return s;
}

std::uint64_t hashRunState(const RunState& s) { return vehicle::hashBytes(runStateToBytes(s)); }

std::optional<std::string> Simulation::misfit(const RunState& s) const {
  if (s.model != modelFingerprint_) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "a state of another vehicle or rung (model fingerprint %016llx, this simulation's %016llx)",
                  static_cast<unsigned long long>(s.model), static_cast<unsigned long long>(modelFingerprint_));
    return std::string(text);
  }
  if (s.rung < 0 || s.rung >= rungCount())
    return "rung " + std::to_string(s.rung) + " of a simulation with " + std::to_string(rungCount());
  const integ::DaeSizes n = rungs_[static_cast<size_t>(s.rung)].stepping->sizes();
  if (s.integrator.count < 1 || s.integrator.count > integ::IntegratorState::kSlots)
    return std::string("no integrator history");
  for (int i = 0; i < s.integrator.count; ++i)
    if (const integ::SolutionPoint& p = s.integrator.node(i);
        p.q.size() != n.nq || p.v.size() != n.nv || p.a.size() != n.nv || p.lambda.size() != n.nc)
      return "a state of " + std::to_string(p.q.size()) + " coordinates and " + std::to_string(p.lambda.size()) +
             " constraints for a model of " + std::to_string(n.nq) + " and " + std::to_string(n.nc) +
             " (another vehicle or rung)";
  return std::nullopt;
}

std::vector<char> Simulation::saveBytes() { return runStateToBytes(save()); }

void Simulation::restoreBytes(const std::vector<char>& bytes) {
  const RunState s = runStateFromBytes(bytes);
  if (const auto why = misfit(s)) throw RunStateBytesError("run state bytes do not fit this simulation: " + *why);
  restore(s);
}

}  // namespace bdfcar::scenario
