#include "nonlinear/iterative_module.hpp"

#include <dlfcn.h>
#include <unistd.h>
#include <climits>
#include <cstdlib>
#include <stdexcept>

#include "io/errors.hpp"

namespace grout {

const char* const iterative_module_file = "libgrout_iterative.so";

namespace {

using Factory = IterativeSolver* (*)(int);

void* loaded_module = nullptr;

// <directory of the running executable>/../lib/grout, empty if /proc/self/exe is unreadable.
std::string beside_executable() {
  char path[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", path, sizeof path - 1);
  if (n <= 0) return "";
  const std::string exe(path, std::size_t(n));
  const std::size_t slash = exe.rfind('/');
  return slash == std::string::npos ? "" : exe.substr(0, slash) + "/../lib/grout";
}

}  // namespace

std::vector<std::string> iterative_module_directories() {
  std::vector<std::string> directories;
  if (const char* env = std::getenv("GROUT_PLUGIN_DIR"); env != nullptr && *env != '\0')
    directories.push_back(env);
#ifdef GROUT_ITERATIVE_BUILD_DIR
  directories.push_back(GROUT_ITERATIVE_BUILD_DIR);
#endif
#ifdef GROUT_ITERATIVE_INSTALL_DIR
  directories.push_back(GROUT_ITERATIVE_INSTALL_DIR);
#endif
  if (std::string beside = beside_executable(); !beside.empty())
    directories.push_back(std::move(beside));
  return directories;
}

void* open_iterative_module(const std::vector<std::string>& directories) {
  std::string tried;
  for (const std::string& directory : directories) {
    const std::string path = directory + "/" + iterative_module_file;
    std::string why;
    if (access(path.c_str(), F_OK) != 0) {
      why = "no such file";
    } else if (void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL); handle == nullptr) {
      const char* error = dlerror();
      why = error != nullptr ? error : "dlopen failed";
    } else if (auto create =
                   reinterpret_cast<Factory>(dlsym(handle, "grout_create_iterative_solver"));
               create == nullptr) {
      why = "no symbol grout_create_iterative_solver";
    } else if (std::unique_ptr<IterativeSolver> probe(create(iterative_solver_interface_version));
               probe == nullptr) {
      why = "built for another interface version than " +
            std::to_string(iterative_solver_interface_version);
    } else {
      return handle;  // never dlclose()d: Trilinos keeps static state in it
    }
    tried += "\n  " + path + ": " + why;
  }
  throw ExitCodeError(
      "cannot load the iterative solver module (Belos + MueLu; set GROUT_PLUGIN_DIR to the "
      "directory holding " +
          std::string(iterative_module_file) +
          "); tried:" + (tried.empty() ? " no directory" : tried),
      exit_code_incomplete_installation);
}

std::unique_ptr<IterativeSolver> create_iterative_solver() {
  if (loaded_module == nullptr)
    loaded_module = open_iterative_module(iterative_module_directories());
  const auto create =
      reinterpret_cast<Factory>(dlsym(loaded_module, "grout_create_iterative_solver"));
  return std::unique_ptr<IterativeSolver>(create(iterative_solver_interface_version));
}

bool iterative_module_loaded() {
  return loaded_module != nullptr;
}

}  // namespace grout
