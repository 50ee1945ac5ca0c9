// A drive keeps every byte: reset, rewind and a divergence start a new
// telemetry segment in the same file (a column), never a truncation; the
// recording holds them as events and replays to the same telemetry; a
// recording refuses to replay against other data.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>

#include <iterator>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "session/drive_session.h"
#include "session/drive_picks.h"
#include "session/pause_menu.h"
#include "scenario_overrides.h"

#include "test_files.h"

using namespace bdfcar;

namespace {

using test::asset;
using test::readFile;
std::string temp(const std::string& name) { return test::tempFile("session", name); }
std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream s(text);
  for (std::string l; std::getline(s, l);) out.push_back(l);
  return out;
}
scenario::DriverInput personAt(int i) {
  const double t = 0.01 * i;
  return {0.3 * std::sin(2.0 * t), t < 1.0 ? 0.5 : 0.0, 0.0};
}

// A drive of `ticks` of a person's inputs, recorded to `path`.
void recordTicks(const scenario::ScenarioSpec& spec, const std::string& path, int ticks) {
  app::SessionOptions o;
  o.recordPath = path;
  app::DriveSession d(spec, o);
  for (int i = 0; i < ticks; ++i) ASSERT_TRUE(d.tick(personAt(i)));
  d.closeOutputs();
}

// 100 ticks, reset, 60 ticks, rewind, 40 ticks.
void driveWithResetAndRewind(app::DriveSession& d) {
  for (int i = 0; i < 100; ++i) ASSERT_TRUE(d.tick(personAt(i)));
  d.restart();
  for (int i = 0; i < 60; ++i) ASSERT_TRUE(d.tick(personAt(i)));
  ASSERT_TRUE(d.rewind());
  for (int i = 60; i < 100; ++i) ASSERT_TRUE(d.tick(personAt(i)));
}

// The telemetry of a recording replayed in a rewindable session (as `drive --replay --batch`).
std::string replayedTelemetry(const scenario::ScenarioSpec& spec, const app::Recording& r, const std::string& csv) {
  {
    app::SessionOptions o;
    o.telemetryPath = csv;
    o.rewindable = true;
    app::DriveSession d(spec, o);
    for (const app::RecordedTick& e : r.entries)
      if (!d.replay(e)) return "replay failed: " + d.failure();
    d.closeOutputs();
  }
  return readFile(csv);
}

}  // namespace

TEST(DriveSession, ResetAndRewindStartSegmentsAndKeepEveryRow) {
  const scenario::ScenarioSpec spec = scenario::loadScenarioFile(asset("scenarios/drive.toml"));
  const std::string csv = temp("segments.csv"), rec = temp("segments.rec");
  {
    app::SessionOptions o;
    o.telemetryPath = csv;
    o.recordPath = rec;
    o.rewindable = true;
    app::DriveSession d(spec, o);
    driveWithResetAndRewind(d);
    EXPECT_EQ(d.segment(), 2);
    d.closeOutputs();
  }
  const std::vector<std::string> rows = lines(readFile(csv));
  // Header, the start, one row per tick, and the first row of each new segment.
  ASSERT_EQ(rows.size(), 1u + 1u + 200u + 2u);
  // The segment column, by name.
  auto field = [](const std::string& row, size_t index) {
    size_t start = 0;
    for (size_t k = 0; k < index; ++k) start = row.find(',', start) + 1;
    return row.substr(start, row.find(',', start) - start);
  };
  size_t column = 0;
  while (field(rows[0], column) != "segment") ASSERT_LT(++column, 100u);
  std::set<std::string> segments;
  for (size_t i = 1; i < rows.size(); ++i) segments.insert(field(rows[i], column));
  EXPECT_EQ(segments, (std::set<std::string>{"0", "1", "2"}));
  // The recording: 200 inputs with the reset and the rewind between them.
  const app::Recording r = app::readRecording(rec);
  EXPECT_EQ(r.inputCount(), 200);
  ASSERT_EQ(r.entries.size(), 202u);
  EXPECT_EQ(r.entries[100].kind, app::RecordedTick::Kind::Reset);
  EXPECT_EQ(r.entries[161].kind, app::RecordedTick::Kind::Rewind);
  EXPECT_EQ(r.vehicleHash, app::fileContentHash(spec.vehicleFile));
  EXPECT_TRUE(app::replayMismatch(r, spec).empty());
  // Replayed, it gives the very same telemetry.
  EXPECT_EQ(readFile(csv), replayedTelemetry(spec, r, temp("segments_replay.csv")));
}

