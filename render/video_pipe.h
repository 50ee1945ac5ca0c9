// A video file from frames: raw RGBA frames piped into an ffmpeg process.
// Written as NAME.partial.EXT beside the file and renamed onto it when
// ffmpeg has finished, so an earlier video of that name is kept until the
// new one is whole; a failure to write it (ffmpeg stopped, a full disk) is
// scenario::OutputError (exit 5), the partial file left.
#pragma once

#include <cstdio>
#include <string>

#include "render/frame.h"

namespace bdfcar::render {

struct VideoOptions {
  double fps = 50.0;
  int crf = 20;                       // x264 quality (lower = better, larger)
  // x264's fastest preset: on a 2-core machine "veryfast" took a core from
  // the software rasteriser (12 s against 8.6 s for the 361-frame lane change
  // at 1280x720) for files half the size at the same crf.
  std::string preset = "ultrafast";
  std::string ffmpeg = "ffmpeg";      // executable, looked up on PATH
};

class VideoPipe {
 public:
  // Starts ffmpeg writing `path` (container from the extension, e.g. .mp4);
  // throws RenderError if ffmpeg cannot be found or started.
  VideoPipe(const std::string& path, int width, int height, const VideoOptions& options = {});
  ~VideoPipe();  // closes the pipe (errors are dropped: call close() to see them)
  VideoPipe(const VideoPipe&) = delete;
  VideoPipe& operator=(const VideoPipe&) = delete;

  // Sends one frame (must have the size given at construction); throws
  // scenario::OutputError when ffmpeg no longer takes them.
  void write(const Frame& frame);
  // Ends the stream, waits for ffmpeg and renames the video into place;
  // throws scenario::OutputError if ffmpeg failed.
  void close();
  // NAME.partial.EXT for NAME.EXT: where the video is until close().
  static std::string partialPath(const std::string& path);
  int frames() const { return frames_; }

 private:
  std::string path_, partial_;
  int width_, height_;
  int frames_ = 0;
  FILE* pipe_ = nullptr;
};

}  // namespace bdfcar::render
