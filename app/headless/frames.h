// Headless rendering of a drive (OSMesa, no display server): steps the
// drive and renders a frame every 1/fps seconds of simulated time, written
// as PNG (on a worker thread) and/or into a video through ffmpeg.
#pragma once

#include <string>

#include "render/frame.h"
#include "session/drive_session.h"
#include "session/loop_stats.h"

namespace bdfcar::app {

struct FramesOptions {
  std::string outDir;        // frames go to outDir/frame_00000.png, ...; empty: no PNG
  std::string video;         // .mp4 through ffmpeg; empty: none
  double fps = 30;
  int width = 1280, height = 720;
  std::string camera = "chase";  // chase, hood, orbit, top-down
  std::string body = "solid";    // solid, translucent, hidden (the suspension view: the model's members)
  std::string wav;           // the soundtrack (audio/car_synth.h) as a WAV file; empty: none
};

struct FramesResult {
  int frames = 0;
  int width = 0, height = 0;
  LoopStats stats;           // render time per frame (frame()), physics per tick (tick())
  double encodeSeconds = 0;  // the render loop waiting for PNG / video output
  double wallSeconds = 0;    // the whole run, first frame to the last file closed
  Percentiles pngEncode;     // encoding + writing one PNG (worker thread, overlaps rendering)
  std::string renderer;      // GL_RENDERER
  render::DrawLoad drawnP50;  // per frame, the medians of drawables and triangles drawn
  long soundFrames = 0;      // samples written to the WAV
};

// Renders the whole scenario (until its duration or a failure).
FramesResult renderFrames(DriveSession& session, const FramesOptions& options);

}  // namespace bdfcar::app
