// The transcendental functions of the physics, the same bits on every
// machine. The C library picks its sin, exp, pow ... at run time by the CPU
// (glibc's ifunc variants for FMA, AVX2, ...): the same build gave other
// telemetry on another x86-64-v3 machine, so a recording replayed there was
// not the drive recorded. SLEEF's pure-C scalar functions (Debian's
// libsleef, built for baseline x86-64, no dispatch, no FMA) are one fixed
// code path: within 1 ulp (hypot 0.5 ulp) of the exact result, as the C
// library's are. sqrt is IEEE-exact everywhere and stays std::sqrt; fmod,
// floor and the like are exact too.
#pragma once

#include <sleef.h>

namespace bdfcar::pm {

inline double sin(double x) { return Sleef_sind1_u10purec(x); }
inline double cos(double x) { return Sleef_cosd1_u10purec(x); }
// sin and cos of one angle at the cost of one: x -> (sin x, cos x).
struct SinCos {
  double s, c;
};
inline SinCos sincos(double x) {
  const Sleef_double_2 r = Sleef_sincosd1_u10purec(x);
  return {r.x, r.y};
}
inline double tan(double x) { return Sleef_tand1_u10purec(x); }
inline double asin(double x) { return Sleef_asind1_u10purec(x); }
inline double acos(double x) { return Sleef_acosd1_u10purec(x); }
inline double atan(double x) { return Sleef_atand1_u10purec(x); }
inline double atan2(double y, double x) { return Sleef_atan2d1_u10purec(y, x); }
inline double tanh(double x) { return Sleef_tanhd1_u10purec(x); }
inline double exp(double x) { return Sleef_expd1_u10purec(x); }
inline double log(double x) { return Sleef_logd1_u10purec(x); }
inline double pow(double x, double y) { return Sleef_powd1_u10purec(x, y); }
inline double hypot(double x, double y) { return Sleef_hypotd1_u05purec(x, y); }

}  // namespace bdfcar::pm
