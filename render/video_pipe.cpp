#include "render/video_pipe.h"

#include <sys/wait.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "render/thread_priority.h"
#include "scenario/row_file.h"

namespace bdfcar::render {
namespace {

// Wraps an argument in single quotes for /bin/sh.
std::string shellQuote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace

std::string VideoPipe::partialPath(const std::string& path) {
  const std::filesystem::path p(path);
  return (p.parent_path() / (p.stem().string() + ".partial" + p.extension().string())).string();
}

VideoPipe::VideoPipe(const std::string& path, int width, int height, const VideoOptions& options)
    : path_(path), partial_(partialPath(path)), width_(width), height_(height) {
  if (width <= 0 || height <= 0) throw RenderError("VideoPipe: bad frame size");
  const std::string probe = "command -v " + shellQuote(options.ffmpeg) + " >/dev/null 2>&1";
  if (std::system(probe.c_str()) != 0)
    throw RenderError("VideoPipe: '" + options.ffmpeg + "' not found on PATH (install ffmpeg to write " + path + ")");
  // yuv420p needs even sizes: pad odd ones by a pixel rather than fail.
  // Under nice: the renderer first (render/thread_priority.h).
  const std::string cmd = "nice -n " + std::to_string(kBackgroundNiceness) + " " + shellQuote(options.ffmpeg) +
                          " -y -loglevel error -f rawvideo -pix_fmt rgba -s " + std::to_string(width) + "x" +
                          std::to_string(height) + " -r " + std::to_string(options.fps) +
                          " -i - -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' -c:v libx264 -preset " +
                          shellQuote(options.preset) + " -crf " + std::to_string(options.crf) + " -pix_fmt yuv420p " +
                          shellQuote(partial_);
  // A dead ffmpeg must surface as a write error, not kill us with SIGPIPE.
  std::signal(SIGPIPE, SIG_IGN);
  pipe_ = popen(cmd.c_str(), "w");
  if (!pipe_) throw RenderError("VideoPipe: cannot start ffmpeg for " + path);
}

VideoPipe::~VideoPipe() {
  if (pipe_) pclose(pipe_);
}

// Writes one raw RGBA frame to ffmpeg's stdin.
void VideoPipe::write(const Frame& frame) {
  if (!pipe_) throw RenderError("VideoPipe: write after close (" + path_ + ")");
  if (frame.width != width_ || frame.height != height_)
    throw RenderError("VideoPipe: frame size " + std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                      " differs from the video's " + std::to_string(width_) + "x" + std::to_string(height_));
  if (std::fwrite(frame.rgba.data(), 1, frame.rgba.size(), pipe_) != frame.rgba.size())
    throw scenario::OutputError(path_ + ": cannot write the video: ffmpeg stopped taking frames (a full disk?); " +
                                "what it wrote is in " + partial_ + ", an earlier " + path_ + " is kept");
  ++frames_;
}

// Closes stdin and checks ffmpeg's exit status.
void VideoPipe::close() {
  if (!pipe_) return;
  const int status = pclose(pipe_);
  pipe_ = nullptr;
  if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw scenario::OutputError(path_ + ": cannot write the video: ffmpeg failed (exit status " +
                                std::to_string(status) + "); what it wrote is in " + partial_ + ", an earlier " +
                                path_ + " is kept");
  if (std::rename(partial_.c_str(), path_.c_str()) != 0)
    throw scenario::OutputError(path_ + ": cannot rename " + partial_ + " into place");
}

}  // namespace bdfcar::render
