// Background priorities (render/thread_priority): the calling thread's nice
// value rises by kBackgroundNiceness and no other thread's does; threads named
// as llvmpipe's rasterisers are found by name and lowered, others are not.
#include <gtest/gtest.h>

#include <pthread.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "render/thread_priority.h"

using namespace bdfcar::render;

namespace {

int niceOf(long tid) { return getpriority(PRIO_PROCESS, static_cast<id_t>(tid)); }
long thisTid() { return syscall(SYS_gettid); }

// A thread with a name that waits until released; reports its id.
class NamedThread {
 public:
  explicit NamedThread(const char* name) {
    thread_ = std::thread([this, name] {
      pthread_setname_np(pthread_self(), name);
      std::unique_lock lock(mutex_);
      tid_ = thisTid();
      changed_.notify_all();
      changed_.wait(lock, [&] { return release_; });
    });
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return tid_ != 0; });
  }
  ~NamedThread() {
    {
      std::lock_guard lock(mutex_);
      release_ = true;
    }
    changed_.notify_all();
    thread_.join();
  }
  long tid() const { return tid_; }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  long tid_ = 0;
  bool release_ = false;
  std::thread thread_;
};

}  // namespace

TEST(ThreadPriority, RaisesTheCallingThreadsNiceValueOnly) {
  const int mainBefore = niceOf(thisTid());
  int before = 0, after = 0;
  std::thread([&] {
    before = niceOf(thisTid());
    lowerThisThreadsPriority();
    after = niceOf(thisTid());
  }).join();
  EXPECT_EQ(after, std::min(before + kBackgroundNiceness, 19));
  EXPECT_EQ(niceOf(thisTid()), mainBefore) << "the calling thread alone";
}

TEST(ThreadPriority, FindsTheRasteriserThreadsByName) {
  NamedThread rasteriser("llvmpipe-7"), other("worker-1");
  const int rasteriserBefore = niceOf(rasteriser.tid()), otherBefore = niceOf(other.tid());
  EXPECT_EQ(lowerSoftwareRasteriserPriority(), 1);
  EXPECT_EQ(niceOf(rasteriser.tid()), std::min(rasteriserBefore + kBackgroundNiceness, 19));
  EXPECT_EQ(niceOf(other.tid()), otherBefore);
}
