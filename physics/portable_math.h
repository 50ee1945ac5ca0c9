// The transcendental functions of the physics, the same bits on every
// machine of a build flavour. The C library picks its sin, exp, pow ... at
// run time by the CPU (glibc's ifunc variants for FMA, AVX2, ...): the same
// build gave other telemetry on another x86-64-v3 machine, so a recording
// replayed there was not the drive recorded. SLEEF's scalar functions
// (Debian's libsleef) are fixed code paths with no dispatch: the pure-C ones
// in the generic flavour, the pure-C-with-FMA ones where the flavour itself
// requires FMA (x86-64-v3: the compiler defines FP_FAST_FMA), so each
// flavour has one path. Accuracy: the 3.5-ulp functions where SLEEF has
// them (a relative error below 1e-15, far under anything the physics
// resolves) at a half to a third of the 1-ulp ones' instructions (sincos
// 98 against 230, atan2 125 against 346, tanh 84 against 408 under
// callgrind); exp and pow exist at 1 ulp only, hypot at 0.5. tanh returns
// +-1 outright where the exact value rounds to it (|x| >= 20: the rolling
// resistance's sign of a wheel at road speed). sqrt is IEEE-exact
// everywhere and stays std::sqrt; fmod, floor and the like are exact too.
#pragma once

#include <cmath>  // FP_FAST_FMA, which sleef.h reads to declare its FMA functions
#include <sleef.h>

#ifdef FP_FAST_FMA
#define BDFCAR_SLEEF(name) Sleef_##name##purecfma
#else
#define BDFCAR_SLEEF(name) Sleef_##name##purec
#endif

namespace bdfcar::pm {

inline double sin(double x) { return BDFCAR_SLEEF(sind1_u35)(x); }
inline double cos(double x) { return BDFCAR_SLEEF(cosd1_u35)(x); }
// sin and cos of one angle at the cost of one: x -> (sin x, cos x). The
// physics' angles are mostly small (roll, pitch, a table's camber and toe,
// the yaw a step turns): within pi/4 their Taylor series to x^15 and x^16
// (the first terms left out below 5e-17 of the values at pi/4; Horner in
// x^2, about a third of SLEEF's instructions, within an ulp or two as
// SLEEF's 3.5-ulp function is), SLEEF's beyond.
struct SinCos {
  double s, c;
};
inline SinCos sincos(double x) {
  if (std::abs(x) <= 0.78539816339744828) {
    const double x2 = x * x;
    const double s =
        x + x * x2 *
                (-1.0 / 6 + x2 * (1.0 / 120 + x2 * (-1.0 / 5040 + x2 * (1.0 / 362880 + x2 * (-1.0 / 39916800 +
                 x2 * (1.0 / 6227020800 + x2 * (-1.0 / 1307674368000)))))));
    const double c =
        1.0 + x2 * (-0.5 + x2 * (1.0 / 24 + x2 * (-1.0 / 720 + x2 * (1.0 / 40320 + x2 * (-1.0 / 3628800 +
              x2 * (1.0 / 479001600 + x2 * (-1.0 / 87178291200 + x2 * (1.0 / 20922789888000))))))));
    return {s, c};
  }
  const Sleef_double_2 r = BDFCAR_SLEEF(sincosd1_u35)(x);
  return {r.x, r.y};
}
inline double tan(double x) { return BDFCAR_SLEEF(tand1_u35)(x); }
inline double asin(double x) { return BDFCAR_SLEEF(asind1_u35)(x); }
inline double acos(double x) { return BDFCAR_SLEEF(acosd1_u35)(x); }
inline double atan(double x) { return BDFCAR_SLEEF(atand1_u35)(x); }
inline double atan2(double y, double x) { return BDFCAR_SLEEF(atan2d1_u35)(y, x); }
inline double tanh(double x) {
  if (std::abs(x) >= 20.0) return x > 0 ? 1.0 : -1.0;  // 1 - tanh(20) = 8.5e-18, below half an ulp of 1
  return BDFCAR_SLEEF(tanhd1_u35)(x);
}
inline double exp(double x) { return BDFCAR_SLEEF(expd1_u10)(x); }
inline double log(double x) { return BDFCAR_SLEEF(logd1_u35)(x); }
inline double pow(double x, double y) { return BDFCAR_SLEEF(powd1_u10)(x, y); }
inline double hypot(double x, double y) { return BDFCAR_SLEEF(hypotd1_u05)(x, y); }

}  // namespace bdfcar::pm

#undef BDFCAR_SLEEF