TEST(DriveSession, StartingAndStoppingARecordingKeepsTheFormerOne) {
  const scenario::ScenarioSpec spec = scenario::loadScenarioFile(asset("scenarios/drive.toml"));
  const std::string first = temp("first.rec"), second = temp("second.rec");
  app::SessionOptions o;
  o.recordPath = first;
  app::DriveSession d(spec, o);
  for (int i = 0; i < 50; ++i) ASSERT_TRUE(d.tick(personAt(i)));
  d.startRecording(second);  // F9 with a recording running: the first is closed, whole
  for (int i = 0; i < 30; ++i) ASSERT_TRUE(d.tick(personAt(i)));
  EXPECT_EQ(d.stopRecording(), 30);
  EXPECT_FALSE(d.recording());
  for (int i = 0; i < 10; ++i) ASSERT_TRUE(d.tick(personAt(i)));
  EXPECT_EQ(app::readRecording(first).inputCount(), 50);
  EXPECT_EQ(app::readRecording(second).inputCount(), 30);
}

TEST(DriveSession, ARecordingRefusesToReplayAgainstAnotherVehicleOrTick) {
  scenario::ScenarioSpec spec = scenario::loadScenarioFile(asset("scenarios/drive.toml"));
  const std::string rec = temp("mismatch.rec");
  recordTicks(spec, rec, 5);
  const app::Recording r = app::readRecording(rec);
  scenario::ScenarioSpec other = spec;
  other.vehicleFile = asset("vehicles/paper.toml");
  EXPECT_NE(app::replayMismatch(r, other).find("recorded with the vehicle"), std::string::npos);
  other = spec;
  other.tick = 0.02;
  EXPECT_NE(app::replayMismatch(r, other).find("tick"), std::string::npos);
  other = spec;
  other.integrator.step = 0.005;  // another step replays the same drive
  EXPECT_TRUE(app::replayMismatch(r, other).empty());
}

// The recording's header is what makes the check: a recording without its
// content hashes (an old one, or one whose header was deleted) is refused
// (--replay-anyway replays it all the same); one with no whole tick is
// refused when read; a last line cut off (a kill, a full disk) is dropped
// and the whole lines before it replay.
TEST(DriveSession, ARecordingWithoutItsHeaderOrTicksIsRefusedAndACutLineDropped) {
  scenario::ScenarioSpec spec = scenario::loadScenarioFile(asset("scenarios/drive.toml"));
  const std::string rec = temp("header.rec");
  recordTicks(spec, rec, 5);
  std::string text;
  {
    std::ifstream in(rec);
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  auto write = [](const std::string& path, const std::string& content) { std::ofstream(path, std::ios::binary) << content; };
  // The header lines removed: the ticks alone.
  std::string ticksOnly;
  {
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
      if (!line.empty() && (std::isdigit(static_cast<unsigned char>(line[0])) || line[0] == '#')) ticksOnly += line + "\n";
  }
  const std::string headerless = temp("headerless.rec");
  write(headerless, ticksOnly);
  const app::Recording h = app::readRecording(headerless);
  EXPECT_EQ(h.inputCount(), 5);
  EXPECT_NE(app::replayMismatch(h, spec).find("does not name the content"), std::string::npos);

  // Header only, and empty: no tick to replay.
  auto refused = [&](const std::string& content, const std::string& expected) {
    const std::string path = temp("refused.rec");
    write(path, content);
    try {
      app::readRecording(path);
      ADD_FAILURE() << "accepted: " << expected;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("refused.rec:"), std::string::npos) << e.what();
    }
  };
  refused(text.substr(0, text.find("\n0 ") + 1), "no recorded ticks");
  refused("", "no recorded ticks");

  // Cut inside the last tick: the four whole ticks replay, the cut one is dropped.
  const std::string cut = temp("cut.rec");
  write(cut, text.substr(0, text.size() - 7));
  const app::Recording c = app::readRecording(cut);
  EXPECT_EQ(c.inputCount(), 4);
  EXPECT_GT(c.droppedLine, 0);
  EXPECT_TRUE(app::replayMismatch(c, spec).empty());
  // Cut inside the only tick.
  const size_t firstTick = text.find("\n0 ") + 1;
  refused(text.substr(0, firstTick + 5), "cut off");
}

