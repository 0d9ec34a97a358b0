// grout_mesh_probe: reads a mesh as the distributed mesh (default) or as the replicated mesh
// (--replicated: read on rank 0 and broadcast), and prints what each rank holds, the time of
// each step and each rank's peak resident memory. Exit code 2 for a bad mesh, on every rank.
// --solid then builds the small-strain solid on it (SolidProblem: maps, graph, one linear
// elastic material per block) and assembles f_int and K at u = 0, the memory a driver run
// needs before its first solve.
//
//   grout_mesh_probe mesh.exo [--replicated] [--solid] [--timers] [--contact <side set> ...]
//   [--contact-weight w] [--balance-contact] [--separate-contact [--master <side set> ...]]
// (--master: the contact pairs' master side sets, for the gap bands of the driver's default
// partition, DistributionOptions::master_side_sets)

#include <sys/resource.h>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <Tpetra_Core.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

#include "assembly/agree_on_errors.hpp"
#include "assembly/distribute_mesh.hpp"
#include "assembly/solid_problem.hpp"
#include "drivers/mpi_startup.hpp"
#include "io/errors.hpp"
#include "io/exodus.hpp"
#include "kernels/topology.hpp"
#include "parallel/distributed_mesh.hpp"

namespace {

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;  // KiB on Linux
}

// One linear elastic material per block of `mesh`.
grout::Input solid_input(const grout::Mesh& mesh) {
  grout::Input input;
  input.file = "grout_mesh_probe";
  input.model.dimension = mesh.dimension;
  for (const grout::ElementBlock& block : mesh.blocks) {
    grout::MaterialInput m;
    m.name = m.block = block.name;
    m.youngs_modulus = 1.0;
    m.poissons_ratio = 0.3;
    input.materials.push_back(m);
  }
  return input;
}

// Builds the solid, assembles f_int and K at u = 0, and says what each rank assembles.
std::string build_solid(const grout::SolidProblem& solid) {
  grout::Vector u(solid.owned_map()), f(solid.owned_map());
  const auto K = solid.create_matrix();
  solid.assemble(u, f, K.get());
  return grout::describe_solid_holdings(solid);
}

}  // namespace

