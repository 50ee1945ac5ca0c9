// `bdfcar tyre FILE [--variant textbook|chrono9] [--friction MU] [--out DIR]`:
// a tyre's characteristic curves and headline numbers (app/tyre_curves.h),
// for a Magic Formula .tir file or for each distinct tyre of a vehicle
// file's wheels; --out writes the curves as CSV (degrees for angles) and
// PNG plots.
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_errors.h"
#include "commands.h"
#include "config/units.h"
#include "scenario/row_file.h"
#include "session/plots.h"
#include "tyre/pac2002_file.h"
#include "tyre_curves.h"
#include "vehicle/vehicle_builder.h"
#include "vehicle/vehicle_file.h"
#include "vehicle/vehicle_sheet.h"

namespace bdfcar::app {

namespace {

using config::degToRad;
using config::radToDeg;

// The Fiala tyre has no nominal load of its own: the vehicle's static
// corner load stands in, or this reference load where that cannot be had.
constexpr double kReferenceLoad = 4000;  // N

// One distinct tyre of the input, with the wheels that carry it.
struct TyreEntry {
  tyre::TyreParams params;
  std::string wheels;       // "FL FR RL RR"; empty for a .tir file
  double nominalLoad = 0;   // N
  std::string loadSource;   // where the nominal load comes from
};

bool isTirFile(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return ext == ".tir";
}

std::string loadText(double Fz) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0fN", Fz);
  return buf;
}

std::string format(const char* fmt, double x) {
  char buf[48];
  std::snprintf(buf, sizeof buf, fmt, x);
  return buf;
}

// The curves as CSV files in dir: named columns, units in the names.
void writeCsv(const std::filesystem::path& file, const std::vector<std::string>& header,
              const std::vector<const std::vector<double>*>& columns, const std::vector<double>& scale) {
  std::string text;
  for (size_t k = 0; k < header.size(); ++k) {
    if (k) text += ',';
    text += header[k];
  }
  text += "\n";
  char buf[32];
  for (size_t i = 0; i < columns[0]->size(); ++i) {
    for (size_t k = 0; k < columns.size(); ++k) {
      std::snprintf(buf, sizeof buf, "%s%.9g", k ? "," : "", (*columns[k])[i] * scale[k]);
      text += buf;
    }
    text += "\n";
  }
  scenario::RowFile f(file.string());
  f.append(text);
  f.close();
}

std::string writeCurves(const TyreCurves& c, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  const double deg = radToDeg(1.0);
  std::vector<std::string> fy, mz, fx;
  for (double f : TyreCurves::loadFactors) {
    const std::string at = "_at_" + loadText(f * c.nominalLoad);
    fy.push_back("Fy_N" + at);
    mz.push_back("Mz_Nm" + at);
    fx.push_back("Fx_N" + at);
  }
  {
    std::vector<std::string> h = {"alpha_deg"};
    h.insert(h.end(), fy.begin(), fy.end());
    h.insert(h.end(), mz.begin(), mz.end());
    writeCsv(dir / "lateral.csv", h, {&c.alpha, &c.Fy[0], &c.Fy[1], &c.Fy[2], &c.Mz[0], &c.Mz[1], &c.Mz[2]},
             {deg, 1, 1, 1, 1, 1, 1});
  }
  {
    std::vector<std::string> h = {"kappa"};
    h.insert(h.end(), fx.begin(), fx.end());
    writeCsv(dir / "longitudinal.csv", h, {&c.kappa, &c.Fx[0], &c.Fx[1], &c.Fx[2]}, {1, 1, 1, 1});
  }
  std::vector<std::string> ellipseX, ellipseY;
  {
    std::vector<std::string> h = {"kappa"};
    std::vector<const std::vector<double>*> cols = {&c.kappa};
    for (size_t j = 0; j < TyreCurves::combinedAlphaDeg.size(); ++j) {
      const std::string at = "_alpha_" + format("%g", TyreCurves::combinedAlphaDeg[j]) + "deg";
      ellipseX.push_back("Fx_N" + at);
      ellipseY.push_back("Fy_N" + at);
      h.push_back(ellipseX.back());
      h.push_back(ellipseY.back());
      cols.push_back(&c.combinedFx[j]);
      cols.push_back(&c.combinedFy[j]);
    }
    writeCsv(dir / "combined.csv", h, cols, std::vector<double>(cols.size(), 1.0));
  }
  {
    std::vector<double> Fz, ca, caModel, ck, ckModel;
    for (const LoadStiffness& s : c.stiffness) {
      Fz.push_back(s.Fz);
      ca.push_back(s.cornering);
      caModel.push_back(s.corneringModel);
      ck.push_back(s.slip);
      ckModel.push_back(s.slipModel);
    }
    writeCsv(dir / "stiffness.csv",
             {"Fz_N", "cornering_stiffness_N_per_rad", "cornering_stiffness_model_N_per_rad", "slip_stiffness_N",
              "slip_stiffness_model_N"},
             {&Fz, &ca, &caModel, &ck, &ckModel}, {1, 1, 1, 1, 1});
  }
  auto csv = [&](const char* name) { return (dir / (std::string(name) + ".csv")).string(); };
  auto png = [&](const char* name) { return (dir / (std::string(name) + ".png")).string(); };
  const std::vector<CsvPlot> plots = {
      {csv("lateral"), png("lateral_force"), "lateral force Fy (N, ISO: opposes alpha) over the slip angle, pure slip",
       "alpha_deg", fy},
      {csv("lateral"), png("aligning_moment"), "aligning moment Mz (N m, ISO) over the slip angle, pure slip",
       "alpha_deg", mz},
      {csv("longitudinal"), png("longitudinal_force"), "longitudinal force Fx (N) over the slip ratio, pure slip",
       "kappa", fx},
      {csv("combined"), png("combined"),
       "combined slip at " + loadText(c.nominalLoad) + ": Fy (N) over Fx (N), kappa swept at fixed slip angles",
       "Fx_N", ellipseY, ellipseX},
      {csv("stiffness"), png("stiffness"), "cornering stiffness (N/rad) and slip stiffness (N) over the load (N)",
       "Fz_N", {"cornering_stiffness_N_per_rad", "slip_stiffness_N"}},
  };
  return plotCsvColumns(plots, (dir / "plots.gp").string());
}

void printPeak(const char* label, const CurvePeak (&p)[2], const char* slipName, bool angle, const char* unit) {
  std::printf("    %-32s", label);
  for (int s = 0; s < 2; ++s) {
    const double slip = angle ? radToDeg(p[s].slip) : p[s].slip;
    if (unit[0] == '\0')
      std::printf("%s%.4f at %s %+.*f%s (%+.1f N)", s ? "; " : "", p[s].mu, slipName, angle ? 2 : 4, slip,
                  angle ? " deg" : "", p[s].value);
    else
      std::printf("%s%+.2f %s at %s %+.2f deg", s ? "; " : "", p[s].value, unit, slipName, slip);
    if (p[s].atSweepEnd) std::printf(" (the sweep's end: the peak is beyond it)");
  }
  std::printf("\n");
}

// How the model combines the slips (the combined.csv curves).
std::string combinedLaw(const tyre::TyreParams& p) {
  if (std::holds_alternative<tyre::FialaParams>(p))
    return "only through the friction factor U(S): Fx and Fy each up to U Fz, no friction ellipse";
  const tyre::Pac2002Params& pac = std::get<tyre::Pac2002Params>(p);
  if (!pac.combined) return "none (USE_MODE 3): Fx and Fy as in pure slip";
  if (pac.ellipse) return "Chrono's friction ellipse";
  if (pac.c.RBX1 == 0 && pac.c.RBY1 == 0 && pac.c.RVY1 == 0 && pac.c.RVY2 == 0)  // Gxa = Gyk = 1, SVyk = 0 (camber 0)
    return "the PAC2002 weighting functions, but the file has no RBX1, RBY1, RVY*: Fx and Fy as in pure slip";
  return "the PAC2002 weighting functions Gxa, Gyk";
}

void printCurves(const TyreEntry& e, const TyreCurves& c) {
  std::printf("  model %s", c.model.c_str());
  if (const auto* pac = std::get_if<tyre::Pac2002Params>(&e.params))
    std::printf(", measured %s, mounted %s (%s)", pac->measuredLeft ? "left" : "right",
                pac->mountedLeft ? "left" : "right", pac->file.c_str());
  std::printf("\n  unloaded radius %.4f m; nominal load %.1f N (%s)\n", c.unloadedRadius, c.nominalLoad,
              e.loadSource.c_str());
  std::printf("  road friction %.3g (the tyre's reference friction %.3g%s)\n", c.friction, c.referenceFriction,
              c.friction == c.referenceFriction ? ": its own peak factors" : "");
  std::printf("  ISO convention (alpha = atan(vy/|vx|), kappa > 0 driving, Fy < 0 and Mz > 0 for alpha > 0), pure slip, "
              "camber 0\n");
  std::printf("  combined slip: %s\n", combinedLaw(e.params).c_str());
  const LoadStiffness& s = c.atNominal;
  std::printf("  at the nominal load:\n");
  std::printf("    %-32s%.1f N/deg, %.0f N/rad (slope at alpha = 0); model %.0f N/rad\n", "cornering stiffness",
              degToRad(s.cornering), s.cornering, s.corneringModel);
  std::printf("    %-32s%.0f N (slope at kappa = 0); model %.0f N\n", "longitudinal slip stiffness", s.slip,
              s.slipModel);
  printPeak("peak lateral |Fy|/Fz", c.lateral, "alpha", true, "");
  printPeak("peak longitudinal |Fx|/Fz", c.longitudinal, "kappa", false, "");
  printPeak("aligning-moment peak", c.aligning, "alpha", true, "N m");
  std::printf("  cornering stiffness over the load:\n    %8s %10s %10s %12s %12s %12s\n", "x nominal", "Fz (N)",
              "N/deg", "N/rad", "model N/rad", "slip (N)");
  for (double f : {0.5, 1.0, 1.5, 2.0}) {
    const LoadStiffness& r = stiffnessAt(c, f);
    std::printf("    %8.1f %10.0f %10.1f %12.0f %12.0f %12.0f\n", f, r.Fz, degToRad(r.cornering), r.cornering,
                r.corneringModel, r.slip);
  }
}

std::vector<TyreEntry> tyresOfTir(const std::string& path, const std::string& variant) {
  const tyre::Pac2002Variant v = variant == "chrono9" ? tyre::Pac2002Variant::Chrono9 : tyre::Pac2002Variant::Textbook;
  tyre::Pac2002File f = tyre::readPac2002(path, v);
  if (!f.ignoredKeys.empty())
    std::fprintf(stderr, "warning: %s: keys bdfcar's PAC2002 evaluation does not read, ignored: %s\n", path.c_str(),
                 f.ignoredKeys.c_str());
  f.params.mountedLeft = f.params.measuredLeft;  // as measured: no mirroring
  return {{f.params, "", f.params.nominalLoad, "FNOMIN"}};
}

std::vector<TyreEntry> tyresOfVehicle(const std::string& path) {
  const vehicle::VehicleSpec spec = vehicle::loadVehicleFile(path);
  // The static corner loads, for the tyres without a nominal load (Fiala).
  std::vector<double> corner;
  std::string why;
  try {
    const vehicle::VehicleSheet sheet = vehicle::vehicleSheet(vehicle::buildVehicle(spec));
    for (const vehicle::WheelSpec& w : spec.wheels)
      corner.push_back(sheet.axleLoad[w.position.front() == 'F' ? 0 : 1] / 2);
  } catch (const std::exception& e) {
    why = e.what();
  }
  std::vector<TyreEntry> out;
  std::vector<std::vector<size_t>> users;
  for (size_t i = 0; i < spec.wheels.size(); ++i) {
    size_t k = 0;
    while (k < out.size() && !sameTyre(out[k].params, spec.wheels[i].tyre)) ++k;
    if (k == out.size()) {
      out.push_back({spec.wheels[i].tyre, "", 0, ""});
      users.emplace_back();
    }
    out[k].wheels += (out[k].wheels.empty() ? "" : " ") + spec.wheels[i].position;
    users[k].push_back(i);
  }
  for (size_t k = 0; k < out.size(); ++k) {
    if (const auto* pac = std::get_if<tyre::Pac2002Params>(&out[k].params)) {
      out[k].nominalLoad = pac->nominalLoad;
      out[k].loadSource = "FNOMIN";
    } else if (!corner.empty()) {
      double sum = 0;
      std::string each;
      for (size_t i : users[k]) {
        sum += corner[i];
        each += format(" %.0f", corner[i]);
      }
      out[k].nominalLoad = sum / users[k].size();
      out[k].loadSource = "the mean static corner load of its wheels, N:" + each;
    } else {
      out[k].nominalLoad = kReferenceLoad;
      out[k].loadSource = "a reference load: the static corner loads could not be derived (" + why + ")";
    }
  }
  return out;
}

int runTyre(const std::string& path, const std::string& variant, bool variantGiven, double friction, bool frictionGiven,
            const std::string& out) {
  const bool tir = isTirFile(path);
  if (!tir && variantGiven)
    throw std::invalid_argument("--variant is for a .tir file: a vehicle file names its tyres' variant");
  const std::vector<TyreEntry> tyres = tir ? tyresOfTir(path, variant) : tyresOfVehicle(path);
  std::vector<std::string> written;
  for (const TyreEntry& e : tyres) {
    const double mu = frictionGiven ? friction : std::visit([](const auto& m) { return m.referenceFriction; }, e.params);
    const TyreCurves c = tyreCurves(e.params, e.nominalLoad, mu);
    std::printf("tyre: %s%s%s\n", path.c_str(), e.wheels.empty() ? "" : ", wheels ", e.wheels.c_str());
    printCurves(e, c);
    if (!out.empty()) {
      std::string sub = e.wheels;
      for (char& ch : sub)
        if (ch == ' ') ch = '_';
      const std::filesystem::path dir = tyres.size() > 1 ? std::filesystem::path(out) / sub : std::filesystem::path(out);
      const std::string plots = writeCurves(c, dir);
      std::printf("  curves: %s/{lateral,longitudinal,combined,stiffness}.csv%s%s\n", dir.string().c_str(),
                  plots.empty() ? " and PNG plots" : "; ", plots.c_str());
    }
    std::printf("\n");
  }
  return kExitOk;
}

}  // namespace

