// Units at the edges: config values may be plain numbers (SI) or strings
// "<number> <unit>" such as "80 km/h", "6 deg", "310 mm". This is the one
// place where non-SI units are converted; physics sees SI only.
#pragma once

#include <optional>
#include <string>

namespace bdfcar::config {

enum class Dimension {
  None,            // dimensionless (also "%")
  Length,          // m
  Mass,            // kg
  Time,            // s
  Angle,           // rad
  Speed,           // m/s
  AngularSpeed,    // rad/s
  Acceleration,    // m/s^2
  Force,           // N
  Torque,          // N m
  Stiffness,       // N/m
  Damping,         // N s/m
  Inertia,         // kg m^2
  AngularStiffness,// N m/rad
  TorqueRate,      // N m per (m/s) (speed-controller gains)
  Frequency,       // Hz
};

const char* dimensionName(Dimension d);   // e.g. "length"
const char* siUnit(Dimension d);          // e.g. "m"

// Factor that converts a value in `unit` to SI for dimension d, if the unit
// belongs to it ("" is the SI unit itself).
std::optional<double> unitFactor(Dimension d, const std::string& unit);

// Parses "<number> <unit>" for dimension d; nullopt with `why` set on failure.
std::optional<double> parseQuantity(const std::string& text, Dimension d, std::string& why);

// Conversions used at the CLI and HUD edges.
constexpr double kKmhPerMps = 3.6;
constexpr double kDegPerRad = 57.295779513082320876798154814105;
inline double kmhToMps(double kmh) { return kmh / kKmhPerMps; }
inline double mpsToKmh(double mps) { return mps * kKmhPerMps; }
inline double degToRad(double deg) { return deg / kDegPerRad; }
inline double radToDeg(double rad) { return rad * kDegPerRad; }

}  // namespace bdfcar::config
