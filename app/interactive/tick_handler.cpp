#include "interactive/tick_handler.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "input/driver_controls.h"
#include "interactive/drive_loop.h"

namespace bdfcar::app {

namespace {

// recording-1.txt, recording-2.txt, ... in the recordings folder, the first free name.
std::string nextRecordingName(const std::string& dir) {
  std::filesystem::create_directories(dir);
  for (int i = 1;; ++i) {
    const std::filesystem::path name = std::filesystem::path(dir) / ("recording-" + std::to_string(i) + ".txt");
    if (!std::filesystem::exists(name)) return name.string();
  }
}

constexpr double kMessageSeconds = 4.0;

}  // namespace

TickHandler::TickHandler(DriveSession& session, const InteractiveOptions& options)
    : session_(session), options_(options), carSteering_(session.simulation().carSteering()),
      menu_(session.spec().places, options.picks) {
  if (options_.driver == DriverSource::Person) {
    input::InputOptions io;
    if (!options_.mappingDir.empty()) io.mappingDir = options_.mappingDir;
    io.onMessage = [](const std::string& m) { std::fprintf(stderr, "input: %s\n", m.c_str()); };
    devices_ = std::make_unique<input::InputSystem>(io);
  }
  if (!options_.startMessage.empty()) say(options_.startMessage);
}

void TickHandler::say(const std::string& text) {
  message_ = text;
  messageTicks_ = std::lround(kMessageSeconds / session_.spec().tick);
}

std::string TickHandler::message() const {
  if (session_.failed()) return session_.failure();
  if (paused_) return "paused";
  if (messageTicks_ > 0) return message_;
  if (session_.finished()) return "scenario finished";
  return "";
}

TickOutcome TickHandler::handle(const render::WindowEvents& we) {
  TickOutcome out;
  out.quit = we.quit;
  out.view.orbitYaw = -0.005 * we.dragX;
  out.view.orbitPitch = 0.005 * we.dragY;
  out.view.zoom = std::pow(0.9, we.wheel);
  if (messageTicks_ > 0) --messageTicks_;
  bool step = false;
  if (devices_) {
    const input::Controls c = devices_->poll(session_.spec().tick);
    out.quit |= c.quit;
    if (c.menu && !menu_.isOpen()) {
      menu_.open();
    } else if (c.menu) {
      menu_.close();
    } else if (menu_.isOpen()) {
      // The menu holds the drive; its keys may steer and pedal otherwise.
      if (c.menuUp) menu_.up();
      if (c.menuDown) menu_.down();
      if (c.menuSelect) out.quit |= choose(menu_.select());
      return out;
    }
    if (menu_.isOpen()) return out;
    if (c.pause) paused_ = !paused_;
    step = c.singleStep;
    out.view.cameraSwitches = c.camera ? 1 : 0;
    out.view.bodySwitches = c.view ? 1 : 0;
    if (c.record) {
      toggleRecording();
    } else if (c.reset) {
      session_.restart();
      say("back to the start (telemetry segment " + std::to_string(session_.segment()) + ")");
    } else if (c.rewind) {
      if (session_.rewind()) {
        char text[96];
        std::snprintf(text, sizeof text, "rewound to t = %.1f s (telemetry segment %d)", session_.time(),
                      session_.segment());
        say(text);
      } else {
        say("nothing to rewind");
      }
    }
    if (out.quit) return out;
    if ((!paused_ || step) && !session_.failed() && !session_.finished())
      // The speed the HUD shows (the last sample's) for speed-sensitive steering.
      session_.tick(input::toDriverInput(c, carSteering_, session_.lastSample().speed));
  } else if ((!paused_ || step) && !session_.failed() && !session_.finished()) {
    advance();
  }
  if (session_.resets() != resetsSeen_) {
    resetsSeen_ = session_.resets();
    say(session_.notice());
    std::fprintf(stderr, "%s: %s\n", session_.notice().c_str(), session_.lastDivergence().c_str());
  }
  return out;
}

// What a menu choice does; true to quit.
bool TickHandler::choose(const MenuChoice& choice) {
  switch (choice.kind) {
    case MenuChoice::Kind::Resume: break;
    case MenuChoice::Kind::Restart:
      session_.restart();
      say("back to the start (telemetry segment " + std::to_string(session_.segment()) + ")");
      break;
    case MenuChoice::Kind::GoTo:
      if (session_.goTo(choice.place))
        say("at " + session_.spec().places[choice.place].name + " (telemetry segment " +
            std::to_string(session_.segment()) + ")");
      else
        say(session_.placeNotice());
      break;
    case MenuChoice::Kind::Cycled: break;  // the menu shows the next value
    case MenuChoice::Kind::Relaunch:
      relaunch_ = choice;
      return true;
    case MenuChoice::Kind::Quit: return true;
  }
  return false;
}

std::string TickHandler::menuText() const { return menu_.isOpen() ? menu_.text() : ""; }

// The scripted driver, or the next line of the replay (its events first).
void TickHandler::advance() {
  if (options_.driver == DriverSource::Scripted || !options_.replay) {
    session_.tick(std::nullopt);
    return;
  }
  const auto& entries = options_.replay->entries;
  while (replayCursor_ < entries.size()) {
    const RecordedTick& e = entries[replayCursor_++];
    session_.replay(e);
    if (e.kind == RecordedTick::Kind::Input) return;
  }
  if (message_ != "replay finished") say("replay finished");
}

// F9: start recording (the scenario restarts: a recording replays from the
// start) into a new numbered file, or stop and keep it.
void TickHandler::toggleRecording() {
  try {
    if (session_.recording()) {
      const std::string path = session_.recordingPath();
      const long ticks = session_.stopRecording();
      say("recording saved: " + path + " (" + std::to_string(ticks) + " ticks)");
      std::printf("recording saved: %s (%ld ticks)\n", path.c_str(), ticks);
    } else {
      session_.startRecording(nextRecordingName(options_.recordDir));
      say("recording to " + session_.recordingPath() + " from the start; F9 stops");
      std::printf("recording to %s\n", session_.recordingPath().c_str());
    }
  } catch (const std::exception& e) {
    say(e.what());
    std::fprintf(stderr, "error: %s\n", e.what());
  }
}

void TickHandler::setSteeringFeel() {
  if (devices_) devices_->setSteeringTorque(session_.steeringFeel());
}

}  // namespace bdfcar::app
