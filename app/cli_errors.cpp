#include "cli_errors.h"

#include <cstdio>
#include <exception>

#include "config/toml_reader.h"
#include "multibody/model_error.h"

namespace bdfcar::app {

int reportErrors(const std::function<int()>& body) {
  try {
    return body();
  } catch (const config::ConfigError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
  } catch (const mb::ModelError& e) {
    std::fprintf(stderr, "error: invalid model: %s\n", e.what());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
  }
  return 1;
}

}  // namespace bdfcar::app
