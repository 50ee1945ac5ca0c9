#include "car_pool.h"

#include <utility>

namespace bdfcar::python {

CarPool::CarPool(int threads) {
  if (threads < 0) threads = std::max(0, static_cast<int>(std::thread::hardware_concurrency()) - 1);
  for (int i = 0; i < threads; ++i) workers_.emplace_back([this] { work(); });
}

CarPool::~CarPool() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : workers_) t.join();
}

void CarPool::drain() {
  for (int i = next_.fetch_add(1); i < n_; i = next_.fetch_add(1)) {
    try {
      (*job_)(i);
    } catch (...) {
      std::lock_guard lock(mutex_);
      if (!error_) error_ = std::current_exception();
    }
  }
}

void CarPool::work() {
  long seen = 0;
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
    if (stop_) return;
    seen = generation_;
    lock.unlock();
    drain();
    lock.lock();
    if (--busy_ == 0) done_.notify_all();
  }
}

void CarPool::run(int n, const std::function<void(int)>& job) {
  if (n <= 0) return;
  {
    std::lock_guard lock(mutex_);
    job_ = &job;
    n_ = n;
    next_ = 0;
    busy_ = static_cast<int>(workers_.size());
    ++generation_;
  }
  wake_.notify_all();
  drain();
  // Every worker takes part in every batch (one with nothing left to take
  // leaves at once), so none can wake into the next batch's counter late.
  std::unique_lock lock(mutex_);
  done_.wait(lock, [&] { return busy_ == 0; });
  job_ = nullptr;
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
}

}  // namespace bdfcar::python
