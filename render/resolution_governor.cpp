#include "render/resolution_governor.h"

#include <algorithm>

namespace bdfcar::render {

ResolutionGovernor::ResolutionGovernor(double budget, int window) : budget_(budget), window_(std::max(1, window)) {
  recent_.reserve(window_);
}

double ResolutionGovernor::frame(double seconds) {
  recent_.push_back(seconds);
  if (static_cast<int>(recent_.size()) < window_) return scale();
  std::nth_element(recent_.begin(), recent_.begin() + recent_.size() / 2, recent_.end());
  const double median = recent_[recent_.size() / 2];
  recent_.clear();  // the next decision sees only frames drawn at the scale it judges
  const double limit = kDownAt * budget_;
  if (median > limit && step_ + 1 < kResolutionSteps.size()) {
    ++step_;
  } else if (step_ > 0) {
    const double up = kResolutionSteps[step_ - 1] / kResolutionSteps[step_];
    if (median * up * up < kUpMargin * limit) --step_;
  }
  return scale();
}

}  // namespace bdfcar::render
