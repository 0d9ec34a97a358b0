#pragma once
// Finding and loading the module grout_iterative (nonlinear/iterative_solver.hpp), once per
// process, at the first iterative solve: dlopen(RTLD_NOW | RTLD_LOCAL), kept loaded until the
// process exits (MueLu and Belos register static state that must outlive every solver).
//
// The directories tried, in order:
//   1. $GROUT_PLUGIN_DIR, when set (docs/input.md, "type: belos");
//   2. the build tree's module directory (<build>/lib/grout), a definition from CMake;
//   3. the install tree's (${CMAKE_INSTALL_FULL_LIBDIR}/grout), a definition from CMake;
//   4. <directory of the executable>/../lib/grout (/proc/self/exe): a relocated install.
// A directory whose module cannot be loaded, or was built from other sources (another
// iterative_solver_interface_version), is skipped; when none works the error names every
// path tried with its dlerror().

#include <memory>
#include <string>
#include <vector>

#include "nonlinear/iterative_solver.hpp"

namespace grout {

/// The module's file name: libgrout_iterative.so.
extern const char* const iterative_module_file;

/// The directories above, in the order tried (empty entries dropped).
std::vector<std::string> iterative_module_directories();

/// dlopen()s the module from the first of `directories` that holds a loadable module of this
/// interface version and returns the handle (a leak on purpose: never dlclose()d). Throws
/// ExitCodeError (exit_code_incomplete_installation, io/errors.hpp) naming each path tried and
/// why it failed: not a failed solve that a smaller step could cure.
void* open_iterative_module(const std::vector<std::string>& directories);

/// A new solver from the module, loaded from iterative_module_directories() on the first
/// call. Throws ExitCodeError as open_iterative_module (the same on every rank: each
/// rank searches the same directories). Thread-unsafe, as the rest of the solve.
std::unique_ptr<IterativeSolver> create_iterative_solver();

/// Whether this process has loaded the module (create_iterative_solver succeeded).
bool iterative_module_loaded();

}  // namespace grout
