#pragma once
// The iterative path of LinearSolver (Belos Krylov solver + MueLu preconditioner) behind an
// abstract interface: it is built as the module grout_iterative (nonlinear/iterative_plugin.cpp,
// with elasticity_preconditioner.cpp), the one binary of Grout that links MueLu, Belos and
// Xpetra, and is dlopen()ed at the first iterative solve (nonlinear/iterative_module.hpp).
//
// Why: Debian builds Trilinos with BIND_NOW, so the dynamic loader resolves every symbol of
// every loaded library before main. MueLu, Belos, Xpetra and what they pull in (Teko, Thyra,
// Stratimikos, Ifpack2, ML, ...) were 58 % of the 312 k start-up relocations of `grout`, more
// than a small 2D run's own work (docs/performance.md, "Process
// start-up"). A process that solves directly never loads them.
//
// Only standard, Teuchos and Tpetra types cross the boundary: the module and the process share
// one libstdc++, one Kokkos and one Tpetra (the same Debian shared libraries).

#include <Teuchos_ParameterList.hpp>
#include <string>
#include <vector>

#include "assembly/tpetra_types.hpp"

namespace grout {

/// What of the last MueLu hierarchy the next solve of the same unknowns keeps
/// (linear_solver.hpp, `reuse_preconditioner`).
enum class HierarchyReuse {
  none,           ///< a new hierarchy every solve (`reuse_preconditioner: false`)
  coarse_levels,  ///< prolongators and coarse levels; the fine smoother rebuilt (the default)
  prolongators,   ///< prolongators, coarse operators rebuilt (`reuse_preconditioner: true`)
};

/// What LinearSolver knows of the iterative path's settings (references into its own state).
struct IterativeSettings {
  const Teuchos::ParameterList& belos;     ///< Belos parameters, without `Solver Type`
  const Teuchos::ParameterList& muelu;     ///< the user's `MueLu` sublist
  HierarchyReuse reuse;                    ///< what of the MueLu hierarchy a solve keeps
  int dim;                                 ///< 0: no coordinates
  const std::vector<double>& coordinates;  ///< node-major, every node or those of `nodes`
  const std::vector<int>& bodies;          ///< body per node; empty on every rank: one body
  const std::vector<GO>& nodes;            ///< ids of the nodes given, ascending; empty: all
  long long num_global_nodes;              ///< all ranks; 0: the nodes of `coordinates`
  bool multipliers;                        ///< contact or tie multipliers (condensed or not)
  bool translations_only;                  ///< near-null space: no rotations (elasticity)
};

class IterativeSolver {
 public:
  virtual ~IterativeSolver() = default;

  /// Solve K x = b with Belos `belos_type` right-preconditioned by MueLu (smoothed
  /// aggregation for elasticity when the coordinates are given); returns the iterations.
  /// Throws std::runtime_error if it does not converge. Keeps the MueLu hierarchy for the next
  /// solve as `settings.reuse` says.
  virtual int solve(const Teuchos::RCP<const Matrix>& K, const Vector& b, Vector& x,
                    const std::string& belos_type, const IterativeSettings& settings) = 0;
  /// Solves that reused a MueLu hierarchy, since construction.
  virtual int reused_hierarchies() const = 0;
  /// Of those, the solves whose system equalled the hierarchy's value for value: the whole
  /// hierarchy kept, no set-up.
  virtual int kept_hierarchies() const = 0;
  /// The damping of the last built hierarchy's Jacobi smoother (nonlinear/jacobi_smoother.hpp),
  /// or 0 when it smooths otherwise (Gauss-Seidel, ILU(0) or the user's smoother).
  virtual double jacobi_damping() const = 0;

  /// Belos's solver names (case-insensitive), to check `Belos/Solver Type` against.
  virtual bool is_belos_solver(const std::string& name) const = 0;
  virtual std::vector<std::string> belos_solver_names() const = 0;
  /// Empty if Belos accepts the parameters `belos` for solver `name`, otherwise its message.
  virtual std::string belos_rejects(const std::string& name,
                                    const Teuchos::ParameterList& belos) const = 0;
  /// The parameter names of every Belos solver (each solver manager's getValidParameters()),
  /// and MueLu's (MueLu::MasterList::List()), sorted: what io/solver_parameters.hpp's
  /// allow-lists are checked against.
  virtual std::vector<std::string> belos_parameter_names() const = 0;
  virtual std::vector<std::string> muelu_parameter_names() const = 0;
  /// Empty if MueLu builds a preconditioner with `muelu` for a small 1D Laplacian on one rank,
  /// otherwise its message (for tests of the values io/ admits; some settings need data such
  /// a matrix lacks, e.g. coordinates).
  virtual std::string muelu_rejects(const Teuchos::ParameterList& muelu) const = 0;
};

/// Bumped whenever IterativeSolver or IterativeSettings change: a module built from other
/// sources refuses to create a solver (the loader then tries the next directory).
constexpr int iterative_solver_interface_version = 7;

}  // namespace grout

/// The module's factory (C linkage, looked up by dlsym): a new solver, or nullptr when
/// `interface_version` is not the module's iterative_solver_interface_version.
extern "C" grout::IterativeSolver* grout_create_iterative_solver(int interface_version);
