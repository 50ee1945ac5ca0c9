// Writes PNG files on a worker thread so that encoding overlaps rendering.
#pragma once

#include <condition_variable>
#include <deque>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "render/frame.h"

namespace bdfcar::render {

class PngQueue {
 public:
  // maxPending: frames waiting before push() blocks (bounds memory: 3.7 MB per 1280x720 frame).
  explicit PngQueue(int compressionLevel = 1, int maxPending = 4);
  ~PngQueue();  // writes what is queued, then stops (errors are dropped: call flush() to see them)
  PngQueue(const PngQueue&) = delete;
  PngQueue& operator=(const PngQueue&) = delete;

  // Queues a frame for writing to path; blocks while maxPending frames are waiting.
  void push(std::string path, Frame frame);
  // Waits until every queued frame is written; throws the first write error, if any.
  void flush();
  int written() const;
  // Seconds each written frame took to encode and write (on the worker thread).
  std::vector<double> encodeSeconds() const;

 private:
  void run();

  struct Job {
    std::string path;
    Frame frame;
  };
  int level_, maxPending_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Job> jobs_;
  bool busy_ = false, stopping_ = false;
  int written_ = 0;
  std::vector<double> encodeSeconds_;
  std::string error_;
  std::thread worker_;
};

}  // namespace bdfcar::render
