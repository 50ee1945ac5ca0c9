#include "interactive/drive_loop.h"

#include <cstdio>
#include <memory>
#include <mutex>

#include "audio/audio_output.h"

#include "demo_common.h"
#include "interactive/draw_thread.h"
#include "interactive/tick_clock.h"
#include "interactive/tick_handler.h"
#include "interrupt.h"
#include "render/window.h"
#include "session/car_sound.h"
#include "view/scene_setup.h"

namespace bdfcar::app {

LoopStats runInteractive(DriveSession& session, const InteractiveOptions& opt, std::optional<MenuChoice>* relaunch) {
  // With software GL (Mesa llvmpipe, no GPU) the rasteriser's threads, one a
  // core, share the cores with the tick at a lower priority (draw_thread.cpp):
  // on two cores the proving ground drew at 44 fps against 30 with one thread
  // (three runs each, alternated), the tick's period p99 12.4 ms against 11.8,
  // no overruns either way (docs/RESULTS.md 8).
  // LP_NUM_THREADS, when set, still decides.
  LoopStats stats;
  std::mutex statsMutex;
  render::Scene scene(sceneConfigFor(session));
  for (const std::string& w : scene.warnings()) std::fprintf(stderr, "warning: %s\n", w.c_str());
  render::WindowOptions wo;
  wo.width = opt.width;
  wo.height = opt.height;
  wo.vsync = opt.vsync;
  wo.multisample = opt.multisample;
  wo.renderScale = opt.renderScale;
  wo.title = "bdfcar - " + session.spec().name;
  render::Window window(scene, wo);
  TickHandler handler(session, opt);
  // The sound on its own thread, fed each tick (never waited for).
  std::unique_ptr<audio::AudioOutput> sound;
  if (opt.sound) {
    try {
      sound = std::make_unique<audio::AudioOutput>();
    } catch (const audio::AudioError& e) {
      std::fprintf(stderr, "note: %s: driving without sound\n", e.what());
    }
  }
  CarSound carSound;
  bool soundPaused = false;
  DrawThread drawing(scene, window, stats, statsMutex, session.view(), session.hud(0, 0, ""), opt.screenshot);

  TickClock clock(session.spec().tick);
  RealTimeMeter realTime;
  double closingSince = -1;  // s since the start when the scenario ended (quitAtEnd)
  while (true) {
    const double period = clock.waitForTick();
    const double sim0 = session.time();
    const TickOutcome out = handler.handle(window.takeEvents());
    drawing.command(out.view);
    if (sound) {
      sound->publish(carSound.update(session));
      if (handler.paused() != soundPaused) sound->pause(soundPaused = handler.paused());
    }
    if (out.quit || interruptRequested()) break;
    if (opt.seconds > 0 && clock.sinceStart() >= opt.seconds) break;
    const double physics = std::chrono::duration<double>(TickClock::Clock::now() - clock.tickStart()).count();
    // At the end, the verdict's card stays up a moment before the window closes.
    if (opt.quitAtEnd && session.finished()) {
      if (closingSince < 0) closingSince = clock.sinceStart();
      if (clock.sinceStart() - closingSince >= opt.closingCardSeconds) break;
    }
    handler.setSteeringFeel();
    // Time advanced by a rewind or reset is not real-time progress.
    const double advanced = session.time() - sim0;
    realTime.add(period, advanced > 0 ? advanced : 0.0);
    const std::string card = opt.quitAtEnd && session.finished() ? courseVerdictLine(session) : "";
    vehicle::HudInfo hud = session.hud(realTime.factor(), physics, card.empty() ? handler.message() : card);
    hud.menu = handler.menuText();
    drawing.publish(session.view(), hud);
    const bool overrun = clock.endTick();
    std::lock_guard<std::mutex> lock(statsMutex);
    stats.tick(period, physics, overrun);
  }
  drawing.stop();
  if (relaunch) *relaunch = handler.relaunch();
  return stats;
}

}  // namespace bdfcar::app
