// Error thrown while building a model from invalid data. The message names
// the element and what was expected; loaders prefix the file and line.
#pragma once

#include <stdexcept>
#include <string>

namespace bdfcar::mb {

struct ModelError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace bdfcar::mb
