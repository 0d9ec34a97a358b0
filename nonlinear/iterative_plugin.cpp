// The module grout_iterative: LinearSolver's iterative path (Belos + MueLu), loaded on demand
// (nonlinear/iterative_solver.hpp, nonlinear/iterative_module.hpp).

#include <mpi.h>

#include <BelosSolverFactory.hpp>
#include <BelosTpetraAdapter.hpp>
#include <MueLu_CreateTpetraPreconditioner.hpp>
#include <MueLu_MasterList.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "nonlinear/elasticity_preconditioner.hpp"
#include "nonlinear/iterative_solver.hpp"
#include "nonlinear/jacobi_smoother.hpp"

namespace grout {
namespace {

// FNV-1a hashes of this rank's rows of K: its sparsity pattern (row and column global ids),
// and the pattern with the values' bits.
struct Fingerprint {
  std::uint64_t pattern = 0, values = 0;
};

Fingerprint local_fingerprint(const Matrix& K) {
  std::uint64_t h = 1469598103934665603ull, v = h;
  const auto mix = [](std::uint64_t& hash, std::uint64_t word) {
    for (int byte = 0; byte < 8; ++byte, word >>= 8)
      hash = (hash ^ (word & 0xff)) * 1099511628211ull;
  };
  const auto& row_map = *K.getRowMap();
  const auto& col_map = *K.getColMap();
  const auto local = K.getLocalMatrixHost();
  for (LO i = 0; i < LO(row_map.getNodeNumElements()); ++i) {
    mix(h, std::uint64_t(row_map.getGlobalElement(i)));
    for (auto p = local.graph.row_map(i); p < local.graph.row_map(i + 1); ++p) {
      mix(h, std::uint64_t(col_map.getGlobalElement(local.graph.entries(p))));
      std::uint64_t bits;
      const double value = local.values(p);
      std::memcpy(&bits, &value, sizeof bits);
      mix(v, bits);
    }
    mix(h, ~std::uint64_t(0));
  }
  mix(v, h);
  return {h, v};
}

// MueLu's preconditioner prints an exception's whole text (source path, "Throw test ...") to
// std::cerr before it rethrows it, from inside the Krylov solve; its message reaches the user
// through Grout's error, without the source paths (io/errors.hpp). std::cerr is held back for
// the solve's duration: passed on when the solve returns, dropped when it throws.
class HeldErrorStream {
 public:
  HeldErrorStream() : saved_(std::cerr.rdbuf(held_.rdbuf())) {}
  ~HeldErrorStream() { std::cerr.rdbuf(saved_); }
  HeldErrorStream(const HeldErrorStream&) = delete;
  HeldErrorStream& operator=(const HeldErrorStream&) = delete;
  void pass_on() const {
    std::cerr.rdbuf(saved_);
    std::cerr << held_.str() << std::flush;
  }

 private:
  std::ostringstream held_;
  std::streambuf* saved_;
};

class BelosMueLuSolver : public IterativeSolver {
 public:
  int solve(const Teuchos::RCP<const Matrix>& K, const Vector& b, Vector& x,
            const std::string& belos_type, const IterativeSettings& settings) override;
  int reused_hierarchies() const override { return reused_; }
  int kept_hierarchies() const override { return kept_; }
  double jacobi_damping() const override { return jacobi_damping_; }

