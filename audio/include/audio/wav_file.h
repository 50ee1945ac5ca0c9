// The soundtrack of a headless render as a WAV file (libsndfile, 32-bit
// float, mono), written as every output is: into FILE.partial, renamed into
// place when closed whole (an earlier file of the name stays until then);
// missing folders are made. Errors throw WavError naming the file.
#pragma once

#include <stdexcept>
#include <string>

namespace bdfcar::audio {

struct WavError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class WavFile {
 public:
  WavFile(const std::string& path, int sampleRate);
  ~WavFile();  // an unclosed file is left as FILE.partial
  WavFile(const WavFile&) = delete;
  WavFile& operator=(const WavFile&) = delete;
  void write(const float* samples, long count);
  void close();
  long frames() const { return frames_; }

 private:
  std::string path_, partial_;
  void* file_ = nullptr;  // SNDFILE*
  long frames_ = 0;
};

}  // namespace bdfcar::audio
