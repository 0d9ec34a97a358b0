#pragma once
// Shared by the fuzz targets and the replay driver.

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <typeinfo>

namespace grout::fuzz {

/// A reader refused its input, as it should; the message is shown when GROUT_FUZZ_VERBOSE
/// is set (to see what the corpus exercises).
inline void expected_error(const std::exception& e) {
  static const bool verbose = std::getenv("GROUT_FUZZ_VERBOSE") != nullptr;
  if (verbose) std::fprintf(stderr, "  InputError: %s\n", e.what());
}

/// An exception other than InputError escaped a reader: report it and abort, so that
/// libFuzzer (or the replay test) records the input as a failure.
[[noreturn]] inline void unexpected_exception(const std::exception& e) {
  std::fprintf(stderr, "grout fuzz: unexpected exception %s: %s\n", typeid(e).name(), e.what());
  std::abort();
}

}  // namespace grout::fuzz
