#include "config/line_reader.h"

#include <filesystem>
#include <stdexcept>

namespace bdfcar::config {

namespace {

std::string sizeText(std::uint64_t bytes) {
  if (bytes >= (1u << 20) && bytes % (1u << 20) == 0) return std::to_string(bytes >> 20) + " MiB";
  if (bytes >= 1024 && bytes % 1024 == 0) return std::to_string(bytes >> 10) + " KiB";
  return std::to_string(bytes) + " bytes";
}

}  // namespace

LineReader::LineReader(const std::string& path, const std::string& what, const LineLimits& limits)
    : path_(path), what_(what), limits_(limits), buffer_(limits.maxLineBytes + 1) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status s = fs::status(path, ec);
  if (const auto why = notARegularFile(path); why && s.type() != fs::file_type::fifo)
    throw std::runtime_error(path + ":0: the " + what + " " + *why);
  if (s.type() == fs::file_type::fifo) {
    piped_.str(readDataFile(path, what));  // its writer's text, under the data-file cap
    in_ = &piped_;
  } else {
    const std::uintmax_t size = fs::file_size(path, ec);
    if (!ec && size > limits_.maxBytes)
      throw std::runtime_error(path + ":0: the " + what + " is " + std::to_string(size) + " bytes, over its limit of " +
                               sizeText(limits_.maxBytes));
    file_.open(path, std::ios::binary);
    if (!file_) throw std::runtime_error(path + ":0: cannot open the " + what);
    in_ = &file_;
  }
}

void LineReader::fail(const std::string& message) const {
  throw std::runtime_error(path_ + ":" + std::to_string(line_) + ": " + message);
}

bool LineReader::next(std::string& line) {
  if (!in_->good()) return false;
  in_->getline(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  const std::streamsize n = in_->gcount();
  if (n == 0 && in_->eof()) return false;  // nothing after the last newline
  ++line_;
  // getline stores at most maxLineBytes characters; failbit without eof:
  // it stopped there with no newline in sight.
  if (in_->fail() && !in_->eof())
    fail("this line of the " + what_ + " is longer than " + sizeText(limits_.maxLineBytes) + ", its limit for one line");
  if (in_->bad()) fail("cannot read the " + what_);
  ended_ = !in_->eof();
  bytes_ += static_cast<std::uint64_t>(n);
  if (bytes_ > limits_.maxBytes)  // a file that grew while read
    fail("the " + what_ + " is larger than its limit of " + sizeText(limits_.maxBytes));
  if (static_cast<std::uint64_t>(line_) > limits_.maxLines)
    fail("the " + what_ + " has more than " + std::to_string(limits_.maxLines) + " lines, its limit");
  line.assign(buffer_.data(), static_cast<std::size_t>(ended_ ? n - 1 : n));
  return true;
}

}  // namespace bdfcar::config
