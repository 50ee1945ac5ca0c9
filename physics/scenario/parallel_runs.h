// Independent runs on threads: f(0) ... f(n - 1), `jobs` at a time, each on
// a thread of its own (runs are whole simulations: a thread's start costs
// nothing beside them). Every run is done before an exception reaches the
// caller (the first one by index), so no thread outlives the call.
#pragma once

#include <functional>

namespace bdfcar::scenario {

void runInParallel(int n, int jobs, const std::function<void(int)>& f);

}  // namespace bdfcar::scenario