  bool is_belos_solver(const std::string& name) const override {
    return Factory().isSupported(name);
  }
  std::vector<std::string> belos_solver_names() const override {
    const auto names = Factory().supportedSolverNames();
    return std::vector<std::string>(names.begin(), names.end());
  }
  std::string belos_rejects(const std::string& name,
                            const Teuchos::ParameterList& belos) const override {
    try {  // Belos checks the names and values of its parameters when it sets them
      Factory().create(name, Teuchos::rcp(new Teuchos::ParameterList(belos)));
    } catch (const std::exception& e) {
      return e.what();
    }
    return "";
  }
  std::vector<std::string> belos_parameter_names() const override {
    std::set<std::string> names;
    for (const std::string& solver : Factory().supportedSolverNames()) {
      try {  // a solver that cannot be built on Tpetra (STOCHASTIC CG) has no parameters here
        const auto valid = Factory().create(solver, Teuchos::null)->getValidParameters();
        for (auto it = valid->begin(); it != valid->end(); ++it) names.insert(valid->name(it));
      } catch (const std::exception&) {
      }
    }
    return std::vector<std::string>(names.begin(), names.end());
  }
  std::vector<std::string> muelu_parameter_names() const override {
    const auto valid = MueLu::MasterList::List();
    std::set<std::string> names;
    for (auto it = valid->begin(); it != valid->end(); ++it) names.insert(valid->name(it));
    return std::vector<std::string>(names.begin(), names.end());
  }
  std::string muelu_rejects(const Teuchos::ParameterList& muelu) const override {
    const int n = 60;  // tridiag(-1, 2, -1) on one rank
    // MPI_COMM_SELF: MueLu's summary needs an MPI communicator (a SerialComm crashes it).
    const auto comm = Teuchos::rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
    const auto map = Teuchos::rcp(new Map(n, 0, comm));
    const auto A = Teuchos::rcp(new Matrix(map, 3));
    for (GO row = 0; row < n; ++row) {
      std::vector<GO> columns;
      std::vector<double> values;
      for (GO column = std::max<GO>(row - 1, 0); column <= std::min<GO>(row + 1, n - 1); ++column) {
        columns.push_back(column);
        values.push_back(column == row ? 2.0 : -1.0);
      }
      A->insertGlobalValues(row, Teuchos::ArrayView<const GO>(columns),
                            Teuchos::ArrayView<const double>(values));
    }
    A->fillComplete();
    Teuchos::ParameterList params = muelu;
    if (!params.isParameter("verbosity")) params.set("verbosity", "none");
    try {
      Teuchos::RCP<Operator> op = A;
      MueLu::CreateTpetraPreconditioner(op, params);
    } catch (const std::exception& e) {
      return e.what();
    }
    return "";
  }