// A drive in the car with a powertrain: gear requests, the handbrake and a
// clutch pedal are recorded with the ticks and replayed to the very same
// telemetry, across a rewind (the transmission's state is in the snapshot).
TEST(DriveSession, APowertrainDriveWithShiftsReplaysBitForBit) {
  const scenario::ScenarioSpec spec = scenario::loadScenarioFile(asset("scenarios/drive_powertrain.toml"));
  auto person = [](int i) {
    scenario::DriverInput in;
    in.steer = 0.1 * std::sin(0.02 * i);
    in.throttle = i < 150 ? 1.0 : 0.2;
    in.shift = i == 120 ? 1 : i == 160 ? -1 : 0;      // a manual upshift, then a downshift
    in.handbrake = i >= 180 ? 0.5 : 0.0;
    in.clutchPedal = i >= 190;                          // a pedal, pressed halfway
    in.clutch = i >= 190 ? 0.5 : 0.0;
    return in;
  };
  const std::string csv = temp("powertrain.csv"), rec = temp("powertrain.rec");
  int topGear = 0;
  {
    app::SessionOptions o;
    o.telemetryPath = csv;
    o.recordPath = rec;
    o.rewindable = true;
    app::DriveSession d(spec, o);
    for (int i = 0; i < 140; ++i) {
      ASSERT_TRUE(d.tick(person(i)));
      topGear = std::max(topGear, d.simulation().powertrainChannels().gear);
    }
    ASSERT_TRUE(d.rewind());
    for (int i = 140; i < 200; ++i) ASSERT_TRUE(d.tick(person(i)));
    d.closeOutputs();
  }
  EXPECT_GE(topGear, 2);  // the car pulled away and shifted
  const app::Recording r = app::readRecording(rec);
  ASSERT_EQ(r.inputCount(), 200);
  EXPECT_EQ(r.entries[120].input.shift, 1);
  EXPECT_EQ(r.entries[161].input.shift, -1);  // after the rewind event
  EXPECT_TRUE(r.entries[195].input.clutchPedal);
  EXPECT_EQ(r.entries[195].input.handbrake, 0.5);
  EXPECT_EQ(readFile(csv), replayedTelemetry(spec, r, temp("powertrain_replay.csv")));
  // The powertrain's columns are there.
  EXPECT_NE(readFile(csv).find("engine_rpm,gear,clutch"), std::string::npos);
}

// The HUD shows the course's lines from the moment the car enters it (the
// judge's entry time), not before; after the exit gate the course time is the
// judge's exit minus entry, and the verdict reads PASSED.
TEST(DriveSession, TheHudShowsTheCourseFromItsEntry) {
  const scenario::ScenarioSpec spec = scenario::loadScenarioFile(asset("scenarios/iso_lane_change.toml"));
  app::DriveSession d(spec, {});
  bool sawBeforeEntry = false, sawInside = false;
  while (!d.finished()) {
    ASSERT_TRUE(d.tick(std::nullopt)) << d.failure();
    const auto c = d.courseResult();
    ASSERT_TRUE(c.has_value());
    const vehicle::HudInfo h = d.hud(1.0, 0.0, "");
    if (c->entryTime < 0) {
      sawBeforeEntry = true;
      EXPECT_EQ(h.coneHits, -1) << "t = " << d.time();
      EXPECT_EQ(h.courseTime, -1.0) << "t = " << d.time();
    } else {
      sawInside = true;
      EXPECT_EQ(h.coneHits, c->coneHits);
      if (c->exitTime < 0) {
        EXPECT_NEAR(h.courseTime, d.lastSample().t - c->entryTime, 1e-12);
      }
    }
  }
  EXPECT_TRUE(sawBeforeEntry && sawInside);
  const auto c = d.courseResult();
  ASSERT_TRUE(c.has_value() && c->exitTime >= 0);
  const vehicle::HudInfo h = d.hud(1.0, 0.0, "");
  EXPECT_EQ(h.courseTime, c->exitTime - c->entryTime);
  EXPECT_EQ(h.verdict, "PASSED");
}

