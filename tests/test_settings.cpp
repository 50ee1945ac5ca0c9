// Composing config files (config/toml_reader.h): includes merged under the
// including file, and --set KEY=VALUE settings applied over both, checked as
// the files are. A setting must give exactly what editing the file gives.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "config/toml_reader.h"
#include "test_files.h"
#include "scenario/run.h"
#include "scenario/scenario_spec.h"
#include "vehicle/vehicle_file.h"

using namespace bdfcar;
namespace fs = std::filesystem;

namespace {

const fs::path kAssets = fs::path(BDFCAR_SOURCE_DIR) / "assets";

fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / "bdfcar_settings_test";
  fs::create_directories(d / "sub");
  return d / name;
}

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

// The including file wins over what it includes, the later include over the
// earlier; tables merge key by key, arrays are replaced whole.
TEST(Include, MergesUnderTheIncludingFile) {
  write(scratch("sub/a.toml"), "[t]\nx = 1\ny = 1\nlist = [1, 2, 3]\n[only_a]\nk = \"a\"\n");
  write(scratch("sub/b.toml"), "[t]\ny = 2\nz = 2\n");
  write(scratch("top.toml"), "include = [\"sub/a.toml\", \"sub/b.toml\"]\n[t]\nz = 3\nlist = [9]\n");
  config::Table top = config::parseTomlFile(scratch("top.toml").string());
  config::Table t = top.table("t");
  EXPECT_EQ(t.integer("x"), 1);  // a only
  EXPECT_EQ(t.integer("y"), 2);  // b over a
  EXPECT_EQ(t.integer("z"), 3);  // the including file over b
  EXPECT_EQ(t.numbers("list").size(), 1u);
  EXPECT_EQ(top.table("only_a").string("k"), "a");
  EXPECT_FALSE(top.has("include"));
  // A bad value is located in the file that wrote it.
  const std::string e = errorOf([&] { t.reject("y", "something else"); });
  EXPECT_NE(e.find("b.toml:2: key 't.y'"), std::string::npos) << e;
}

// A relative path in an included file is relative to that file: the sedan's
// body mesh is named in parts/reference_sedan.toml as ../../models/...
TEST(Include, PathsAreRelativeToTheFileThatWritesThem) {
  const vehicle::VehicleSpec s = vehicle::loadVehicleFile((kAssets / "vehicles/sedan.toml").string());
  EXPECT_EQ(fs::path(s.geometry.bodyMesh), (kAssets / "models/sedan_body.obj").lexically_normal());
  EXPECT_EQ(s.points.size(), vehicle::loadVehicleFile((kAssets / "vehicles/paper.toml").string()).points.size());
}

// A scenario run with --set settings gives bit for bit the run of a file
// edited to the same values, for a scenario key and a vehicle key.
TEST(Settings, GiveWhatEditingTheFileGives) {
  const std::string jturn = (kAssets / "scenarios/jturn.toml").string();
  // The edited copies: the scenario with another speed, naming an edited vehicle.
  std::ifstream in(jturn);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::regex speed(R"(\nspeed = [^\n]*)");
  ASSERT_TRUE(std::regex_search(text, speed));
  text = std::regex_replace(text, speed, "\nspeed = \"70 km/h\"", std::regex_constants::format_first_only);
  const std::regex vehicleKey(R"(vehicle = "[^"]*")");
  text = std::regex_replace(text, vehicleKey, "vehicle = \"" + scratch("sedan_soft.toml").string() + "\"");
  text = std::regex_replace(text, std::regex(R"(= "\.\./)"), "= \"" + kAssets.string() + "/");  // the terrain
  write(scratch("jturn_edited.toml"), text);
  vehicle::VehicleSpec soft = vehicle::loadVehicleFile((kAssets / "vehicles/sedan.toml").string(),
                                                       {config::parseSetting("springs[0].damping=9000")});
  EXPECT_DOUBLE_EQ(soft.springs[0].damper.coefficient, 9000.0);
  EXPECT_DOUBLE_EQ(soft.springs[1].damper.coefficient, 9000.0);  // mirrored: the file's one element is both sides
  // The edited vehicle file: the sedan's springs array with the damping changed.
  std::string sedan = test::sedanText((kAssets / "vehicles/parts/").string());
  const std::regex firstDamping(R"(\ndamping = [^\n]*)");
  ASSERT_TRUE(std::regex_search(sedan, firstDamping));
  sedan = std::regex_replace(sedan, firstDamping, "\ndamping = 9000.0", std::regex_constants::format_first_only);
  write(scratch("sedan_soft.toml"), sedan);

  const std::vector<config::Setting> settings = {config::parseSetting("start.speed=70 km/h"),
                                                 config::parseSetting("vehicle.springs[0].damping=9000")};
  scenario::Simulation a(scenario::loadScenarioFile(jturn, settings));
  scenario::Simulation b(scenario::loadScenarioFile(scratch("jturn_edited.toml").string()));
  EXPECT_DOUBLE_EQ(a.spec().initialSpeed, 70 / 3.6);
  const scenario::RunResult ra = scenario::runScenario(a, {}), rb = scenario::runScenario(b, {});
  ASSERT_TRUE(ra.ok && rb.ok);
  ASSERT_EQ(ra.samples.size(), rb.samples.size());
  for (size_t i = 0; i < ra.samples.size(); ++i) {
    ASSERT_EQ(ra.samples[i].yawRate, rb.samples[i].yawRate) << i;
    ASSERT_EQ(ra.samples[i].damperForce[0], rb.samples[i].damperForce[0]) << i;
  }
  // And the setting did change the run.
  scenario::Simulation c(scenario::loadScenarioFile(jturn));
  const scenario::RunResult rc = scenario::runScenario(c, {});
  EXPECT_NE(rc.samples.back().yawRate, ra.samples.back().yawRate);
}

// What a setting may be: a TOML value, or a bare word taken as a string; a
// key that the file lacks is added (and then judged by the reader).
TEST(Settings, ValuesAndKeys) {
  write(scratch("plain.toml"), "[a]\nx = 1\nlist = [{ y = 1 }, { y = 2 }]\n");
  config::Table t = config::parseTomlFile(
      scratch("plain.toml").string(),
      {config::parseSetting("a.x=2.5"), config::parseSetting("a.list[1].y=7"), config::parseSetting("a.word=planar"),
       config::parseSetting("a.q=\"80 km/h\""), config::parseSetting("b.new.deep=[1, 2]")});
  config::Table a = t.table("a");
  EXPECT_DOUBLE_EQ(a.number("x"), 2.5);
  EXPECT_EQ(a.tables("list")[1].integer("y"), 7);
  EXPECT_EQ(a.string("word"), "planar");
  EXPECT_DOUBLE_EQ(a.number("q", config::Dimension::Speed), 80 / 3.6);
  EXPECT_EQ(t.table("b").table("new").numbers("deep").size(), 2u);
  EXPECT_NE(errorOf([] { config::parseSetting("=3"); }).find("expected KEY=VALUE"), std::string::npos);
  EXPECT_NE(errorOf([] { config::parseSetting("a..b=3"); }).find("an empty name"), std::string::npos);
  EXPECT_NE(errorOf([] { config::parseSetting("a[x]=3"); }).find("not an array index"), std::string::npos);
  EXPECT_NE(errorOf([&] { config::parseTomlFile(scratch("plain.toml").string(), {config::parseSetting("a.x.y=1")}); })
                .find("'a.x' is 1, not a table"),
            std::string::npos);
}
