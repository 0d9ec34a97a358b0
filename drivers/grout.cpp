// grout: solve the problem an input YAML describes (docs/design.md §5) and write its results.
//
//   grout input.yaml [--output-dir DIR]      on one rank
//   mpirun -np 2 grout input.yaml
// --output-dir puts the Exodus and CSV files the input names into DIR instead of beside the
// input (DIR is created if missing); --timers prints where the time went (solid assembly,
// contact, Jacobian, linear solve; min/mean/max over ranks) and, before the first step,
// which mesh the run reads and what each rank holds of it.
//
// The mesh: every run reads the distributed mesh (each rank its part, drivers/mesh_choice.hpp;
// with contact, the slave faces' elements partitioned apart, so that every rank evaluates its
// share of them; GROUT_PARTITION picks another partition). GROUT_MESH=replicated makes every
// rank read the whole mesh instead.
//
// Exit codes: 0 done, 2 bad input (message names the file and key or mesh entity; also an
// output that cannot be written), 3 a step did not converge (every earlier step is already
// written), 1 anything else. On several ranks an error found by one rank ends every rank
// with one message and one exit code (assembly/agree_on_errors.hpp).

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <Tpetra_Core.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "assembly/agree_on_errors.hpp"
#include "assembly/contact_mesh.hpp"
#include "assembly/distribute_mesh.hpp"
#include "assembly/initial_conditions.hpp"
#include "assembly/mass_matrix.hpp"
#include "assembly/raw_mpi_comm.hpp"
#include "assembly/solid_problem.hpp"
#include "drivers/heap_settings.hpp"
#include "drivers/mesh_choice.hpp"
#include "drivers/mpi_startup.hpp"
#include "drivers/results_output.hpp"
#include "io/errors.hpp"
#include "io/exodus.hpp"
#include "io/input.hpp"
#include "nonlinear/dynamic_stepping.hpp"
#include "nonlinear/linear_solver.hpp"
#include "nonlinear/load_stepping.hpp"
#include "nonlinear/mechanics_problem.hpp"
#include "nonlinear/newton.hpp"
#include "nonlinear/system_layout.hpp"
#include "parallel/distributed_bodies.hpp"
#include "parallel/distributed_mesh.hpp"
#include "parallel/exodus_slices.hpp"

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
  std::error_code error;
  if (root && !fs::create_directories(dir, error) && !fs::is_directory(dir)) {
    throw InputError("--output-dir " + dir + ": cannot create the folder (" +
                     (error ? error.message() : "a file of that name exists") + ")");
  }
  input.output.file = (fs::path(dir) / fs::path(input.output.file).filename()).string();
  if (!input.output.summary.empty())
    input.output.summary = (fs::path(dir) / fs::path(input.output.summary).filename()).string();
}

/// The mesh of a run: the replicated mesh, or this rank's part of the distributed mesh.
struct RunMesh {
  std::optional<Mesh> replicated;
  std::optional<DistributedMesh> distributed;
  std::string partition;  ///< the distributed mesh's partition, in words
  /// On the distributed mesh: whether the run solves on Belos + MueLu (iterative_solver_chosen
  /// with the contact's slave nodes counted), whose layout then takes the owned nodes.
  bool iterative = false;

  const Mesh& mesh() const { return distributed ? distributed->local : *replicated; }
  GlobalIndex num_nodes() const {
    return distributed ? distributed->global_num_nodes : replicated->num_nodes();
  }
  GlobalIndex num_elements() const {
    return distributed ? distributed->global_num_elements : replicated->num_elements();
  }
};

/// What contact reads of a distributed mesh (assembly/contact_mesh.hpp), bodies not set.
ContactMeshPart contact_mesh_part(const DistributedMesh& mesh) {
  ContactMeshPart part;
  part.global_num_nodes = mesh.global_num_nodes;
  part.rank = mesh.rank;
  part.node_gid = &mesh.node_gid;
  part.element_owner = &mesh.element_owner;
  part.element_gid = &mesh.element_gid;
  part.side_set_position = &mesh.side_set_position;
  part.side_set_global_size = &mesh.side_set_global_size;
  return part;
}

