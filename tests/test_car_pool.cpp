// The worker pool that steps many cars for Python (python/car_pool.h): every
// job runs once whatever the thread count, and a job that throws has its
// exception rethrown to the caller after the batch (never std::terminate on
// a worker, which would end the Python interpreter); the pool works on.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

#include "car_pool.h"

namespace bdfcar {
namespace {

TEST(CarPool, EveryJobOnceAndAThrowReachesTheCaller) {
  for (int workers : {0, 1, 3}) {
    python::CarPool pool(workers);
    std::vector<std::atomic<int>> runs(100);
    pool.run(100, [&](int i) { ++runs[i]; });
    for (auto& r : runs) EXPECT_EQ(r.load(), 1);
    EXPECT_THROW(pool.run(100,
                          [&](int i) {
                            ++runs[i];
                            if (i == 37) throw std::runtime_error("job 37");
                          }),
                 std::runtime_error);
    for (auto& r : runs) EXPECT_EQ(r.load(), 2);  // the others still ran
    pool.run(100, [&](int i) { ++runs[i]; });     // and the pool works on
    for (auto& r : runs) EXPECT_EQ(r.load(), 3);
  }
}

}  // namespace
}  // namespace bdfcar
