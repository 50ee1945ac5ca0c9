// A fixed set of worker threads for stepping many cars at once (the vector
// environment): run(n, job) calls job(0..n-1) spread over the workers and
// the calling thread, and returns when every call has returned. Which thread
// runs which car does not matter: each car's simulation is its own (the
// world they share is read-only), so the results are those of N separate
// runs, whatever the thread count.
#pragma once

#include <atomic>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace bdfcar::python {

class CarPool {
 public:
  // threads: the workers besides the caller (0: none; negative: one per
  // core, less the caller's).
  explicit CarPool(int threads = -1);
  ~CarPool();
  CarPool(const CarPool&) = delete;
  CarPool& operator=(const CarPool&) = delete;

  // An exception a job throws (on any thread) is rethrown here once every
  // job has returned (the first one; the others are dropped): a worker
  // thread never ends the process.
  void run(int n, const std::function<void(int)>& job);
  int threads() const { return static_cast<int>(workers_.size()) + 1; }

 private:
  void work();        // the workers' loop
  void drain();       // takes indices until none is left

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(int)>* job_ = nullptr;
  int n_ = 0;
  std::atomic<int> next_{0};
  int busy_ = 0;          // workers not yet done with the current batch
  long generation_ = 0;   // batches started
  bool stop_ = false;
  std::exception_ptr error_;  // the batch's first failure
};

}  // namespace bdfcar::python