void addTyreCommand(CLI::App& app, CommandList& commands) {
  CLI::App* cmd = app.add_subcommand(
      "tyre", "A tyre's characteristic curves: cornering and slip stiffness (also over the load), peak lateral and "
              "longitudinal friction and where they are, the aligning-moment peak, for a PAC2002 .tir file or each "
              "tyre of a vehicle file (docs/VEHICLES.md)");
  auto path = std::make_shared<std::string>();
  cmd->add_option("file", *path, "A Magic Formula .tir file, or a vehicle file (assets/vehicles/*.toml)")
      ->required()
      ->check(CLI::ExistingFile);
  auto variant = std::make_shared<std::string>("textbook");
  CLI::Option* variantOpt = cmd->add_option("--variant", *variant, "Evaluation of a .tir file: textbook (default) or "
                                                                   "chrono9 (as Chrono 9.0.1's ChPac02Tire)")
                                ->check(CLI::IsMember({"textbook", "chrono9"}));
  auto friction = std::make_shared<double>(0.8);
  CLI::Option* frictionOpt =
      cmd->add_option("--friction", *friction,
                      "Road friction mu (default: each tyre's reference friction, i.e. its own peak factors)")
          ->check(CLI::Range(0.01, 3.0));
  auto out = std::make_shared<std::string>();
  cmd->add_option("--out", *out,
                  "Directory for the curves: lateral.csv, longitudinal.csv, combined.csv, stiffness.csv and PNG plots "
                  "(one subdirectory per tyre where a vehicle has several)");
  commands.push_back({cmd, [=] {
                        return reportErrors([&] {
                          return runTyre(*path, *variant, variantOpt->count() > 0, *friction, frictionOpt->count() > 0,
                                         *out);
                        });
                      }});
}

}  // namespace bdfcar::app