/// Collective: the slave nodes of every contact pair of `input` on the distributed mesh (the
/// slave side sets gathered, as the interfaces gather them).
GlobalIndex contact_slave_nodes(const DistributedMesh& mesh, const Input& input, const Comm& comm) {
  const ContactMeshPart part = contact_mesh_part(mesh);  // only the faces' nodes are read
  const ContactMesh contact_mesh(mesh.local, part, raw_mpi_comm(comm));
  GlobalIndex count = 0;
  for (const ContactInput& c : input.contact) {
    std::vector<GlobalIndex> nodes;
    for (const std::string& set : contact_side_sets(c, false)) {
      const SideFaces faces = contact_mesh.all_faces(set);
      for (std::size_t f = 0; f < faces.size(); ++f)
        nodes.insert(nodes.end(), faces.nodes[f].begin(),
                     faces.nodes[f].begin() + std::max(faces.num_nodes[f], 0));
    }
    std::sort(nodes.begin(), nodes.end());
    count += GlobalIndex(std::unique(nodes.begin(), nodes.end()) - nodes.begin());
  }
  return count;
}

/// Collective. Reads the distributed mesh, or the replicated one under GROUT_MESH=replicated
/// (`forced_replicated`; drivers/mesh_choice.hpp), and checks the input against it; every rank
/// agrees on the outcome.
RunMesh read_mesh(const Input& input, bool forced_replicated,
                  const Teuchos::RCP<const Comm>& comm) {
  RunMesh run_mesh;
  if (forced_replicated) {
    run_mesh.replicated =
        read_and_broadcast_mesh(*comm, [&] { return read_exodus(input.mesh_file); });
    agree_on_errors(*comm, [&] { check_input_against_mesh(input, *run_mesh.replicated); });
    return run_mesh;
  }
  // With contact, the partition shares the slave faces as well as the elements.
  DistributionOptions options;
  agree_on_errors(*comm, [&] { options = distribution_options(input); });
  run_mesh.partition = describe_partition(options);
  const DistributedMesh& mesh =
      run_mesh.distributed.emplace(read_distributed_mesh(*comm, input.mesh_file, options));
  double x_max = 0.0, x_max_all = 0.0;  // the axisymmetric check's extent in x
  for (GlobalIndex n = 0; n < mesh.num_owned_nodes; ++n)
    x_max =
        std::max(x_max, std::abs(mesh.local.coordinates[std::size_t(n * mesh.local.dimension)]));
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, x_max, Teuchos::outArg(x_max_all));
  const MeshPartNumbers numbers{mesh.node_gid, mesh.element_gid,          mesh.element_owner,
                                mesh.rank,     mesh.side_set_global_size, mesh.node_set_global_size,
                                x_max_all};
  agree_on_errors(*comm, [&] { check_input_against_mesh(input, mesh.local, numbers); });
  // With contact under `type: auto` the multipliers count too (dim per slave node, as
  // ContactInterface numbers them).
  const GlobalIndex slave_nodes =
      input.contact.empty() || input.solver.linear.type != LinearSolverType::automatic
          ? 0
          : contact_slave_nodes(mesh, input, *comm);
  run_mesh.iterative = iterative_solver_chosen(input, mesh.global_num_nodes, slave_nodes);
  return run_mesh;
}

/// The layout the direct solvers read (linear_solver.hpp): the dimension and the multiplier
/// pairing; no coordinates or bodies, which only the iterative path reads. Collective.
SystemLayout direct_solver_layout(const MechanicsProblem& problem, int dim) {
  SystemLayout layout;
  layout.multiplier_pairing = problem.multiplier_pairing();
  layout.dofs_per_node = dim;
  layout.dim = dim;
  return layout;
}

/// The layout on the distributed mesh: the direct solvers' (the dimension, the pairing), and
/// for the iterative path each rank's owned nodes (its rows' nodes) with their coordinates and
/// bodies, labelled across the ranks (parallel/distributed_bodies.hpp; none when the mesh is
/// one body). Collective.
SystemLayout distributed_layout(const MechanicsProblem& problem, const DistributedMesh& mesh,
                                bool iterative, const Comm& comm) {
  SystemLayout layout = direct_solver_layout(problem, mesh.local.dimension);
  if (!iterative) return layout;
  const std::size_t owned = std::size_t(mesh.num_owned_nodes), dim = mesh.local.dimension;
  layout.nodes.assign(mesh.node_gid.begin(), mesh.node_gid.begin() + owned);
  layout.coordinates.assign(mesh.local.coordinates.begin(),
                            mesh.local.coordinates.begin() + owned * dim);
  layout.num_global_nodes = mesh.global_num_nodes;
  DistributedBodies bodies = distributed_node_bodies(comm, mesh);
  if (bodies.num_bodies > 1) layout.node_bodies = std::move(bodies.owned_node_body);
  return layout;
}