// Rewind goes back 0.5 s further at each press, up to the start: pressed ten
// times while driving (three ticks between presses, as a held key repeats)
// or while paused (no tick between), the drive is 5 s earlier; a press after
// driving on for a while starts again from the newest snapshot.
TEST(DriveSession, TenRewindsGoBackFiveSecondsDrivingOrPaused) {
  const scenario::ScenarioSpec spec = scenario::loadScenarioFile(asset("scenarios/drive.toml"));
  const scenario::DriverInput cruise{0.0, 0.2, 0.0};
  for (const int ticksBetween : {3, 0}) {
    SCOPED_TRACE(ticksBetween);
    app::SessionOptions o;
    o.rewindable = true;
    app::DriveSession d(spec, o);
    const double t0 = d.time();
    for (int i = 0; i < 1200; ++i) ASSERT_TRUE(d.tick(cruise)) << d.failure();
    ASSERT_NEAR(d.time() - t0, 12.0, 1e-9);
    for (int press = 1; press <= 10; ++press) {
      ASSERT_TRUE(d.rewind());
      // Snapshots every 0.5 s: the first press lands on the one at 11.5 s.
      EXPECT_NEAR(d.time() - t0, 12.0 - 0.5 * press, 1e-9) << "press " << press;
      for (int i = 0; i < ticksBetween; ++i) ASSERT_TRUE(d.tick(cruise)) << d.failure();
    }
    // Driven on for 2 s from there: a new press goes back to the newest snapshot.
    for (int i = 0; i < 200 - ticksBetween; ++i) ASSERT_TRUE(d.tick(cruise)) << d.failure();
    ASSERT_NEAR(d.time() - t0, 9.0, 1e-9);
    ASSERT_TRUE(d.rewind());
    EXPECT_NEAR(d.time() - t0, 8.5, 1e-9);
    // Held on, it reaches the start and stops there.
    int presses = 0;
    while (d.rewind()) ASSERT_LT(++presses, 100);
    EXPECT_NEAR(d.time() - t0, 0.0, 1e-9);
    EXPECT_EQ(presses, 17);  // 8.0, 7.5, ... 0.5, then the start
  }
}

// The HUD's pedal line under a speed hold: a car without a powertrain shows
// the speed it holds (the hold drives the wheels, the throttle input is 0);
// one with a powertrain shows the throttle the hold works.
TEST(DriveSession, TheHudShowsWhatASpeedHoldDoes) {
  scenario::ScenarioSpec spec = scenario::loadScenarioFile(asset("scenarios/jturn.toml"));
  {
    app::DriveSession d(spec, {});
    for (int i = 0; i < 50; ++i) ASSERT_TRUE(d.tick(std::nullopt)) << d.failure();
    const vehicle::HudInfo h = d.hud(1.0, 0.0, "");
    EXPECT_NEAR(h.speedHold, 80 / 3.6, 1e-9);
    EXPECT_EQ(h.throttle, 0.0);
  }
  spec.vehicleFile = asset("vehicles/sedan_drive.toml");
  app::DriveSession d(spec, {});
  for (int i = 0; i < 50; ++i) ASSERT_TRUE(d.tick(std::nullopt)) << d.failure();
  const vehicle::HudInfo h = d.hud(1.0, 0.0, "");
  EXPECT_EQ(h.speedHold, -1.0);
  EXPECT_GT(h.throttle, 0.02);  // drag and rolling at 80 km/h need some
  EXPECT_LE(h.throttle, 1.0);
}

// The pause menu: resume, restart, a "go to" per place, quit; up and down
// wrap round; select gives the highlighted item's choice and closes.
TEST(PauseMenu, ListsThePlacesAndGivesTheChoice) {
  const std::vector<scenario::Place> places{{"hill", 1, 2, 0}, {"skid pad", 3, 4, 0}};
  app::PauseMenu m(places);
  EXPECT_FALSE(m.isOpen());
  m.open();
  ASSERT_EQ(m.items(), 5);
  m.up();  // from the first to the last: quit
  EXPECT_EQ(m.selected(), 4);
  m.down();
  m.down();
  m.down();
  m.down();  // resume, restart, hill, skid pad
  EXPECT_NE(m.text().find("> go to: skid pad"), std::string::npos) << m.text();
  const app::MenuChoice c = m.select();
  EXPECT_EQ(c.kind, app::MenuChoice::Kind::GoTo);
  EXPECT_EQ(c.place, 1);
  EXPECT_FALSE(m.isOpen());
  m.open();
  EXPECT_EQ(m.select().kind, app::MenuChoice::Kind::Resume);  // opens at its first item
}

