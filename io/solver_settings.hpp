#pragma once
// The `grout/solver` section of the input, typed once (docs/input.md, "grout/solver"): Newton's
// tolerances and line search, the linear solver's type and MUMPS options, and the sublists
// passed through to NOX, Belos and MueLu, each key checked against the names the package
// accepts (io/solver_parameters.hpp). The solvers (nonlinear/newton.hpp,
// nonlinear/linear_solver.hpp, nonlinear/mumps_solver.hpp) take these structs; none of them
// looks a setting up by string.

#include <Teuchos_ParameterList.hpp>
#include <optional>
#include <string>

namespace grout {

/// Options of the `Linear Solver/MUMPS` sublist.
struct MumpsOptions {
  /// Fill-reducing ordering: scotch (SCOTCH on the gathered graph, ICNTL(7) = 3), ptscotch
  /// (parallel PT-SCOTCH, ICNTL(28) = 2, ICNTL(29) = 1; same as scotch on one rank), amd
  /// (ICNTL(7) = 0) or pord (ICNTL(7) = 4).
  std::string ordering = "scotch";
  /// true: the matrix is symmetric (MUMPS sym = 2, LDLᵀ of the lower triangle, about half
  /// the work). Only for a matrix known to be symmetric; false (sym = 0, LU) is always safe.
  bool symmetric = false;
  /// true: the system is gathered to rank 0 and factorised there on one BLAS thread
  /// (LinearSolver, `gather`): MUMPS then sees the same matrix and does the same operations in
  /// the same order on any number of ranks, so the answer is the same bit for bit. false: each
  /// rank hands MUMPS its rows (the fronts are factorised on all ranks; rounding differs).
  bool gather = false;
  /// true (symmetric positive definite matrices only; LinearSolver sets it for the symmetric
  /// reduction, it is no input key): when a new matrix differs from the last factorised one
  /// only in rows that an analysis put into the Schur set, solve it with a dense update of
  /// the Schur complement instead of a new factorisation (schur_update.hpp). The Schur set is
  /// chosen at an analysis that the pattern requires anyway: the rows that changed since the
  /// last factorisation, joined to the previous set, while its dense Cholesky factorisation
  /// costs at most half a sparse one.
  bool schur_updates = false;
};

/// `Linear Solver/type` (docs/input.md, "type: auto").
enum class LinearSolverType { automatic, mumps, amesos2, belos };

/// The input name of `type`: auto, mumps, amesos2 or belos.
std::string linear_solver_type_name(LinearSolverType type);

/// Belos' defaults in Grout: `Convergence Tolerance` 1e-12, `Maximum Iterations` 2000.
Teuchos::ParameterList grout_belos_defaults();

/// The `Linear Solver` sublist.
struct LinearSolverSettings {
  LinearSolverType type = LinearSolverType::automatic;
  MumpsOptions mumps;                 ///< the `MUMPS` sublist
  bool mumps_given = false;           ///< a `MUMPS` sublist was given: auto keeps MUMPS
  bool mumps_ordering_given = false;  ///< `MUMPS/ordering` was given (gathered solves: amd)
  /// `Belos/Solver Type`; empty: CG without multipliers, GMRES on the condensed system.
  std::string belos_solver;
  /// The other `Belos` keys, typed as Belos takes them, over grout_belos_defaults().
  Teuchos::ParameterList belos = grout_belos_defaults();
  Teuchos::ParameterList muelu;  ///< the `MueLu` sublist, typed as MueLu takes it
  /// `condense_multipliers`; absent: the solver's default (linear_solver.hpp).
  std::optional<bool> condense_multipliers;
  /// `reuse_preconditioner`; absent: the coarse levels are kept (linear_solver.hpp).
  std::optional<bool> reuse_preconditioner;
  /// `symmetric_reduction`: condensed solves (distributed MUMPS, Belos) try the symmetric
  /// reduction first (linear_solver.hpp).
  bool symmetric_reduction = true;
  /// `near_null_space: translations`: MueLu's near-null space on the iterative path holds the
  /// translations only (linear_solver.hpp); false (`rigid_body`, the default): the rotations too.
  bool translations_only = false;
  /// "<file>: grout/solver/Linear Solver", the prefix of the solvers' input errors.
  std::string where = "grout/solver/Linear Solver";
};

/// The `Newton` sublist, and the `NOX` sublist passed through.
struct NewtonOptions {
  int max_iterations = 25;
  double absolute_tolerance = 1e-10;  ///< converged if ‖F‖₂ ≤ this ...
  double relative_tolerance = 1e-10;  ///< ... or ‖F‖₂ / ‖F(x₀)‖₂ < this
  double floor_factor = 10.0;  ///< ... or ‖F‖₂ ≤ this · residual_floor() (round-off; 0 = off)
  double update_tolerance = 0.0;          ///< and, if > 0, ‖Δx‖_∞ < this
  std::string line_search = "Full Step";  ///< NOX name: "Full Step", "Backtrack", "Polynomial"
  /// The line search of the retries of a step whose Newton solve failed (and of its
  /// cut-backs), when `line_search` is the default full step and the input chose none
  /// (Newton/line_search, or NOX's Line Search sublist); empty: none (load_stepping.hpp).
  std::string fallback_line_search = "Backtrack";
  bool require_unchanged_active_set = true;  ///< and no active-set change at the iterate
  bool verbose = true;                       ///< one log line per iteration on rank 0
  Teuchos::ParameterList nox;                ///< passed to NOX, merged over Grout's defaults
  std::string where = "grout/solver";        ///< "<input file>: grout/solver", for errors
};

/// Bounds of the Newton tolerances (docs/input.md): a relative tolerance of 1 or more accepts
/// the first iterate, and an absolute one above max_absolute_tolerance (force units) accepts
/// a residual no solve should stop at.
constexpr double max_relative_tolerance = 1.0;  ///< relative_tolerance < this
constexpr double max_absolute_tolerance = 1.0;  ///< absolute_tolerance ≤ this

struct SolverSettings {
  NewtonOptions newton;
  LinearSolverSettings linear;
};

/// Reads and validates the `solver` sublist (`Newton`, `NOX`, `Linear Solver`); `file` names
/// the input in errors ("" for none). Throws InputError "<file>: grout/solver/...: <what>",
/// with a "did you mean" for a misspelt key.
SolverSettings solver_settings_from(const Teuchos::ParameterList& solver,
                                    const std::string& file = "");

/// solver_settings_from(solver_sublist, file).newton.
NewtonOptions newton_options_from(const Teuchos::ParameterList& solver_sublist,
                                  const std::string& file = "");

/// Reads a `Linear Solver` sublist on its own; `where` names it in errors
/// ("case.yaml: grout/solver/Linear Solver").
LinearSolverSettings linear_solver_settings_from(const Teuchos::ParameterList& params,
                                                 const std::string& where);

/// Reads a `MUMPS` sublist on its own; throws InputError naming `where` + key on a bad value.
MumpsOptions mumps_options_from(const Teuchos::ParameterList& params, const std::string& where);

}  // namespace grout
