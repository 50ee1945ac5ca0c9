#include "sweep/sweep_spec.h"
#include "config/file_kind.h"

#include <cstdio>
#include <filesystem>
#include <random>

namespace bdfcar::app {

using config::Table;

namespace {

constexpr long kMaxCases = 100000;

SweepVariable readVariable(Table& t, bool monteCarlo) {
  SweepVariable v;
  v.keys = t.stringOrStrings("key");
  t.require(!v.keys.empty(), "key", "a key (e.g. \"vehicle.springs[0].stiffness\") or an array of keys set together");
  for (const std::string& k : v.keys) {
    try {
      config::parseSetting(k + "=0");
    } catch (const config::ConfigError& e) {
      t.fail(std::string("not a key path: ") + e.what(), "key");
    }
  }
  v.label = v.keys.front();
  if (!monteCarlo) {
    v.values = t.scalarTexts("values");
  } else {
    const std::string d = t.choice("distribution", {"uniform", "normal"}, "uniform");
    v.distribution = d == "uniform" ? SweepVariable::Distribution::Uniform : SweepVariable::Distribution::Normal;
    const config::Range any{-1e12, 1e12};
    if (v.distribution == SweepVariable::Distribution::Uniform) {
      v.min = t.numberIn("min", any);
      v.max = t.numberIn("max", any);
      t.require(v.max >= v.min, "max", "max >= min");
    } else {
      v.mean = t.numberIn("mean", any);
      v.sd = t.numberIn("sd", config::Range{0.0, 1e12});
    }
    v.unit = t.string("unit", "");
  }
  t.finish();
  return v;
}

}  // namespace

std::string tomlQuoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

namespace {

// A TOML text's label: a string without its quotes, anything else as written.
std::string labelOf(const std::string& text) {
  if (text.size() >= 2 && text.front() == '"' && text.back() == '"') return text.substr(1, text.size() - 2);
  return text;
}

}  // namespace

SweepSpec loadSweepFile(const std::string& path) {
  Table root = config::parseTomlFile(path);
  SweepSpec s;
  s.sourceFile = path;
  Table sw = root.table("sweep");
  s.name = sw.string("name");
  for (const std::string& test : sw.stringOrStrings("tests")) {
    const std::filesystem::path p = std::filesystem::path(test).is_absolute()
                                        ? std::filesystem::path(test)
                                        : std::filesystem::path(sw.folderOf("tests")) / test;
    if (const auto why = config::notARegularFile(p)) sw.fail("the scenario '" + p.string() + "' " + *why, "tests");
    s.tests.push_back(p.lexically_normal().string());
  }
  sw.require(!s.tests.empty(), "tests", "at least one scenario file");
  const std::string mode = sw.choice("mode", {"grid", "monte_carlo"}, "grid");
  s.monteCarlo = mode == "monte_carlo";
  if (s.monteCarlo) {
    s.samples = static_cast<int>(sw.integerIn("samples", 1, kMaxCases));
    s.seed = static_cast<std::uint64_t>(sw.integerIn("seed", 0, 1L << 62, 1));
  }
  for (const std::string& text : sw.stringOrStrings("set")) {
    try {
      s.fixed.push_back(config::parseSetting(text));
    } catch (const config::ConfigError& e) {
      sw.fail(e.what(), "set");
    }
  }
  sw.finish();
  for (Table& v : root.optionalTables("vary")) s.vary.push_back(readVariable(v, s.monteCarlo));
  if (auto p = root.optionalTable("plot")) {
    s.plotMetric = p->string("metric", "");
    s.plotChannel = p->string("channel", s.plotChannel);
    p->finish();
  }
  root.finish();
  long cases = static_cast<long>(s.tests.size()) * (s.monteCarlo ? s.samples : 1);
  for (const SweepVariable& v : s.vary)
    if (!s.monteCarlo) cases *= static_cast<long>(v.values.size());
  if (cases > kMaxCases)
    root.fail("the sweep has " + std::to_string(cases) + " cases, more than " + std::to_string(kMaxCases) +
              ": split it");
  return s;
}

std::vector<SweepCase> sweepCases(const SweepSpec& spec) {
  std::vector<SweepCase> out;
  std::mt19937_64 random(spec.seed);
  auto add = [&](const std::string& test, const std::vector<std::string>& texts) {
    SweepCase c;
    char id[32];
    std::snprintf(id, sizeof id, "case_%04zu", out.size() + 1);
    c.id = id;
    c.test = test;
    c.settings = spec.fixed;
    for (size_t i = 0; i < spec.vary.size(); ++i) {
      c.values.push_back(labelOf(texts[i]));
      for (const std::string& k : spec.vary[i].keys) c.settings.push_back({k, texts[i], ""});
    }
    out.push_back(c);
  };
  for (const std::string& test : spec.tests) {
    if (spec.monteCarlo) {
      for (int n = 0; n < spec.samples; ++n) {
        std::vector<std::string> texts;
        for (const SweepVariable& v : spec.vary) {
          double x;
          if (v.distribution == SweepVariable::Distribution::Uniform)
            x = std::uniform_real_distribution<double>(v.min, v.max)(random);
          else
            x = std::normal_distribution<double>(v.mean, v.sd)(random);
          char text[40];
          std::snprintf(text, sizeof text, "%.10g", x);
          texts.push_back(v.unit.empty() ? std::string(text) : tomlQuoted(std::string(text) + " " + v.unit));
        }
        add(test, texts);
      }
      continue;
    }
    // The grid: an odometer over the variables' values, the last fastest.
    std::vector<size_t> at(spec.vary.size(), 0);
    for (;;) {
      std::vector<std::string> texts;
      for (size_t i = 0; i < spec.vary.size(); ++i) texts.push_back(spec.vary[i].values[at[i]]);
      add(test, texts);
      size_t i = spec.vary.size();
      while (i > 0 && ++at[i - 1] == spec.vary[i - 1].values.size()) at[--i] = 0;
      if (i == 0) break;
    }
  }
  return out;
}

}  // namespace bdfcar::app
