#include "nonlinear/elasticity_preconditioner.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "kernels/free_rigid_modes.hpp"

namespace grout {

namespace {

// Where global node `node` is in `coordinates`: its id itself without `nodes` (every node
// given), else its place in `*nodes` (ascending); -1 when it is not given.
long long node_index(GO node, std::size_t num_given, const std::vector<GO>* nodes) {
  if (!nodes) return node >= 0 && std::size_t(node) < num_given ? node : -1;
  const auto at = std::lower_bound(nodes->begin(), nodes->end(), node);
  return at != nodes->end() && *at == node ? at - nodes->begin() : -1;
}

}  // namespace

Teuchos::RCP<MultiVector> rigid_body_modes(const Map& map, int dim,
                                           const std::vector<double>& coordinates,
                                           const std::vector<GO>* nodes, bool translations_only) {
  const std::size_t num_nodes = coordinates.size() / std::size_t(dim);
  // Centroid of all nodes: rotations about it keep the modes well scaled. With `nodes` each
  // rank sums its own and the sums are added over the ranks.
  double centre[3] = {0.0, 0.0, 0.0};
  for (std::size_t n = 0; n < num_nodes; ++n)
    for (int d = 0; d < dim; ++d) centre[d] += coordinates[n * dim + d];
  double count = double(num_nodes);
  if (nodes) {
    double local[4] = {centre[0], centre[1], centre[2], count}, global[4];
    Teuchos::reduceAll(*map.getComm(), Teuchos::REDUCE_SUM, 4, local, global);
    for (int d = 0; d < 3; ++d) centre[d] = global[d];
    count = global[3];
  }
  for (int d = 0; d < dim; ++d) centre[d] /= count > 0.0 ? count : 1.0;

  // Translations only: every prolongator row has half the columns (3D), so MueLu's products
  // A·P and Pᵀ(AP) cost about a half and a quarter (docs/performance.md, "Two ranks against
  // one in 3D"); bending converges more slowly without the rotations.
  const int num_modes = translations_only ? dim : rigid_mode_count(dim);
  auto modes = Teuchos::rcp(new MultiVector(Teuchos::rcpFromRef(map), num_modes));
  auto v = modes->getLocalViewHost(Tpetra::Access::OverwriteAll);
  for (LO i = 0; i < LO(map.getNodeNumElements()); ++i) {
    const GO g = map.getGlobalElement(i);
    const long long node = node_index(g / dim, num_nodes, nodes);
    const int c = int(g % dim);
    if (node < 0)
      throw std::invalid_argument("rigid_body_modes: dof " + std::to_string(g) +
                                  " is not a displacement dof of the nodes given");
    // Translations e_c, then the rotations e_k × (x − centre) (kernels/free_rigid_modes.hpp).
    for (int k = 0; k < num_modes; ++k) {
      double r[3];
      rigid_mode_value(dim, k, &coordinates[std::size_t(node) * dim], centre, 1.0, r);
      v(i, k) = r[c];
    }
  }
  return modes;
}

bool is_nodal_displacement_map(const Map& map, int dim, long long num_nodes) {
  int ok = 1;
  const LO n = LO(map.getNodeNumElements());
  if (n % dim != 0) ok = 0;
  for (LO i = 0; i < n && ok; ++i) {
    const GO g = map.getGlobalElement(i);
    if (g < 0 || g >= GO(num_nodes) * dim || int(g % dim) != int(i % dim)) ok = 0;
    if (i % dim != 0 && g != map.getGlobalElement(i - 1) + 1) ok = 0;
  }
  int all_ok = 0;
  Teuchos::reduceAll(*map.getComm(), Teuchos::REDUCE_MIN, ok, Teuchos::outArg(all_ok));
  return all_ok == 1;
}

Teuchos::RCP<MultiVector> node_coordinates(const Map& map, int dim,
                                           const std::vector<double>& coordinates,
                                           const std::vector<int>& bodies,
                                           const std::vector<GO>* nodes) {
  // Bounding-box diagonal of all nodes: the bodies' spacing is 1000 times it. With `nodes`
  // the union of the ranks' boxes (a rank without nodes: an empty box, +inf and -inf).
  double spacing = 0.0;
  const bool distributed = nodes != nullptr;
  if ((!bodies.empty() && !coordinates.empty()) || distributed) {
    double lo[3], hi[3];  // hi as -max for one reduction
    for (int d = 0; d < dim; ++d) {
      lo[d] = coordinates.empty() ? INFINITY : coordinates[d];
      hi[d] = coordinates.empty() ? INFINITY : -coordinates[d];
      for (std::size_t i = d; i < coordinates.size(); i += dim)
        lo[d] = std::min(lo[d], coordinates[i]), hi[d] = std::min(hi[d], -coordinates[i]);
    }
    if (distributed) {
      double local[6], global[6];
      for (int d = 0; d < dim; ++d) local[d] = lo[d], local[dim + d] = hi[d];
      Teuchos::reduceAll(*map.getComm(), Teuchos::REDUCE_MIN, 2 * dim, local, global);
      for (int d = 0; d < dim; ++d) lo[d] = global[d], hi[d] = global[dim + d];
    }
    for (int d = 0; d < dim; ++d) spacing += (-hi[d] - lo[d]) * (-hi[d] - lo[d]);
    spacing = 1000.0 * std::max(std::sqrt(spacing), 1e-300);
  }
  std::vector<GO> row_nodes;
  for (LO i = 0; i < LO(map.getNodeNumElements()); i += dim)
    row_nodes.push_back(map.getGlobalElement(i) / dim);
  const auto node_map =
      Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                           row_nodes.data(), row_nodes.size(), 0, map.getComm()));
  auto X = Teuchos::rcp(new MultiVector(node_map, dim));
  auto v = X->getLocalViewHost(Tpetra::Access::OverwriteAll);
  const std::size_t num_given = coordinates.size() / std::size_t(dim);
  for (std::size_t n = 0; n < row_nodes.size(); ++n) {
    const long long at = node_index(row_nodes[n], num_given, nodes);
    if (at < 0)
      throw std::invalid_argument("node_coordinates: node " + std::to_string(row_nodes[n]) +
                                  " is not among the nodes given");
    for (int d = 0; d < dim; ++d) v(n, d) = coordinates[std::size_t(at) * dim + d];
    if (!bodies.empty()) v(n, 0) += spacing * bodies[std::size_t(at)];
  }
  return X;
}