int main(int argc, char** argv) {
  grout::prefer_local_mpi_startup();
  Tpetra::ScopeGuard tpetra(&argc, &argv);
  const auto comm = Tpetra::getDefaultComm();
  const bool root = comm->getRank() == 0;
  std::string path;
  bool replicated = false, timers = false, solid = false;
  grout::DistributionOptions options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--replicated") {
      replicated = true;
    } else if (arg == "--solid") {
      solid = true;
    } else if (arg == "--timers") {
      timers = true;
    } else if (arg == "--contact" && i + 1 < argc) {
      options.contact_side_sets.push_back(argv[++i]);
    } else if (arg == "--balance-contact") {
      options.balance_contact = true;
    } else if (arg == "--separate-contact") {
      options.separate_contact = true;
    } else if (arg == "--master" && i + 1 < argc) {
      options.master_side_sets.push_back(argv[++i]);
    } else if (arg == "--contact-weight" && i + 1 < argc) {
      options.contact_weight = std::atof(argv[++i]);
    } else if (path.empty() && arg.rfind("-", 0) != 0) {
      path = arg;
    } else {
      if (root)
        std::fprintf(stderr, "grout_mesh_probe: error: unexpected argument '%s'\n", argv[i]);
      return 2;
    }
  }
  if (path.empty()) {
    if (root)
      std::fprintf(
          stderr,
          "usage: grout_mesh_probe mesh.exo [--replicated] [--solid] [--contact <side set>]"
          " [--contact-weight w] [--balance-contact] [--separate-contact [--master <side "
          "set>]]\n");
    return 2;
  }
  try {
    const double start_rss = peak_rss_mb();
    comm->barrier();
    const auto t0 = std::chrono::steady_clock::now();
    std::string text;
    grout::agree_on_errors(*comm, [&] {
      if (replicated) {
        const grout::Mesh mesh = grout::read_and_broadcast_mesh(*comm, [&] {
          grout::Mesh m = grout::read_exodus(path);
          grout::check_mesh(m);
          return m;
        });
        if (root)
          text = "mesh on every rank: " + std::to_string(mesh.num_nodes()) + " nodes, " +
                 std::to_string(mesh.num_elements()) + " elements\n";
        if (solid) {
          const grout::Input input = solid_input(mesh);
          text += build_solid(grout::SolidProblem(mesh, input, comm));
        }
      } else {
        const grout::DistributedMesh mesh = grout::read_distributed_mesh(*comm, path, options);
        text = grout::describe_holdings(*comm, mesh);
        if (solid) {
          const grout::Input input = solid_input(mesh.local);
          text += build_solid(grout::SolidProblem(grout::mesh_part(mesh), input, comm));
        }
        // Contact balance per rank: faces of each contact side set on owned elements, faces
        // with an owned node (those the contact evaluates), owned nodes of the set, owned dofs
        // (nodes x dimension).
        for (const std::string& name : options.contact_side_sets) {
          const grout::SideSet* set = mesh.local.find_side_set(name);
          long long mine[4] = {0, 0, 0, mesh.num_owned_nodes * mesh.local.dimension};
          std::vector<grout::GlobalIndex> owned_nodes;
          for (std::size_t i = 0; set && i < set->elements.size(); ++i) {
            mine[0] += mesh.owns_element(set->elements[i]);
            const grout::GlobalIndex e = set->elements[i];
            const grout::ElementBlock& block = *mesh.local.block_of(e);
            int local[grout::max_side_nodes];
            const int n_face = grout::side_local_nodes(block.topology, set->sides[i], local);
            bool evaluated = false;
            for (int a = 0; a < n_face; ++a) {
              const grout::GlobalIndex n =
                  block
                      .connectivity[(e - block.first_element) * block.nodes_per_element + local[a]];
              if (mesh.owns_node(n)) evaluated = true, owned_nodes.push_back(n);
            }
            mine[1] += evaluated;
          }
          std::sort(owned_nodes.begin(), owned_nodes.end());
          mine[2] = std::unique(owned_nodes.begin(), owned_nodes.end()) - owned_nodes.begin();
          std::vector<long long> all(std::size_t(4 * comm->getSize()));
          Teuchos::gatherAll(*comm, 4, mine, int(all.size()), all.data());
          for (int r = 0; r < comm->getSize(); ++r)
            text += "balance rank " + std::to_string(r) + ": side set '" + name + "' faces " +
                    std::to_string(all[4 * r]) + " (" + std::to_string(all[4 * r + 1]) +
                    " with an owned node), nodes owned " + std::to_string(all[4 * r + 2]) +
                    ", owned dofs " + std::to_string(all[4 * r + 3]) + "\n";
        }
      }
    });
    comm->barrier();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double rss[2] = {start_rss, peak_rss_mb()};
    std::vector<double> all(std::size_t(2 * comm->getSize()));
    Teuchos::gatherAll(*comm, 2, rss, int(all.size()), all.data());
    if (root) {
      std::printf("%s", text.c_str());
      std::printf("%s read on %d rank(s): %.3f s\n", replicated ? "replicated" : "distributed",
                  comm->getSize(), seconds);
      for (int r = 0; r < comm->getSize(); ++r)
        std::printf("peak RSS rank %d: %.1f MB (%.1f MB before reading)\n", r, all[2 * r + 1],
                    all[2 * r]);
    }
    if (timers) Teuchos::TimeMonitor::summarize(comm.ptr(), std::cout, false, true, false);
    return 0;
  } catch (const grout::ErrorOnOtherRank& e) {
    return e.exit_code();
  } catch (...) {
    const std::exception_ptr error = std::current_exception();
    std::fprintf(stderr, "grout_mesh_probe: error: %s\n", grout::message_of(error).c_str());
    return grout::exit_code_of(error);
  }
}
