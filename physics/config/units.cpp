#include "config/units.h"

#include <array>
#include <cctype>
#include <cstdlib>
#include <string_view>

namespace bdfcar::config {

namespace {

struct UnitEntry {
  Dimension dim;
  std::string_view name;
  double factor;
};

// Accepted spellings; "*" and " " are interchangeable, "^2" and "2" too.
constexpr std::array kUnits = {
    UnitEntry{Dimension::None, "", 1.0},
    UnitEntry{Dimension::None, "%", 0.01},
    UnitEntry{Dimension::Length, "m", 1.0},
    UnitEntry{Dimension::Length, "mm", 1e-3},
    UnitEntry{Dimension::Length, "cm", 1e-2},
    UnitEntry{Dimension::Length, "km", 1e3},
    UnitEntry{Dimension::Mass, "kg", 1.0},
    UnitEntry{Dimension::Mass, "g", 1e-3},
    UnitEntry{Dimension::Mass, "t", 1e3},
    UnitEntry{Dimension::Time, "s", 1.0},
    UnitEntry{Dimension::Time, "ms", 1e-3},
    UnitEntry{Dimension::Time, "min", 60.0},
    UnitEntry{Dimension::Angle, "rad", 1.0},
    UnitEntry{Dimension::Angle, "deg", 1.0 / kDegPerRad},
    UnitEntry{Dimension::Speed, "m/s", 1.0},
    UnitEntry{Dimension::Speed, "km/h", 1.0 / kKmhPerMps},
    UnitEntry{Dimension::AngularSpeed, "rad/s", 1.0},
    UnitEntry{Dimension::AngularSpeed, "deg/s", 1.0 / kDegPerRad},
    UnitEntry{Dimension::AngularSpeed, "rpm", 2.0 * 3.14159265358979323846 / 60.0},
    UnitEntry{Dimension::Acceleration, "m/s^2", 1.0},
    UnitEntry{Dimension::Acceleration, "g", 9.80665},
    UnitEntry{Dimension::Force, "N", 1.0},
    UnitEntry{Dimension::Force, "kN", 1e3},
    UnitEntry{Dimension::Torque, "N*m", 1.0},
    UnitEntry{Dimension::Torque, "kN*m", 1e3},
    UnitEntry{Dimension::Stiffness, "N/m", 1.0},
    UnitEntry{Dimension::Stiffness, "N/mm", 1e3},
    UnitEntry{Dimension::Stiffness, "kN/m", 1e3},
    UnitEntry{Dimension::Damping, "N*s/m", 1.0},
    UnitEntry{Dimension::Damping, "kN*s/m", 1e3},
    UnitEntry{Dimension::Inertia, "kg*m^2", 1.0},
    UnitEntry{Dimension::AngularStiffness, "N*m/rad", 1.0},
    UnitEntry{Dimension::AngularStiffness, "N*m/deg", kDegPerRad},
    UnitEntry{Dimension::TorqueRate, "N*m*s/m", 1.0},
    UnitEntry{Dimension::Frequency, "Hz", 1.0},
    UnitEntry{Dimension::Frequency, "1/s", 1.0},
};

// Canonical spelling: spaces between factors become '*', "m2" becomes "m^2".
std::string canonical(const std::string& u) {
  std::string out;
  for (size_t i = 0; i < u.size(); ++i) {
    const char c = u[i];
    if (c == ' ') {
      if (!out.empty() && out.back() != '*' && out.back() != '/') out += '*';
      continue;
    }
    if (c == '2' && !out.empty() && std::isalpha(static_cast<unsigned char>(out.back()))) {
      out += "^2";
      continue;
    }
    if ((c == '*' || c == '/') && !out.empty() && out.back() == '*') out.pop_back();
    out += c;
  }
  while (!out.empty() && out.back() == '*') out.pop_back();
  return out;
}

}  // namespace

const char* dimensionName(Dimension d) {
  switch (d) {
    case Dimension::None: return "dimensionless number";
    case Dimension::Length: return "length";
    case Dimension::Mass: return "mass";
    case Dimension::Time: return "time";
    case Dimension::Angle: return "angle";
    case Dimension::Speed: return "speed";
    case Dimension::AngularSpeed: return "angular speed";
    case Dimension::Acceleration: return "acceleration";
    case Dimension::Force: return "force";
    case Dimension::Torque: return "torque";
    case Dimension::Stiffness: return "stiffness";
    case Dimension::Damping: return "damping coefficient";
    case Dimension::Inertia: return "moment of inertia";
    case Dimension::AngularStiffness: return "angular stiffness";
    case Dimension::TorqueRate: return "torque per speed";
    case Dimension::Frequency: return "frequency";
  }
  return "?";
}

const char* siUnit(Dimension d) {
  switch (d) {
    case Dimension::None: return "";
    case Dimension::Length: return "m";
    case Dimension::Mass: return "kg";
    case Dimension::Time: return "s";
    case Dimension::Angle: return "rad";
    case Dimension::Speed: return "m/s";
    case Dimension::AngularSpeed: return "rad/s";
    case Dimension::Acceleration: return "m/s^2";
    case Dimension::Force: return "N";
    case Dimension::Torque: return "N*m";
    case Dimension::Stiffness: return "N/m";
    case Dimension::Damping: return "N*s/m";
    case Dimension::Inertia: return "kg*m^2";
    case Dimension::AngularStiffness: return "N*m/rad";
    case Dimension::TorqueRate: return "N*m*s/m";
    case Dimension::Frequency: return "Hz";
  }
  return "?";
}

std::optional<double> unitFactor(Dimension d, const std::string& unit) {
  const std::string u = canonical(unit);
  for (const UnitEntry& e : kUnits)
    if (e.dim == d && e.name == u) return e.factor;
  return std::nullopt;
}

std::optional<double> parseQuantity(const std::string& text, Dimension d, std::string& why) {
  const char* begin = text.c_str();
  char* end = nullptr;
  const double value = std::strtod(begin, &end);
  if (end == begin) {
    why = "does not start with a number";
    return std::nullopt;
  }
  std::string unit(end);
  const size_t first = unit.find_first_not_of(' ');
  unit = first == std::string::npos ? "" : unit.substr(first);
  const auto f = unitFactor(d, unit);
  if (!f) {
    why = "unit '" + unit + "' is not a unit of " + dimensionName(d);
    return std::nullopt;
  }
  return value * *f;
}

}  // namespace bdfcar::config