bool set_elasticity_defaults(Teuchos::ParameterList& muelu, int dim, int num_ranks,
                             const Teuchos::RCP<MultiVector>& null_space,
                             const Teuchos::RCP<MultiVector>& node_coordinates,
                             bool separate_bodies, bool multipliers) {
  const auto set_default = [&](const std::string& key, const auto& value) {
    if (!muelu.isParameter(key)) muelu.set(key, value);
  };
  set_default("verbosity", std::string("none"));
  set_default("number of equations", dim);
  set_default("multigrid algorithm", std::string("sa"));
  set_default("aggregation: type", std::string("uncoupled"));
  set_default("transpose: use implicit", true);
  const bool smoother_given =
      muelu.isParameter("smoother: type") || muelu.isParameter("smoother: pre type") ||
      muelu.isParameter("smoother: post type") || muelu.isSublist("smoother: pre params") ||
      muelu.isSublist("smoother: post params");
  bool gauss_seidel_default = false;
  if (!smoother_given) {  // rank-local (elasticity_preconditioner.hpp)
    if (multipliers) {
      muelu.set("smoother: type", std::string("RILUK"));  // ILU(0)
    } else if (!muelu.isSublist("smoother: params")) {
      // Forward Gauss-Seidel before the coarse correction, backward after: the post-smoother
      // is the pre-smoother's adjoint, so the V-cycle stays symmetric for CG, at half the
      // sweeps of symmetric Gauss-Seidel on both sides.
      const auto gauss_seidel = [&](const char* when, bool backward) {
        muelu.set(std::string("smoother: ") + when + " type", std::string("RELAXATION"));
        Teuchos::ParameterList& relaxation =
            muelu.sublist(std::string("smoother: ") + when + " params");
        relaxation.set("relaxation: type", std::string("Gauss-Seidel"));
        relaxation.set("relaxation: sweeps", 1);
        relaxation.set("relaxation: backward mode", backward);
      };
      gauss_seidel("pre", false);
      gauss_seidel("post", true);
      gauss_seidel_default = true;
    }
  }
  // MueLu's default is 2000 rows. 500: the coarse KLU2 solve stays negligible, a system of
  // 500-2000 unknowns on several ranks gets a coarse level (with 2000 it was smoothed only,
  // 71 iterations on 2 ranks against 1 on one rank in 3D), and the stacked study's meshes
  // all get multilevel hierarchies (docs/performance.md, "Iterative solver").
  set_default("coarse: max size", 500);
  // A coarse operator R A P with an empty row (an aggregate whose prolongator columns are
  // zero: seen on level 1 of the 5.7 k-node gmsh hemispheres cut with the contact elements
  // apart, 6 rows on rank 0) gets 1 on its diagonal. Without it the row's unknowns are missing
  // from the column map that Tpetra builds from the entries, while Gauss-Seidel
  // (CrsMatrix::gaussSeidelCopy) takes the column map to start with the domain map's owned
  // entries: a shorter column map threw on one rank (the other waited in the V-cycle's
  // export), and a longer one would misalign the smoother's values without a word. The check
  // is one pass over the diagonal per level.
  set_default("rap: fix zero diagonals", true);
  const int coarse_max_size = muelu.get<int>("coarse: max size");
  if (num_ranks > 1 && !muelu.isParameter("coarse: type") &&
      !muelu.isParameter("repartition: enable") && !node_coordinates.is_null() &&
      null_space->getGlobalLength() > std::size_t(coarse_max_size)) {
    // Never KLU2 on a multi-rank communicator: the coarse levels move to fewer ranks (a
    // subcommunicator), the coarsest to one, where it is factored by KLU2 as on one rank.
    muelu.set("repartition: enable", true);
    muelu.set("repartition: partitioner", std::string("zoltan2"));
    muelu.set("repartition: start level", 1);
    // A level moves when a rank would hold fewer rows, onto ⌊rows / this⌋ ranks (at least
    // one): the coarsest (at most `coarse: max size` rows) always onto one, where KLU2 is
    // exact; a level of 4000 rows or more stays spread (the first coarse level has 1/13 of
    // the rows and a quarter of the nonzeros: on one rank the others waited).
    set_default("repartition: min rows per proc", std::max(2000, coarse_max_size + 1));
    muelu.set("repartition: max imbalance", 1.2);
    muelu.set("repartition: use subcommunicators", true);
    muelu.sublist("repartition: params").set("algorithm", std::string("multijagged"));
    muelu.set("coarse: type", std::string("KLU2"));  // on the one-rank subcommunicator
  }
  if (separate_bodies && !node_coordinates.is_null() &&
      !muelu.isParameter("aggregation: drop scheme")) {
    // Links between bodies have weight 1/S² in the distance Laplacian and are dropped
    // (elasticity_preconditioner.hpp).
    muelu.set("aggregation: drop scheme", std::string("distance laplacian"));
    set_default("aggregation: drop tol", 1e-4);
    // The prolongator is smoothed with the whole matrix: the matrix filtered by the dropping,
    // with the dropped entries lumped onto the diagonal, has a zero diagonal in a condensed
    // gap row (D_jj − Σ_l M_jl = 0).
    set_default("sa: use filtered matrix", false);
    // Jacobi smoothing of the prolongator, P = (I − ω D⁻¹A) P_tent with ω = 4/3 / λ_max(D⁻¹A),
    // takes D = the absolute row sums Σ_j |A_ij| instead of A_ii: Gershgorin bounds
    // λ_max(D⁻¹A) by 1 whatever the rows. The condensed system has rows whose diagonal is
    // ~1e-6 of their row sum: the slot of a prescribed slave dof (a node on a symmetry plane),
    // which holds a multiplier row (nonlinear/condensed_solve.hpp, kind C). With D = A_ii such a
    // row spreads ω/A_ii times its large entries into P, and GMRES stopped on a loss of accuracy
    // even with an exact coarse solve (inputs/sphere_sphere/README.md, "The iterative path").
    set_default("sa: use rowsumabs diagonal scaling", true);
  }
  if (!node_coordinates.is_null() && !muelu.sublist("user data").isParameter("Coordinates"))
    muelu.sublist("user data").set("Coordinates", node_coordinates);
  if (!null_space.is_null() && !muelu.sublist("user data").isParameter("Nullspace"))
    muelu.sublist("user data").set("Nullspace", null_space);
  return gauss_seidel_default;
}

}  // namespace grout
