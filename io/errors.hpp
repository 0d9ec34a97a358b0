#pragma once
#include <exception>
#include <sstream>
#include <stdexcept>
#include <string>

namespace grout {

/// An error in what the user gave us (input file, mesh, expression, output paths). The
/// message names the file and the key or mesh entity; the driver prints it without a stack
/// trace and exits 2.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Exit code of a run that cannot load a part of Grout's own installation (a module such as
/// the iterative solvers' libgrout_iterative.so): neither the input nor the numerics.
constexpr int exit_code_incomplete_installation = 4;

/// A failure that carries its own exit code (3: a step did not converge; 4: an incomplete
/// installation).
class ExitCodeError : public std::runtime_error {
 public:
  ExitCodeError(const std::string& what, int exit_code)
      : std::runtime_error(what), exit_code_(exit_code) {}
  int exit_code() const { return exit_code_; }

 private:
  int exit_code_;
};

/// Thrown on the ranks that did not report an error another rank reported (its message is
/// printed there, once): carries only that error's exit code.
class ErrorOnOtherRank : public ExitCodeError {
 public:
  explicit ErrorOnOtherRank(int exit_code)
      : ExitCodeError("error reported by another rank", exit_code) {}
};

/// The driver's exit code for an error: 2 for InputError, the code an ExitCodeError
/// carries, 1 for anything else (including what is not a std::exception).
inline int exit_code_of(const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const InputError&) {
    return 2;
  } catch (const ExitCodeError& e) {
    return e.exit_code();
  } catch (...) {
    return 1;
  }
}

/// The message of an error, for what is not a std::exception too (NOX throws string
/// literals).
inline std::string message_of(const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const std::exception& e) {
    return e.what();
  } catch (const char* text) {
    return text;
  } catch (const std::string& text) {
    return text;
  } catch (...) {
    return "unknown error (not a std::exception)";
  }
}

/// Trilinos messages start with the source file and line that threw and repeat the test
/// that failed ("Throw test that evaluated to true: ..."): keep the sentences for the user,
/// on one line.
inline std::string without_source_paths(const std::string& text) {
  std::istringstream stream(text);
  std::string kept;
  for (std::string line; std::getline(stream, line);) {
    const auto start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line.find(".cpp:") != std::string::npos ||
        line.find(".hpp:") != std::string::npos || line.find(".H:") != std::string::npos ||
        line.find(".C:") != std::string::npos || line.rfind("Throw number", 0) == 0 ||
        line.rfind("Throw test that evaluated", 0) == 0) {
      continue;
    }
    kept += (kept.empty() ? "" : " ") + line.substr(start);
  }
  return kept.empty() ? text : kept;
}

}  // namespace grout
