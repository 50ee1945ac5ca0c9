#include "render/png_queue.h"

#include <chrono>

#include "render/thread_priority.h"
#include "render/png_writer.h"

namespace bdfcar::render {

PngQueue::PngQueue(int compressionLevel, int maxPending)
    : level_(compressionLevel), maxPending_(maxPending < 1 ? 1 : maxPending), worker_([this] { run(); }) {}

PngQueue::~PngQueue() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  worker_.join();
}

// Queues one frame; blocks while the queue is full.
void PngQueue::push(std::string path, Frame frame) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return static_cast<int>(jobs_.size()) < maxPending_; });
  jobs_.push_back({std::move(path), std::move(frame)});
  changed_.notify_all();
}

// Waits for an empty queue and an idle worker; rethrows the first error.
void PngQueue::flush() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return jobs_.empty() && !busy_; });
  if (!error_.empty()) {
    std::string e = std::move(error_);
    error_.clear();
    throw RenderError(e);
  }
}

int PngQueue::written() const {
  std::lock_guard lock(mutex_);
  return written_;
}

std::vector<double> PngQueue::encodeSeconds() const {
  std::lock_guard lock(mutex_);
  return encodeSeconds_;
}

// Worker loop: encode outside the lock so push() never waits for zlib.
void PngQueue::run() {
  lowerThisThreadsPriority();  // the renderer first (render/thread_priority.h)
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return !jobs_.empty() || stopping_; });
    if (jobs_.empty()) return;  // stopping and drained
    Job job = std::move(jobs_.front());
    jobs_.pop_front();
    busy_ = true;
    changed_.notify_all();
    lock.unlock();
    std::string failure;
    const auto t0 = std::chrono::steady_clock::now();
    try {
      writePng(job.path, job.frame, level_);
    } catch (const std::exception& e) {
      failure = e.what();
    }
    const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    lock.lock();
    busy_ = false;
    if (failure.empty()) {
      ++written_;
      encodeSeconds_.push_back(took);
    }
    else if (error_.empty()) error_ = failure;
    changed_.notify_all();
  }
}

}  // namespace bdfcar::render