/// The body of each owned node of the solid, in its owned order (DynamicProblem): from the
/// replicated mesh's layout (every node's body), or labelled across the ranks on the
/// distributed mesh (parallel/distributed_bodies.hpp). Collective.
std::vector<int> owned_node_bodies(const SolidProblem& solid, const DistributedMesh* distributed,
                                   const SystemLayout& layout, const Comm& comm) {
  std::vector<int> bodies(std::size_t(solid.num_owned_nodes()), 0);
  if (distributed) {
    const DistributedBodies all = distributed_node_bodies(comm, *distributed);
    for (int k = 0; k < solid.num_owned_nodes(); ++k)
      bodies[k] = all.owned_node_body[std::size_t(distributed->local_node(solid.column_node(k)))];
  } else {
    for (int k = 0; k < solid.num_owned_nodes(); ++k)
      bodies[k] = layout.node_bodies[std::size_t(solid.column_node(k))];
  }
  return bodies;
}

/// The mass matrix's layout on the distributed mesh: each rank's owned nodes with their
/// coordinates (the iterative path's near-null space; a direct solver reads the dimension).
SystemLayout distributed_mass_layout(const DistributedMesh& mesh) {
  SystemLayout layout;
  const std::size_t owned = std::size_t(mesh.num_owned_nodes), dim = mesh.local.dimension;
  layout.dim = mesh.local.dimension;
  layout.nodes.assign(mesh.node_gid.begin(), mesh.node_gid.begin() + owned);
  layout.coordinates.assign(mesh.local.coordinates.begin(),
                            mesh.local.coordinates.begin() + owned * dim);
  layout.num_global_nodes = mesh.global_num_nodes;
  return layout;
}

