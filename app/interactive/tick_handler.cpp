#include "interactive/tick_handler.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "interactive/drive_loop.h"

namespace bdfcar::app {

namespace {

// recording-1.txt, recording-2.txt, ... in the working folder, the first free name.
std::string nextRecordingName() {
  for (int i = 1;; ++i) {
    const std::string name = "recording-" + std::to_string(i) + ".txt";
    if (!std::filesystem::exists(name)) return name;
  }
}

constexpr double kMessageSeconds = 4.0;

}  // namespace

TickHandler::TickHandler(DriveSession& session, const InteractiveOptions& options)
    : session_(session), options_(options) {
  if (options_.driver == DriverSource::Person) {
    input::InputOptions io;
    if (!options_.mappingDir.empty()) io.mappingDir = options_.mappingDir;
    io.onMessage = [](const std::string& m) { std::fprintf(stderr, "input: %s\n", m.c_str()); };
    devices_ = std::make_unique<input::InputSystem>(io);
  }
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
    if (c.pause) paused_ = !paused_;
    step = c.singleStep;
    out.view.cameraSwitches = c.camera ? 1 : 0;
    out.view.bodySwitches = c.view ? 1 : 0;
    if (c.record) {
      // A recording replays only from the scenario's start: restart into a new file.
      session_.startRecording(nextRecordingName());
      say("recording to " + session_.recordingPath());
    } else if (c.reset) {
      session_.restart();
      say("back to the start");
    } else if (c.rewind) {
      if (session_.rewind()) {
        char text[64];
        std::snprintf(text, sizeof text, "rewound to t = %.1f s", session_.time());
        say(text);
      } else {
        say("nothing to rewind");
      }
    }
    if (out.quit) return out;
    if ((!paused_ || step) && !session_.failed() && !session_.finished())
      session_.tick(scenario::DriverInput{c.steering, c.throttle, c.brake});
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

void TickHandler::setSteeringFeel() {
  if (devices_) devices_->setSteeringTorque(session_.steeringFeel());
}

}  // namespace bdfcar::app
