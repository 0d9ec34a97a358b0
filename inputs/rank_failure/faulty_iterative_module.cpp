// A stand-in for the module grout_iterative that injects rank-local failures into the
// iterative solve (inputs/rank_failure/README.md). It loads the real module (its path is
// compiled in) and passes every call on, except that solve() fails as the environment
// variable GROUT_FAULTY_SOLVE says:
//   stall: at the second solve, rank 0 throws at once; the other ranks enter a barrier on the
//          system's communicator, which rank 0 never joins (as when one rank's preconditioner
//          throws while the others wait in its next export);
//   first: every rank solves; then, at the first solve only, rank 0 throws (one rank alone
//          sees a failure the others do not).
// Test code: never installed.

#include <dlfcn.h>

#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>

#include "nonlinear/iterative_solver.hpp"

namespace {

using Factory = grout::IterativeSolver* (*)(int);

class FaultySolver : public grout::IterativeSolver {
 public:
  explicit FaultySolver(grout::IterativeSolver* real) : real_(real) {}

  int solve(const Teuchos::RCP<const grout::Matrix>& K, const grout::Vector& b, grout::Vector& x,
            const std::string& belos_type, const grout::IterativeSettings& settings) override {
    const char* env = std::getenv("GROUT_FAULTY_SOLVE");
    const std::string mode = env != nullptr ? env : "";
    const auto& comm = *K->getRowMap()->getComm();
    ++solves_;
    if (mode == "stall" && solves_ == 2) {
      if (comm.getRank() == 0) throw std::runtime_error("injected failure on rank 0 (stall)");
      comm.barrier();  // never returns: rank 0 does not come
    }
    const int iterations = real_->solve(K, b, x, belos_type, settings);
    if (mode == "first" && solves_ == 1 && comm.getRank() == 0)
      throw std::runtime_error("injected failure on rank 0 after its first solve");
    return iterations;
  }
  int reused_hierarchies() const override { return real_->reused_hierarchies(); }
  int kept_hierarchies() const override { return real_->kept_hierarchies(); }
  double jacobi_damping() const override { return real_->jacobi_damping(); }
  bool is_belos_solver(const std::string& name) const override {
    return real_->is_belos_solver(name);
  }
  std::vector<std::string> belos_solver_names() const override {
    return real_->belos_solver_names();
  }
  std::string belos_rejects(const std::string& name,
                            const Teuchos::ParameterList& belos) const override {
    return real_->belos_rejects(name, belos);
  }
  std::vector<std::string> belos_parameter_names() const override {
    return real_->belos_parameter_names();
  }
  std::vector<std::string> muelu_parameter_names() const override {
    return real_->muelu_parameter_names();
  }
  std::string muelu_rejects(const Teuchos::ParameterList& muelu) const override {
    return real_->muelu_rejects(muelu);
  }

 private:
  std::unique_ptr<grout::IterativeSolver> real_;
  int solves_ = 0;
};

}  // namespace

extern "C" grout::IterativeSolver* grout_create_iterative_solver(int interface_version) {
  if (interface_version != grout::iterative_solver_interface_version) return nullptr;
  static void* real = dlopen(GROUT_REAL_ITERATIVE_MODULE, RTLD_NOW | RTLD_LOCAL);
  if (real == nullptr) return nullptr;
  const auto create = reinterpret_cast<Factory>(dlsym(real, "grout_create_iterative_solver"));
  grout::IterativeSolver* solver = create != nullptr ? create(interface_version) : nullptr;
  return solver != nullptr ? new FaultySolver(solver) : nullptr;
}
