#include "cli_errors.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <new>

#include "config/toml_reader.h"
#include "multibody/model_error.h"
#include "scenario/row_file.h"

namespace bdfcar::app {

// Library exceptions are worded for people: never "std::bad_alloc" or "stod".
int reportErrors(const std::function<int()>& body) {
  try {
    return body();
  } catch (const scenario::OutputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return kExitOutputFailed;
  } catch (const config::ConfigError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
  } catch (const mb::ModelError& e) {
    std::fprintf(stderr, "error: invalid model: %s\n", e.what());
  } catch (const std::filesystem::filesystem_error& e) {
    std::fprintf(stderr, "error: %s: %s\n", e.path1().string().c_str(), e.code().message().c_str());
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "error: out of memory (an input asks for more than this machine has)\n");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
  }
  return kExitBadInput;
}

int cliExitCode(const CLI::App& app, const CLI::ParseError& e) {
  const int code = app.exit(e);
  if (code == 0) return kExitOk;
  const int value = static_cast<int>(CLI::ExitCodes::ConversionError);
  const int check = static_cast<int>(CLI::ExitCodes::ValidationError);
  return code == value || code == check ? kExitBadInput : kExitUsage;
}

namespace {

// "expected a finite number" for NaN and inf; other text is left to the option's own conversion.
std::string finiteOrWhy(std::string& text) {
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if (end != text.c_str() && !std::isfinite(x)) return "expected a finite number, got " + text;
  return {};
}

}  // namespace

void requireFiniteNumbers(CLI::App& app) {
  const CLI::Validator finite(finiteOrWhy, "", "FINITE");
  for (CLI::Option* o : app.get_options())
    if (o->get_type_name().rfind("FLOAT", 0) == 0) o->check(finite);
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) requireFiniteNumbers(*sub);
}

}  // namespace bdfcar::app
