// A value handed from one thread to another without either ever waiting:
// a triple buffer. The writer (the physics tick) publishes its newest value;
// the reader (the sound card's callback) takes the newest published one, or
// keeps what it had when nothing new came. Neither side locks, allocates or
// blocks, so the tick cannot be held up by the audio thread or the reverse.
#pragma once

#include <atomic>

namespace bdfcar::audio {

template <class T>
class LatestValue {
 public:
  // Writer side.
  void publish(const T& v) {
    slots_[back_] = v;
    const unsigned old = middle_.exchange(back_ | kFresh, std::memory_order_acq_rel);
    back_ = old & kIndex;
  }
  // Reader side: true (and v set) when a value newer than the last taken was published.
  bool take(T& v) {
    if (!(middle_.load(std::memory_order_acquire) & kFresh)) return false;
    const unsigned old = middle_.exchange(front_, std::memory_order_acq_rel);
    front_ = old & kIndex;
    v = slots_[front_];
    return true;
  }

 private:
  static constexpr unsigned kIndex = 3, kFresh = 4;
  T slots_[3]{};
  std::atomic<unsigned> middle_{1};
  unsigned back_ = 0, front_ = 2;  // each side's own slot
};

}  // namespace bdfcar::audio