 private:
  using Factory = Belos::SolverFactory<double, MultiVector, Operator>;
  // The last MueLu hierarchy, for reuse_preconditioner.
  Teuchos::RCP<MueLu::TpetraOperator<double, LO, GO, Node>> hierarchy_;
  Teuchos::RCP<const Map> hierarchy_map_;
  Fingerprint hierarchy_print_;  // local_fingerprint of its matrix
  int fresh_iterations_ = 0;     // iterations of the hierarchy's first solve
  int excess_iterations_ = 0;    // since then, beyond fresh_iterations_ per solve
  int reused_ = 0;               // solves that reused the hierarchy
  int kept_ = 0;                 // of those, with the same values: no set-up
  double jacobi_damping_ = 0.0;  // the hierarchy's Jacobi damping; 0: not Jacobi
};

int BelosMueLuSolver::solve(const Teuchos::RCP<const Matrix>& K, const Vector& b, Vector& x,
                            const std::string& belos_type, const IterativeSettings& settings) {
  Teuchos::ParameterList muelu = settings.muelu;
  const int dim = settings.dim;
  const int num_ranks = K->getRowMap()->getComm()->getSize();
  // The nodes' coordinates and bodies: every node on every rank (the replicated mesh), or
  // each rank its rows' nodes (the distributed mesh, num_global_nodes given).
  const bool distributed = settings.num_global_nodes > 0;
  const std::size_t num_given = dim > 0 ? settings.coordinates.size() / dim : 0;
  const long long num_nodes = distributed ? settings.num_global_nodes : (long long)(num_given);
  const std::vector<GO>* nodes = distributed ? &settings.nodes : nullptr;
  bool bodies = settings.bodies.size() == num_given && num_given > 0;
  if (distributed) {  // one answer on every rank: a rank may hold no node
    int here = settings.bodies.empty() ? 0 : 1, anywhere = 0;
    Teuchos::reduceAll(*K->getRowMap()->getComm(), Teuchos::REDUCE_MAX, here,
                       Teuchos::outArg(anywhere));
    bodies = anywhere == 1;
  }
  // Damped Jacobi (nonlinear/jacobi_smoother.hpp) in place of the default Gauss-Seidel on a
  // system without multipliers, unless the user chose a smoother: its damping is estimated
  // from K at each new hierarchy (the coarse-level reuse keeps it).
  bool jacobi = false;
  if (num_nodes > 0 && is_nodal_displacement_map(*K->getRowMap(), dim, num_nodes))
    jacobi = set_elasticity_defaults(
        muelu, dim, num_ranks,
        rigid_body_modes(*K->getRowMap(), dim, settings.coordinates, nodes,
                         settings.translations_only),
        node_coordinates(*K->getRowMap(), dim, settings.coordinates,
                         bodies ? settings.bodies : std::vector<int>(), nodes),
        bodies, settings.multipliers);
  if (num_ranks > 1 && !muelu.isParameter("coarse: type"))
    muelu.set("coarse: type", "RELAXATION");  // never KLU2 on a multi-rank communicator
  const auto K_crs = Teuchos::rcp_const_cast<Matrix>(K);
  Teuchos::RCP<Operator> K_op = K_crs;
  // Reuse (Newton iterations after the first): a system equal to the last one, value for
  // value (small strain on the reference geometry with an unchanged active set: the next
  // Newton iteration, the next load step's first), keeps the whole hierarchy, with no set-up.
  // Otherwise, with the same unknowns:
  // - HierarchyReuse::prolongators: the same sparsity pattern keeps the last hierarchy's
  //   prolongators and restrictions, with the coarse operators and the smoothers recomputed
  //   from K (MueLu `reuse: type: RP`; RP keeps the coarse matrices' patterns: a changed
  //   active set changes K's);
  // - HierarchyReuse::coarse_levels: the prolongators, the coarse operators R A P and their
  //   smoothers stay, the fine-level smoother is rebuilt from K (MueLu `reuse: type: RAP`),
  //   whatever K's pattern. The V-cycle's fine level (residual and Gauss-Seidel) sees the new
  //   K, its coarse correction the old one's Galerkin operator: a preconditioner for K that
  //   stays symmetric positive definite, so CG converges; what changed between Newton
  //   iterations (the contact rows, a few hundred nodes) costs iterations, not correctness.
  //   It is rebuilt when the iterations it added since its build, each solve's count less
  //   its first solve's, exceed twice that first count: the set-up of 1-2 solves'
  //   iterations (docs/performance.md, "Iterative solver") is then cheaper than the excess,
  //   so the waste stays within one set-up per build (the rent-or-buy bound).
  // A reused hierarchy that does not converge is rebuilt and the system solved again; one
  // that needs more than twice the iterations of its fresh build (+10) is rebuilt at the next
  // solve.
  const HierarchyReuse reuse = settings.reuse;
  const bool reuse_allowed = reuse != HierarchyReuse::none;
  if (reuse_allowed && !muelu.isParameter("reuse: type"))
    muelu.set("reuse: type", std::string(reuse == HierarchyReuse::coarse_levels ? "RAP" : "RP"));
  const Fingerprint print = reuse_allowed ? local_fingerprint(*K) : Fingerprint();
  bool may_reuse =
      reuse_allowed && !hierarchy_.is_null() && hierarchy_map_->isSameAs(*K->getRowMap());
  const std::string reuse_type =
      reuse_allowed ? muelu.get<std::string>("reuse: type") : std::string("none");
  // RAP and full keep the coarse operators: K's pattern may change.
  const bool keeps_coarse = reuse_type == "RAP" || reuse_type == "full";
  bool same_values = false;
  if (may_reuse) {  // MueLu's RP reuse keeps the coarse patterns: K's must not change
    int same[2] = {keeps_coarse || print.pattern == hierarchy_print_.pattern ? 1 : 0,
                   print.values == hierarchy_print_.values ? 1 : 0};
    int all_same[2] = {0, 0};
    Teuchos::reduceAll(*K->getRowMap()->getComm(), Teuchos::REDUCE_MIN, 2, same, all_same);
    may_reuse = all_same[0] == 1;
    same_values = may_reuse && all_same[1] == 1;
  }
  Factory factory;
  auto params = Teuchos::rcp(new Teuchos::ParameterList(settings.belos));
  if (belos_type == "GMRES" && !params->isParameter("Num Blocks"))
    params->set("Num Blocks", 200);  // Krylov vectors kept before a restart
  for (int attempt = 0;; ++attempt) {
    const bool reused = may_reuse && attempt == 0;
    {
      Teuchos::TimeMonitor setup_timer(
          *Teuchos::TimeMonitor::getNewTimer("grout: linear solve: MueLu set-up"));
      if (reused) {
        // The same values: the hierarchy's own level-0 matrix equals K, nothing to redo.
        if (same_values)
          ++kept_;
        else
          MueLu::ReuseTpetraPreconditioner(K_crs, *hierarchy_);
        ++reused_;
      } else {
        Teuchos::ParameterList build = muelu;
        jacobi_damping_ = jacobi ? grout::jacobi_damping(*K) : 0.0;
        if (jacobi_damping_ > 0.0) set_jacobi_smoother(build, jacobi_damping_);
        hierarchy_ = MueLu::CreateTpetraPreconditioner(K_op, build);
        hierarchy_map_ = K->getRowMap();
      }
      hierarchy_print_ = print;
    }
    auto x_rcp = Teuchos::rcpFromRef(x);
    auto b_rcp = Teuchos::rcpFromRef(b);
    x.putScalar(0.0);
    auto problem = Teuchos::rcp(new Belos::LinearProblem<double, MultiVector, Operator>(
        K_op, Teuchos::rcp_implicit_cast<MultiVector>(x_rcp),
        Teuchos::rcp_implicit_cast<const MultiVector>(b_rcp)));
    problem->setRightPrec(hierarchy_);
    problem->setProblem();
    auto solver = factory.create(belos_type, params);
    solver->setProblem(problem);
    Belos::ReturnType converged;
    {
      Teuchos::TimeMonitor krylov_timer(
          *Teuchos::TimeMonitor::getNewTimer("grout: linear solve: Krylov iterations"));
      const HeldErrorStream held;
      converged = solver->solve();
      held.pass_on();
    }
    const int iterations = solver->getNumIters();
    bool accepted = converged == Belos::Converged;
    double relative = 0.0;
    if (!accepted) {
      // GMRES may stop on a loss of accuracy (the implicit residual met the tolerance, the
      // explicit one did not): accept an explicit residual within max(100 × the tolerance,
      // 1e-6), an inexact Newton step; Newton's residual test decides convergence.
      Vector r(b.getMap());
      K->apply(x, r);
      r.update(1.0, b, -1.0);
      const double b_norm = b.norm2();
      relative = b_norm > 0.0 ? r.norm2() / b_norm : r.norm2();
      accepted = relative <= std::max(1e-6, 100.0 * params->get<double>("Convergence Tolerance"));
    }
    if (accepted) {
      if (!reused) {
        fresh_iterations_ = iterations;
        excess_iterations_ = 0;
      } else {
        if (keeps_coarse) excess_iterations_ += std::max(0, iterations - fresh_iterations_);
        if (iterations > 2 * fresh_iterations_ + 10 ||
            (keeps_coarse && excess_iterations_ > 2 * fresh_iterations_))
          hierarchy_ = Teuchos::null;  // rebuilt at the next solve
      }
      if (!reuse_allowed) hierarchy_ = Teuchos::null;
      return iterations;
    }
    if (reused) continue;  // once more with a fresh hierarchy
    hierarchy_ = Teuchos::null;
    char message[160];
    std::snprintf(message, sizeof message,
                  "linear solver %s did not converge in %d iterations (|b - A x| / |b| = %.3e%s)",
                  belos_type.c_str(), iterations, relative,
                  solver->isLOADetected() ? ", loss of accuracy" : "");
    throw std::runtime_error(message);
  }
}

}  // namespace
}  // namespace grout

extern "C" grout::IterativeSolver* grout_create_iterative_solver(int interface_version) {
  if (interface_version != grout::iterative_solver_interface_version) return nullptr;
  return new grout::BelosMueLuSolver();
}