void run(const std::string& input_path, const std::string& output_dir, bool timers,
         const Teuchos::RCP<const Comm>& comm) {
  const bool root = comm->getRank() == 0;
  const auto start = std::chrono::steady_clock::now();

  // Parse: the input is validated into plain structs before anything is built. Each phase
  // whose errors one rank alone may find ends with every rank agreeing on its outcome.
  Input input;
  bool forced_replicated = false;
  agree_on_errors(*comm, [&] {
    input = read_input(input_path);
    if (!output_dir.empty()) redirect_outputs(input, output_dir, root);
    forced_replicated = replicated_mesh_forced();
  });
  const RunMesh run_mesh = read_mesh(input, forced_replicated, comm);
  const Mesh& mesh = run_mesh.mesh();  // the replicated mesh or this rank's part
  const DistributedMesh* distributed = run_mesh.distributed ? &*run_mesh.distributed : nullptr;
  if (root) {
    std::printf("grout: %s: %lld nodes, %lld elements, %d rank(s)\n", input.file.c_str(),
                run_mesh.num_nodes(), run_mesh.num_elements(), comm->getSize());
    // Said before the first step, so that a run that is killed still names its results.
    if (input.output.parallel == OutputParallel::per_rank && comm->getSize() > 1)
      std::printf(
          "grout: results files %s to %s (output/parallel: per_rank, one per rank)\n",
          spread_file_name(input.output.file, comm->getSize(), 0).c_str(),
          spread_file_name(input.output.file, comm->getSize(), comm->getSize() - 1).c_str());
    else
      std::printf("grout: results file %s\n", input.output.file.c_str());
    // The average-acceleration rule keeps the energy of a linear system only.
    if (input.dynamics.enabled && input.dynamics.scheme == DynamicsScheme::newmark &&
        input.model.strain == StrainKind::finite)
      std::printf(
          "grout: note: %s: dynamics/scheme newmark under strain: finite keeps neither the energy "
          "nor the angular momentum of the bodies exactly; scheme energy_momentum does "
          "(docs/input.md)\n",
          input.file.c_str());
    std::fflush(stdout);
  }

  // Build: partition, maps, graph, contact interfaces; solvers from the `solver` sublist.
  const std::unique_ptr<const SolidProblem> solid_problem =
      distributed ? std::make_unique<const SolidProblem>(mesh_part(*distributed), input, comm)
                  : std::make_unique<const SolidProblem>(mesh, input, comm);
  const SolidProblem& solid = *solid_problem;
  if (timers) {  // collective
    const std::string mesh_held = distributed ? describe_holdings(*comm, *distributed) : "";
    const std::string held = describe_solid_holdings(solid);
    if (root && distributed)
      std::printf("grout: mesh: distributed (each rank reads a slice and holds its part; %s)\n%s%s",
                  run_mesh.partition.c_str(), mesh_held.c_str(), held.c_str());
    else if (root)
      std::printf(
          "grout: mesh: replicated (every rank holds all %lld nodes and %lld elements; "
          "GROUT_MESH=replicated)\n%s",
          run_mesh.num_nodes(), run_mesh.num_elements(), held.c_str());
  }
  // Contact on the distributed mesh: global numbers, set positions and bodies (collective).
  std::optional<ContactMeshPart> contact_part;
  if (distributed && !input.contact.empty()) {
    contact_part = contact_mesh_part(*distributed);
    contact_part->node_body = distributed_node_body_labels(*comm, *distributed);
  }
  MechanicsProblem problem(solid, mesh, input, contact_part ? &*contact_part : nullptr);
  if (timers) {  // collective
    const std::string held = problem.describe_contact_holdings();
    if (root && !held.empty()) std::printf("%s", held.c_str());
  }
  const NewtonOptions& newton = input.solver.newton;
  // The replicated mesh's layout also has every node's coordinates and body (iterative path).
  const SystemLayout layout =
      distributed ? distributed_layout(problem, *distributed, run_mesh.iterative, *comm)
                  : system_layout(problem, mesh);
  LinearSolver linear(input.solver.linear, layout);
  std::unique_ptr<ResultsOutput> output;
  agree_on_errors(*comm, [&] {
    output = std::make_unique<ResultsOutput>(mesh, input, solid, problem, distributed);
  });
  SteppingOptions stepping;
  stepping.end_time = input.time.end;
  stepping.steps = input.time.steps;
  stepping.step_size.adaptive = input.time.adaptive;
  stepping.step_size.max_step_size = input.time.max_step_size;
  stepping.min_step_size = input.time.min_step_size;
  stepping.extrapolate = input.time.extrapolate;

  // Solve, writing and flushing every converged step at once.
  const auto write_step = [&](const ConvergedStep& step) {
    agree_on_errors(*comm, [&] { output->write(step); });
    if (root) {
      std::printf(
          "step %d  t = %g  dt = %g  newton %d  linear %d  |F| = %.3e\n", step.step, step.time,
          step.step_size, step.newton->iterations, step.newton->linear_iterations,
          step.newton->residual_history.empty() ? 0.0 : step.newton->residual_history.back());
      std::fflush(stdout);
    }
  };
  if (input.dynamics.enabled) {
    // Implicit dynamics: the same problem with inertia, one time step after the other.
    DynamicProblem dynamic(problem, mesh.dimension,
                           assemble_mass_matrix(solid, input.dynamics.mass == MassKind::lumped),
                           make_time_integrator(input.dynamics), input.gravity,
                           *initial_velocity(solid, mesh, input), input.dynamics.contact_treatment,
                           owned_node_bodies(solid, distributed, layout, *comm));
    LinearSolverSettings mass_settings;  // type: auto
    mass_settings.where = input.file + ": mass matrix";
    LinearSolver mass_solver(mass_settings, distributed ? distributed_mass_layout(*distributed)
                                                        : mass_matrix_layout(mesh));
    solve_time_steps(dynamic, linear, mass_solver, newton, stepping, write_step);
  } else {
    solve_load_steps(problem, linear, newton, stepping, write_step);
  }
  if (timers) {  // collective: after the solve, with the contact nodes it reached
    const std::string held = problem.describe_prescribed_holdings();
    if (root) std::printf("%s", held.c_str());
  }
  if (root) {
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const bool spread = input.output.parallel == OutputParallel::per_rank && comm->getSize() > 1;
    std::printf("grout: wrote %s%s and %s (%.2f s)\n", input.output.file.c_str(),
                spread ? (".<" + std::to_string(comm->getSize()) + " files>").c_str() : "",
                input.output.summary.c_str(), seconds);
  }
}

}  // namespace

int main(int argc, char** argv) {
  grout::keep_large_blocks_in_heap();
  grout::prefer_local_mpi_startup();  // a run without mpirun starts in 0.02 s, not 0.3 s
  Tpetra::ScopeGuard tpetra(&argc, &argv);
  grout::no_delay_on_local_launcher_sockets();  // MPI_Finalize under mpirun: 2.5 ms, not 45
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
  // Every error ends here, on every rank: the rank that found it prints it, once.
  try {
    agree_on_errors(*comm, [&] { run(input_path, output_dir, timers, comm); });
    if (timers) Teuchos::TimeMonitor::summarize(comm.ptr(), std::cout, false, true, false);
    return 0;
  } catch (const ErrorOnOtherRank& e) {
    return e.exit_code();
  } catch (...) {
    const std::exception_ptr error = std::current_exception();
    const int code = exit_code_of(error);
    if (code == 3) {  // a step did not converge: the message names the step, add the input
      std::fprintf(stderr, "grout: error: %s: %s (converged steps are in the output)\n",
                   input_path.c_str(), message_of(error).c_str());
    } else {
      std::fprintf(stderr, "grout: error: %s\n", message_of(error).c_str());
    }
    return code;
  }
}
