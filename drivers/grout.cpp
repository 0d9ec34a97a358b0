// grout: solve the problem an input YAML describes (DESIGN.md §5) and write its results.
//
//   grout input.yaml [--output-dir DIR]      on one rank
//   mpirun -np 2 grout input.yaml
// --output-dir puts the Exodus and CSV files the input names into DIR instead of beside the
// input (DIR is created if missing); --timers prints where the time went (solid assembly,
// contact, Jacobian, linear solve; min/mean/max over ranks).
//
// Exit codes: 0 done, 2 bad input (message names the file and key or mesh entity),
// 3 a step did not converge (every earlier step is already written), 1 anything else.

#include <Teuchos_TimeMonitor.hpp>
#include <Tpetra_Core.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "assembly/distribute_mesh.hpp"
#include "assembly/solid_problem.hpp"
#include "drivers/results_output.hpp"
#include "io/errors.hpp"
#include "io/exodus.hpp"
#include "io/input.hpp"
#include "nonlinear/linear_solver.hpp"
#include "nonlinear/load_stepping.hpp"
#include "nonlinear/mechanics_problem.hpp"
#include "nonlinear/newton.hpp"

namespace {

using namespace grout;

void print_usage() {
  std::fprintf(stderr,
               "usage: grout <input.yaml> [--output-dir DIR] [--timers]\n"
               "  Solves the contact/solid problem described by the YAML input and writes the\n"
               "  Exodus results and the CSV summary it names (see docs/input.md).\n");
}

// Outputs go to `dir` under the file names the input gives them.
void redirect_outputs(Input& input, const std::string& dir, bool root) {
  namespace fs = std::filesystem;
  if (root) fs::create_directories(dir);
  input.output.file = (fs::path(dir) / fs::path(input.output.file).filename()).string();
  if (!input.output.summary.empty())
    input.output.summary = (fs::path(dir) / fs::path(input.output.summary).filename()).string();
}

int run(const std::string& input_path, const std::string& output_dir,
        const Teuchos::RCP<const Comm>& comm) {
  const bool root = comm->getRank() == 0;
  const auto start = std::chrono::steady_clock::now();

  // Parse: the input is validated into plain structs before anything is built.
  Input input = read_input(input_path);
  if (!output_dir.empty()) redirect_outputs(input, output_dir, root);
  const Mesh mesh = read_and_broadcast_mesh(*comm, [&] { return read_exodus(input.mesh_file); });
  check_input_against_mesh(input, mesh);
  if (root) {
    std::printf("grout: %s: %lld nodes, %lld elements, %d rank(s)\n", input.file.c_str(),
                mesh.num_nodes(), mesh.num_elements(), comm->getSize());
  }

  // Build: partition, maps, graph, contact interfaces; solvers from the `solver` sublist.
  const SolidProblem solid(mesh, input, comm);
  MechanicsProblem problem(solid, mesh, input);
  const NewtonOptions newton = newton_options_from(*input.solver);
  const Teuchos::ParameterList linear_params = input.solver->isSublist("Linear Solver")
                                                   ? input.solver->sublist("Linear Solver")
                                                   : Teuchos::ParameterList();
  LinearSolver linear(linear_params, input.file + ": grout/solver/Linear Solver");
  linear.set_multiplier_pairing(problem.multiplier_pairing(), mesh.dimension);
  linear.set_coordinates(mesh.coordinates, mesh.dimension);
  ResultsOutput output(mesh, input, solid, problem);
  SteppingOptions stepping;
  stepping.end_time = input.time.end;
  stepping.steps = input.time.steps;

  // Solve, writing and flushing every converged step at once.
  solve_load_steps(problem, linear, newton, stepping, [&](const ConvergedStep& step) {
    output.write(step);
    if (root) {
      std::printf(
          "step %d  t = %g  newton %d  linear %d  |F| = %.3e\n", step.step, step.time,
          step.newton->iterations, step.newton->linear_iterations,
          step.newton->residual_history.empty() ? 0.0 : step.newton->residual_history.back());
      std::fflush(stdout);
    }
  });
  if (root) {
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("grout: wrote %s and %s (%.2f s)\n", input.output.file.c_str(),
                input.output.summary.c_str(), seconds);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Tpetra::ScopeGuard tpetra(&argc, &argv);
  const auto comm = Tpetra::getDefaultComm();
  const bool root = comm->getRank() == 0;
  std::string input_path, output_dir;
  bool timers = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      if (root) print_usage();
      return 0;
    } else if (arg == "--timers") {
      timers = true;
    } else if (arg == "--output-dir" && i + 1 < argc) {
      output_dir = argv[++i];
    } else if (input_path.empty() && arg.rfind("-", 0) != 0) {
      input_path = arg;
    } else {
      if (root) std::fprintf(stderr, "grout: error: unexpected argument '%s'\n", arg.c_str());
      if (root) print_usage();
      return 2;
    }
  }
  if (input_path.empty()) {
    if (root) print_usage();
    return 2;
  }
  try {
    const int status = run(input_path, output_dir, comm);
    if (timers) Teuchos::TimeMonitor::summarize(comm.ptr(), std::cout, false, true, false);
    return status;
  } catch (const grout::InputError& e) {
    if (root) std::fprintf(stderr, "grout: error: %s\n", e.what());
    return 2;
  } catch (const grout::ConvergenceError& e) {
    if (root)
      std::fprintf(stderr, "grout: error: %s (converged steps are in the output)\n", e.what());
    return 3;
  } catch (const std::exception& e) {
    if (root) std::fprintf(stderr, "grout: error: %s\n", e.what());
    return 1;
  }
}
