// The format references (docs/SCENARIOS.md, docs/VEHICLES.md, docs/TERRAIN.md)
// against the loaders: every key a loader looks up while it loads every
// shipped scenario, vehicle and terrain must be written in its document as
// `key` (dotted path, [] for array elements). A key added to a loader and used
// by a shipped file, but not documented, fails here.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "config/toml_reader.h"
#include "scenario/scenario_spec.h"
#include "terrain/terrain_file.h"
#include "vehicle/vehicle_file.h"

using namespace bdfcar;
namespace fs = std::filesystem;

namespace {

const fs::path kSource = BDFCAR_SOURCE_DIR;

std::string readText(const fs::path& p) {
  std::ifstream in(p);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::vector<fs::path> tomlFiles(const fs::path& dir, bool recursive) {
  std::vector<fs::path> out;
  if (recursive) {
    for (const auto& e : fs::recursive_directory_iterator(dir))
      if (e.path().extension() == ".toml") out.push_back(e.path());
  } else {
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".toml") out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST(FormatDocs, EveryKeyTheLoadersReadIsDocumented) {
  std::map<std::string, std::string> docOf;  // document path -> the doc that must name its keys
  config::startKeyLog();
  for (const fs::path& f : tomlFiles(kSource / "assets/scenarios", true)) {
    const scenario::ScenarioSpec s = scenario::loadScenarioFile(f.string());
    docOf[f.string()] = "docs/SCENARIOS.md";
    vehicle::loadVehicleFile(s.vehicleFile);
    docOf[s.vehicleFile] = "docs/VEHICLES.md";
    if (!s.terrainFile.empty()) {
      terrain::loadTerrain(s.terrainFile);
      docOf[s.terrainFile] = "docs/TERRAIN.md";
    }
  }
  for (const fs::path& f : tomlFiles(kSource / "assets/vehicles", false)) {
    vehicle::loadVehicleFile(f.string());
    docOf[f.string()] = "docs/VEHICLES.md";
  }
  for (const fs::path& f : tomlFiles(kSource / "assets/terrain", true)) {
    terrain::loadTerrain(f.string());
    docOf[f.string()] = "docs/TERRAIN.md";
  }
  // The bad-input corpus reaches keys no shipped file writes (each file breaks
  // one thing; the keys looked up before the error count).
  for (const fs::path& f : tomlFiles(kSource / "tests/data/bad", false)) {
    const std::string name = f.filename().string();
    const std::string doc = name.rfind("scenario_", 0) == 0  ? "docs/SCENARIOS.md"
                            : name.rfind("vehicle_", 0) == 0 ? "docs/VEHICLES.md"
                            : name.rfind("terrain_", 0) == 0 ? "docs/TERRAIN.md"
                                                             : "";
    if (doc.empty()) continue;
    docOf[f.string()] = doc;
    try {
      if (doc == "docs/SCENARIOS.md") {
        const scenario::ScenarioSpec s = scenario::loadScenarioFile(f.string());
        docOf[s.vehicleFile] = "docs/VEHICLES.md";
        vehicle::loadVehicleFile(s.vehicleFile);
        if (!s.terrainFile.empty()) docOf[s.terrainFile] = "docs/TERRAIN.md", terrain::loadTerrain(s.terrainFile);
      } else if (doc == "docs/VEHICLES.md") {
        vehicle::loadVehicleFile(f.string());
      } else {
        terrain::loadTerrain(f.string());
      }
    } catch (const std::exception&) {
      // Bad on purpose.
    }
  }
  const auto log = config::stopKeyLog();
  std::map<std::string, std::set<std::string>> keys;  // doc -> keys
  for (const auto& [document, key] : log) {
    ASSERT_TRUE(docOf.count(document)) << document << " was read but is not a scenario, vehicle or terrain";
    keys[docOf[document]].insert(key);
  }
  // Every top-level key of a vehicle file has its row in the Layout table.
  {
    const std::string text = readText(kSource / "docs/VEHICLES.md");
    const auto from = text.find("## Layout of a file"), to = text.find("\n## ", from + 1);
    ASSERT_NE(from, std::string::npos) << "docs/VEHICLES.md has no Layout section";
    const std::string layout = text.substr(from, to - from);
    for (const std::string& k : keys["docs/VEHICLES.md"]) {
      if (k.find_first_of(".[") != std::string::npos) continue;
      EXPECT_NE(layout.find("| `" + k + "` |"), std::string::npos)
          << "docs/VEHICLES.md's Layout table has no row for the top-level key `" << k << "`";
    }
  }
  for (const auto& [doc, names] : keys) {
    const std::string text = readText(kSource / doc);
    EXPECT_FALSE(text.empty()) << doc << " is missing";
    for (const std::string& k : names) {
      std::printf("%s %s\n", doc.c_str(), k.c_str());
      EXPECT_NE(text.find("`" + k + "`"), std::string::npos) << doc << " does not document the key `" << k << "`";
    }
  }
}
