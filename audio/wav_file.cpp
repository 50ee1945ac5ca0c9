#include "audio/wav_file.h"

#include <sndfile.h>

#include <cstdio>
#include <filesystem>

namespace bdfcar::audio {

WavFile::WavFile(const std::string& path, int sampleRate) : path_(path), partial_(path + ".partial") {
  std::error_code ec;
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent, ec);
  if (ec) throw WavError(path + ": cannot make the folder " + parent.string() + ": " + ec.message());
  SF_INFO info{};
  info.samplerate = sampleRate;
  info.channels = 1;
  info.format = SF_FORMAT_WAV | SF_FORMAT_FLOAT;
  file_ = sf_open(partial_.c_str(), SFM_WRITE, &info);
  if (!file_) throw WavError(path + ": cannot open " + partial_ + " for writing: " + sf_strerror(nullptr));
}

WavFile::~WavFile() {
  if (file_) sf_close(static_cast<SNDFILE*>(file_));
}

void WavFile::write(const float* samples, long count) {
  if (!file_) throw WavError(path_ + ": written after it was closed");
  const sf_count_t n = sf_write_float(static_cast<SNDFILE*>(file_), samples, count);
  if (n != count)
    throw WavError(path_ + ": cannot write " + partial_ + ": " + sf_strerror(static_cast<SNDFILE*>(file_)));
  frames_ += count;
}

void WavFile::close() {
  if (!file_) return;
  SNDFILE* f = static_cast<SNDFILE*>(file_);
  file_ = nullptr;
  sf_write_sync(f);
  if (sf_close(f) != 0) throw WavError(path_ + ": cannot finish " + partial_);
  if (std::rename(partial_.c_str(), path_.c_str()) != 0)
    throw WavError(path_ + ": cannot rename " + partial_ + " into place");
}

}  // namespace bdfcar::audio
