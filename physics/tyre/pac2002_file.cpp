#include "tyre/pac2002_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

namespace bdfcar::tyre {

namespace {

// Keys the reader takes outside the coefficient list.
const std::set<std::string> kReadKeys{
    "UNITS/LENGTH",          "UNITS/FORCE",           "UNITS/ANGLE",      "UNITS/MASS",
    "UNITS/TIME",            "MODEL/PROPERTY_FILE_FORMAT", "MODEL/USE_MODE", "MODEL/TYRESIDE",
    "MODEL/FE_METHOD",       "MODEL/LONGVL",          "DIMENSION/UNLOADED_RADIUS", "DIMENSION/WIDTH",
    "VERTICAL/VERTICAL_STIFFNESS", "VERTICAL/VERTICAL_DAMPING", "VERTICAL/FNOMIN", "VERTICAL/BREFF",
    "VERTICAL/DREFF",        "VERTICAL/FREFF"};

// Keys that describe the file or its validity ranges, not the forces: read
// by no tyre code, so not worth a warning.
const std::set<std::string> kDescriptive{"MODEL/FITTYP", "MODEL/MESSAGES", "MODEL/VXLOW", "MODEL/TYPE",
                                         "MDI_HEADER/FILE_TYPE", "MDI_HEADER/FILE_VERSION",
                                         "MDI_HEADER/FILE_FORMAT", "DIMENSION/ASPECT_RATIO",
                                         "DIMENSION/RIM_RADIUS", "DIMENSION/RIM_WIDTH"};

bool isRangeSection(const std::string& s) { return s.size() > 6 && s.compare(s.size() - 6, 6, "_RANGE") == 0; }

}  // namespace

Pac2002File readPac2002(const TirFile& tir, Pac2002Variant variant) {
  Pac2002File out;
  Pac2002Params& p = out.params;
  p.file = tir.path();
  p.variant = variant;
  const bool chrono = variant == Pac2002Variant::Chrono9;

  const std::string format = tir.word("MODEL", "PROPERTY_FILE_FORMAT", "");
  if (format != "PAC2002" && format != "MF_05") {
    const TirFile::Entry* e = tir.find("MODEL", "PROPERTY_FILE_FORMAT");
    const std::string what = "unknown tyre model type '" + format +
                             "' (bdfcar reads Magic Formula 5.2 files: 'PAC2002' or 'MF_05')";
    if (e) tir.fail(*e, what);
    tir.fail("MODEL", "PROPERTY_FILE_FORMAT", "missing: " + what);
  }
  // USE_MODE: 3 pure-slip forces, 4 combined (TNO's 1x / 2x variants name
  // the same with transient or contact options bdfcar does not have).
  const double useMode = tir.number("MODEL", "USE_MODE", 4);
  const int mode = static_cast<int>(useMode);
  const int combination = mode % 10;
  if (mode != useMode || mode < 0 || (combination != 3 && combination != 4) || (chrono && mode > 4))
    tir.fail(*tir.find("MODEL", "USE_MODE"),
             std::string("USE_MODE ") + std::to_string(mode) +
                 (chrono ? " is not evaluated (Chrono's own evaluation gives zero forces for it): expected 3 "
                           "(uncombined) or 4 (combined)"
                         : " is not evaluated: expected 3 or 4 (or 13, 14, 23, 24: the same forces without "
                           "TNO's transient or contact options)"));
  p.combined = combination == 4;
  const std::string side = tir.word("MODEL", "TYRESIDE", "LEFT");
  if (side != "LEFT" && side != "RIGHT" && side != "UNKNOWN" && side != "SYMMETRIC")
    tir.fail(*tir.find("MODEL", "TYRESIDE"), "expected 'LEFT', 'RIGHT', 'UNKNOWN' or 'SYMMETRIC', got '" + side + "'");
  p.measuredLeft = side != "RIGHT";
  // FE_METHOD is Chrono's key: absent means its friction ellipse there.
  const std::string fe = tir.word("MODEL", "FE_METHOD", "");
  p.ellipse = chrono ? fe != "NO" : fe == "YES";

  const double L = tir.unitFactor("LENGTH"), F = tir.unitFactor("FORCE"), T = tir.unitFactor("TIME");
  tir.unitFactor("MASS");  // checked: an unknown unit is an error wherever it is
  tir.unitFactor("ANGLE");
  p.unloadedRadius = tir.number("DIMENSION", "UNLOADED_RADIUS") * L;
  p.width = tir.number("DIMENSION", "WIDTH", 0.0) * L;
  p.verticalStiffness = tir.number("VERTICAL", "VERTICAL_STIFFNESS") * F / L;
  p.verticalDamping = tir.number("VERTICAL", "VERTICAL_DAMPING") * F * T / L;
  p.nominalLoad = tir.number("VERTICAL", "FNOMIN") * F;
  p.breff = tir.number("VERTICAL", "BREFF", 0.0);
  p.dreff = tir.number("VERTICAL", "DREFF", 0.0);
  p.freff = tir.number("VERTICAL", "FREFF", 0.0);
  p.longvl = tir.number("MODEL", "LONGVL", 16.7) * L / T;
#define BDFCAR_PAC2002_READ(section, name, value) p.c.name = tir.number(#section, #name, value);
  BDFCAR_PAC2002_COEFFICIENTS(BDFCAR_PAC2002_READ)
#undef BDFCAR_PAC2002_READ

  // Physical curves.
  auto require = [&](const char* section, const char* key, bool ok, const std::string& expected) {
    if (ok) return;
    const TirFile::Entry* e = tir.find(section, key);
    if (e) tir.fail(*e, "expected " + expected + ", got " + e->value);
    tir.fail(section, key, "missing: expected " + expected);
  };
  require("DIMENSION", "UNLOADED_RADIUS", p.unloadedRadius > 0.05 && p.unloadedRadius < 2.0, "a radius in (0.05, 2) m");
  require("DIMENSION", "WIDTH", p.width >= 0 && p.width < 2.0, "a width in [0, 2) m");
  require("VERTICAL", "VERTICAL_STIFFNESS", p.verticalStiffness > 1e3 && p.verticalStiffness < 1e8,
          "a stiffness in (1e3, 1e8) N/m");
  require("VERTICAL", "VERTICAL_DAMPING", p.verticalDamping >= 0 && p.verticalDamping < 1e6,
          "a damping in [0, 1e6) N s/m");
  require("VERTICAL", "FNOMIN", p.nominalLoad > 10 && p.nominalLoad < 1e6, "a nominal load in (10, 1e6) N");
  require("SCALING_COEFFICIENTS", "LFZO", p.c.LFZO > 0, "a positive scale of the nominal load");
  require("SCALING_COEFFICIENTS", "LMUY", p.c.LMUY > 0, "a positive scale of the lateral friction");
  require("LONGITUDINAL_COEFFICIENTS", "PCX1", p.c.PCX1 > 0 && p.c.PCX1 < 2, "a shape factor in (0, 2)");
  require("LATERAL_COEFFICIENTS", "PCY1", p.c.PCY1 > 0 && p.c.PCY1 < 2, "a shape factor in (0, 2)");
  require("LONGITUDINAL_COEFFICIENTS", "PKX1", p.c.PKX1 > 0, "a positive slip stiffness factor");
  require("LATERAL_COEFFICIENTS", "PKY1", p.c.PKY1 < 0,
          "a negative cornering stiffness factor (ISO: the lateral force opposes the slip angle)");
  require("LATERAL_COEFFICIENTS", "PKY2", p.c.PKY2 > 0, "a positive load factor of the cornering stiffness");
  // The peak factors over the loads a tyre meets (a tenth to 2.5 times nominal).
  const double Fz0 = p.nominalLoad * p.c.LFZO;
  for (double share : {0.1, 1.0, 2.5}) {
    const double dfz = (share * p.nominalLoad - Fz0) / Fz0;
    require("LONGITUDINAL_COEFFICIENTS", "PDX1", p.c.PDX1 + p.c.PDX2 * dfz > 0,
            "a positive peak factor PDX1 + PDX2 dfz at every load from 0.1 to 2.5 FNOMIN");
    require("LATERAL_COEFFICIENTS", "PDY1", p.c.PDY1 + p.c.PDY2 * dfz > 0,
            "a positive peak factor PDY1 + PDY2 dfz at every load from 0.1 to 2.5 FNOMIN");
    require("LONGITUDINAL_COEFFICIENTS", "PKX1", p.c.PKX1 + p.c.PKX2 * dfz > 0,
            "a positive slip stiffness PKX1 + PKX2 dfz at every load from 0.1 to 2.5 FNOMIN");
  }
  if (chrono) p.c.QSY1 = p.c.QSY2 = 0;  // Chrono's reader zeroes them (tyre-pac2002.md 1.3)
  // Whatever passed the checks above must give finite forces within a few
  // times the load everywhere a tyre goes: a grid of loads, slips and
  // camber (an overflowing exponent or a coefficient of 1e300 is refused
  // here, not met as a NaN in a run).
  for (double share : {0.1, 1.0, 2.5})
    for (double kappa : {-1.0, -0.1, 0.0, 0.1, 1.0})
      for (double alpha : {-1.0, -0.1, 0.0, 0.1, 1.0})
        for (double gamma : {-0.1, 0.0, 0.1}) {
          const double Fz = share * p.nominalLoad;
          const MagicFormulaForces f = magicFormula(p, kappa, alpha, chrono ? 0.0 : gamma, Fz, p.referenceFriction, 10.0);
          const bool finite = std::isfinite(f.Fx) && std::isfinite(f.Fy) && std::isfinite(f.Mz) &&
                              std::isfinite(f.Mx) && std::isfinite(f.My);
          if (!finite || std::abs(f.Fx) > 5 * Fz || std::abs(f.Fy) > 5 * Fz || std::abs(f.Mz) > 5 * Fz * p.unloadedRadius) {
            char where[160];
            std::snprintf(where, sizeof where, "at Fz = %.0f N, kappa = %g, alpha = %g rad, gamma = %g rad", Fz, kappa,
                          alpha, gamma);
            tir.fail("LATERAL_COEFFICIENTS", "(the curves)",
                     std::string("the coefficients give ") + (finite ? "a force beyond 5 times the load" : "a non-finite force") +
                         " " + where + " (Fx " + std::to_string(f.Fx) + " N, Fy " + std::to_string(f.Fy) + " N, Mz " +
                         std::to_string(f.Mz) + " N m)");
          }
        }

  // What the file has that bdfcar does not evaluate.
  std::set<std::string> known(kReadKeys);
#define BDFCAR_PAC2002_KNOWN(section, name, value) known.insert(#section "/" #name);
  BDFCAR_PAC2002_COEFFICIENTS(BDFCAR_PAC2002_KNOWN)
#undef BDFCAR_PAC2002_KNOWN
  for (const TirFile::Entry& e : tir.entries()) {
    const std::string id = e.section + "/" + e.key;
    if (known.count(id) || kDescriptive.count(id) || isRangeSection(e.section)) continue;
    out.ignoredKeys += (out.ignoredKeys.empty() ? "" : ", ") + e.key + " (line " + std::to_string(e.line) + ")";
  }
  return out;
}

Pac2002File readPac2002(const std::string& path, Pac2002Variant variant) {
  return readPac2002(TirFile::read(path), variant);
}

}  // namespace bdfcar::tyre