// Where the drive offers them, the car and the fidelity: each item cycles
// through its values when chosen and the menu stays open; "drive them here"
// closes it and gives the values shown.
TEST(PauseMenu, CyclesTheCarAndTheFidelityAndDrivesThemHere) {
  const std::vector<scenario::Place> places{{"hill", 1, 2, 0}};
  const app::MenuPicks picks{{"coupe", "sedan", "van"}, {"linkage", "kinematic", "planar", "auto"}, 1, 3};
  app::PauseMenu m(places, picks);
  m.open();
  ASSERT_EQ(m.items(), 7);  // resume, restart, hill, car, fidelity, drive them here, quit
  for (int i = 0; i < 3; ++i) m.down();
  EXPECT_NE(m.text().find("> car: sedan"), std::string::npos) << m.text();
  EXPECT_EQ(m.select().kind, app::MenuChoice::Kind::Cycled);
  EXPECT_TRUE(m.isOpen());
  EXPECT_NE(m.text().find("> car: van"), std::string::npos) << m.text();
  m.down();
  EXPECT_NE(m.text().find("> fidelity: auto"), std::string::npos) << m.text();
  m.select();
  m.select();  // auto -> linkage -> kinematic
  EXPECT_NE(m.text().find("> fidelity: kinematic"), std::string::npos) << m.text();
  m.down();
  const app::MenuChoice c = m.select();
  EXPECT_EQ(c.kind, app::MenuChoice::Kind::Relaunch);
  EXPECT_EQ(c.car, 2);
  EXPECT_EQ(c.fidelity, 1);
  EXPECT_FALSE(m.isOpen());
  // Without cars to offer, no such items.
  EXPECT_EQ(app::PauseMenu(places).items(), 4);
}

// The drive's picks: the shipped cars with the scenario's own chosen, the
// ladder with auto, the scenario's rung chosen; a scenario whose car is not
// shipped gets it first. Each drive after the first writes outputs of its
// own, never an existing file.
TEST(DrivePicks, OfferTheShippedCarsAndTheLadderWithTheScenariosChosen) {
  const scenario::ScenarioSpec spec = scenario::loadScenarioFile(asset("scenarios/drive_powertrain.toml"));
  const app::DrivePicks p = app::drivePicks(spec);
  ASSERT_EQ(p.carFiles.size(), p.menu.cars.size());
  ASSERT_GE(p.menu.cars.size(), 2u);
  EXPECT_TRUE(std::filesystem::equivalent(p.carFiles[p.menu.car], spec.vehicleFile));
  EXPECT_EQ(p.menu.cars[p.menu.car], "sedan_drive");
  EXPECT_EQ(p.menu.fidelities[p.menu.fidelity], "auto");
  EXPECT_NE(std::find(p.menu.fidelities.begin(), p.menu.fidelities.end(), "linkage"), p.menu.fidelities.end());

  scenario::ScenarioSpec own = spec;
  own.vehicleFile = temp("own_car.toml");
  const app::DrivePicks q = app::drivePicks(own);
  EXPECT_EQ(q.menu.car, 0);
  EXPECT_EQ(q.carFiles[0], own.vehicleFile);
  EXPECT_EQ(q.menu.cars.size(), p.menu.cars.size() + 1);

  const std::string csv = temp("drive.csv"), second = temp("drive-2.csv");
  EXPECT_EQ(app::driveOutput(csv, 1), csv);
  EXPECT_EQ(app::driveOutput("", 2), "");
  std::filesystem::remove(second);
  EXPECT_EQ(app::driveOutput(csv, 2), second);
  std::ofstream(second) << "an earlier drive's rows\n";
  EXPECT_EQ(app::driveOutput(csv, 2), temp("drive-3.csv"));
  std::filesystem::remove(second);
}

// "Drive them here" as the drive command does it: the scenario loaded again
// with the chosen car and rung, the new drive started at the place the last
// one was at.
TEST(DriveSession, AnotherCarOnAnotherRungStartsWhereTheDriveWas) {
  const std::string path = asset("scenarios/drive_powertrain.toml");
  const scenario::ScenarioSpec spec = scenario::loadScenarioFile(path);
  ASSERT_GE(spec.places.size(), 2u);
  app::SessionOptions o;
  o.rewindable = true;
  app::DriveSession first(spec, o);
  ASSERT_TRUE(first.goTo(1)) << first.placeNotice();
  app::ScenarioOverrides pick;
  pick.vehicle = asset("vehicles/paper.toml");
  pick.fidelity = "linkage";
  const scenario::ScenarioSpec again = app::loadScenario(path, pick);
  app::DriveSession second(again, o);
  ASSERT_TRUE(second.goTo(first.place())) << second.placeNotice();
  EXPECT_TRUE(std::filesystem::equivalent(second.spec().vehicleFile, asset("vehicles/paper.toml")));
  EXPECT_EQ(second.simulation().rungCount(), 1);
  EXPECT_FALSE(second.spec().fidelity.automatic);
  const vehicle::VehicleSample& s = second.lastSample();
  EXPECT_NEAR(s.chassisOrigin.x(), spec.places[1].x, 0.1);
  EXPECT_NEAR(s.chassisOrigin.y(), spec.places[1].y, 0.1);
  for (int i = 0; i < 50; ++i) ASSERT_TRUE(second.tick(scenario::DriverInput{0.0, 0.3, 0.0})) << second.failure();
  EXPECT_GT(second.lastSample().speed, 0.1);
}

