#include "scenario/parallel_runs.h"

#include <algorithm>
#include <exception>
#include <thread>
#include <vector>

namespace bdfcar::scenario {

void runInParallel(int n, int jobs, const std::function<void(int)>& f) {
  jobs = std::max(1, jobs);
  std::vector<std::exception_ptr> errors(static_cast<size_t>(std::max(0, n)));
  for (int begin = 0; begin < n; begin += jobs) {
    std::vector<std::thread> threads;
    for (int i = begin; i < std::min(n, begin + jobs); ++i)
      threads.emplace_back([&, i] {
        try {
          f(i);
        } catch (...) {
          errors[static_cast<size_t>(i)] = std::current_exception();
        }
      });
    for (std::thread& t : threads) t.join();
  }
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace bdfcar::scenario