// Every place of the default drive is a start: the car there at rest on
// its four wheels, at time 0 in a new telemetry segment; restart comes back
// to the place; a place that is not one is refused and the drive goes on as
// it was; a recording goes there on replay.
TEST(DriveSession, GoingToEachPlaceOfTheSceneStartsTheDriveThere) {
  const scenario::ScenarioSpec spec = scenario::loadScenarioFile(asset("scenarios/drive_powertrain.toml"));
  ASSERT_GE(spec.places.size(), 5u);
  const std::string rec = temp("places.rec"), csv = temp("places.csv"), again = temp("places_replayed.csv");
  {
    app::SessionOptions o;
    o.rewindable = true;
    o.recordPath = rec;
    o.telemetryPath = csv;
    app::DriveSession d(spec, o);
    for (int p = 0; p < static_cast<int>(spec.places.size()); ++p) {
      SCOPED_TRACE(spec.places[p].name);
      for (int i = 0; i < 20; ++i) ASSERT_TRUE(d.tick(scenario::DriverInput{0.0, 0.3, 0.0})) << d.failure();
      const int segment = d.segment();
      ASSERT_TRUE(d.goTo(p)) << d.placeNotice();
      EXPECT_EQ(d.segment(), segment + 1);
      EXPECT_NEAR(d.time(), 0.0, 1e-9);
      const vehicle::VehicleSample& s = d.lastSample();
      EXPECT_NEAR(s.chassisOrigin.x(), spec.places[p].x, 0.1);
      EXPECT_NEAR(s.chassisOrigin.y(), spec.places[p].y, 0.1);
      EXPECT_LT(s.speed, 0.05);
      for (int w = 0; w < 4; ++w) EXPECT_TRUE(s.inContact[w]) << w;
    }
    // Restart: back to the last place, not to [start].
    for (int i = 0; i < 50; ++i) ASSERT_TRUE(d.tick(scenario::DriverInput{0.0, 0.5, 0.0})) << d.failure();
    d.restart();
    EXPECT_NEAR(d.lastSample().chassisOrigin.x(), spec.places.back().x, 0.1);
    // Nowhere: refused, the drive where it was.
    EXPECT_FALSE(d.goTo(static_cast<int>(spec.places.size())));
    for (int i = 0; i < 30; ++i) ASSERT_TRUE(d.tick(scenario::DriverInput{0.0, 0.5, 0.0})) << d.failure();
    d.closeOutputs();
  }
  // The recording goes to the places as the drive did: the same telemetry.
  const app::Recording r = app::readRecording(rec);
  EXPECT_EQ(std::count_if(r.entries.begin(), r.entries.end(),
                          [](const app::RecordedTick& e) { return e.kind == app::RecordedTick::Kind::Place; }),
            static_cast<long>(spec.places.size()));
  EXPECT_EQ(replayedTelemetry(spec, r, again), readFile(csv));
}

TEST(DriveSession, APlaceOffTheTerrainIsRefusedAndTheDriveGoesOn) {
  scenario::ScenarioSpec spec = scenario::loadScenarioFile(asset("scenarios/drive.toml"));
  spec.terrainFile = asset("terrain/curb.toml");  // a road that ends: x -50 .. 300, y -10 .. 10
  spec.places.push_back({"the far side of the moon", 5000, 5000, 0});
  app::DriveSession d(spec, {});
  for (int i = 0; i < 30; ++i) ASSERT_TRUE(d.tick(personAt(i)));
  const double t = d.time(), x = d.lastSample().com.x();
  EXPECT_FALSE(d.goTo(0));
  EXPECT_NE(d.placeNotice().find("cannot go to the far side of the moon: "), std::string::npos) << d.placeNotice();
  EXPECT_NE(d.placeNotice().find("no ground under wheel"), std::string::npos) << d.placeNotice();
  EXPECT_EQ(d.time(), t);
  EXPECT_EQ(d.lastSample().com.x(), x);
  ASSERT_TRUE(d.tick(personAt(30)));
}
