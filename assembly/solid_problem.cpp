#include "assembly/solid_problem.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>

#include <Teuchos_CommHelpers.hpp>

#include "assembly/crs_row_search.hpp"
#include "assembly/rank_holdings.hpp"
#include "io/errors.hpp"
#include "kernels/energy_momentum.hpp"
#include "kernels/surface_load.hpp"

namespace grout {

namespace {

const MaterialInput& material_of(const Input& input, const ElementBlock& block) {
  if (const MaterialInput* m = find_material(input, block)) return *m;
  throw InputError(input.file + ": grout/materials: no material for element block '" + block.name +
                   "'");
}

// A rank assembles the elements that touch one of its nodes (for its rows) and computes
// the stresses of its own elements, whose nodes may all belong to other ranks. One flag per
// element of part.local.
std::vector<char> assembled_elements(const MeshPart& part, int rank) {
  std::vector<char> assembled(std::size_t(part.local.num_elements()), 0);
  for (const auto& block : part.local.blocks) {
    const int npe = block.nodes_per_element;
    for (GlobalIndex i = 0; i < block.num_elements(); ++i) {
      const GlobalIndex e = block.first_element + i;
      const GlobalIndex* conn = &block.connectivity[i * npe];
      assembled[e] =
          part.element_owner[e] == rank ||
          std::any_of(conn, conn + npe, [&](GlobalIndex n) { return part.node_owner[n] == rank; });
    }
  }
  return assembled;
}

// The element's size: its largest node distance from node 0 (X: npe points of dim
// coordinates).
double element_size(int npe, int dim, const double* X) {
  double size2 = 0.0;
  for (int a = 1; a < npe; ++a) {
    double d2 = 0.0;
    for (int d = 0; d < dim; ++d) d2 += (X[a * dim + d] - X[d]) * (X[a * dim + d] - X[d]);
    size2 = std::max(size2, d2);
  }
  return std::sqrt(size2);
}

}  // namespace

SolidProblem::SolidProblem(const Mesh& mesh, const Input& input, Teuchos::RCP<const Comm> comm)
    : mesh_(mesh), input_(input), comm_(std::move(comm)), dim_(mesh.dimension) {
  // Contact slave faces' elements steer the cuts, so that the contact work is shared.
  std::vector<GlobalIndex> contact_elements;
  for (const ContactInput& c : input.contact)
    for (const std::string& name : contact_side_sets(c, false))
      if (const SideSet* set = mesh.find_side_set(name))
        contact_elements.insert(contact_elements.end(), set->elements.begin(), set->elements.end());
  const Partition partition = partition_mesh(mesh, comm_->getSize(), contact_elements);
  // The replicated mesh as a part: local numbers are global, for nodes and elements alike
  // (node_gid_ stays empty).
  std::vector<GlobalIndex> identity(std::size_t(std::max(mesh.num_nodes(), mesh.num_elements())));
  std::iota(identity.begin(), identity.end(), GlobalIndex(0));
  build(MeshPart{mesh, mesh.num_nodes(), mesh.num_elements(), identity, partition.node_part,
                 identity, partition.element_part});
}

SolidProblem::SolidProblem(const MeshPart& part, const Input& input, Teuchos::RCP<const Comm> comm)
    : mesh_(part.local),
      input_(input),
      comm_(std::move(comm)),
      dim_(part.local.dimension),
      node_gid_(part.node_gid) {
  build(part);
}

void SolidProblem::build(const MeshPart& part) {
  num_nodes_ = part.global_num_nodes;
  num_elements_ = part.global_num_elements;
  const std::vector<char> assembled = assembled_elements(part, comm_->getRank());
  build_maps(part, assembled);
  build_blocks(part, assembled);
  build_graph();
  build_loads();
  column_of_local_ = {};
  for (const auto& d : input_.dirichlet) dirichlet_.push_back(&d);
}

// Owned nodes: those the partition gives this rank, ascending global id. Column nodes: owned
// first (same order as the row map), then every other node of an assembled element, ascending.
void SolidProblem::build_maps(const MeshPart& part, const std::vector<char>& assembled) {
  const int rank = comm_->getRank();
  const Mesh& mesh = part.local;
  const std::size_t n_local = std::size_t(mesh.num_nodes());
  std::vector<std::pair<GlobalIndex, GlobalIndex>> owned, ghosts;  // (global, local)
  std::vector<char> is_column(n_local, 0);
  for (std::size_t n = 0; n < n_local; ++n) {
    if (part.node_owner[n] == rank) {
      owned.emplace_back(part.node_gid[n], GlobalIndex(n));
      is_column[n] = 1;
    }
  }
  for (const auto& block : mesh.blocks) {
    const int npe = block.nodes_per_element;
    for (GlobalIndex i = 0; i < block.num_elements(); ++i) {
      if (!assembled[block.first_element + i]) continue;
      for (int a = 0; a < npe; ++a) {
        const GlobalIndex n = block.connectivity[i * npe + a];
        if (!is_column[n]) {
          is_column[n] = 1;
          ghosts.emplace_back(part.node_gid[n], n);
        }
      }
    }
  }
  std::sort(owned.begin(), owned.end());
  std::sort(ghosts.begin(), ghosts.end());
  num_owned_nodes_ = int(owned.size());
  std::vector<std::pair<GlobalIndex, GlobalIndex>>& column_nodes = owned;  // owned, then ghosts
  column_nodes.insert(column_nodes.end(), ghosts.begin(), ghosts.end());
  column_of_local_.assign(n_local, -1);
  for (std::size_t k = 0; k < column_nodes.size(); ++k) {
    column_nodes_.push_back(column_nodes[k].first);
    column_of_local_[column_nodes[k].second] = int(k);
  }

  auto dofs_of = [&](std::size_t count) {
    std::vector<GO> dofs(count * dim_);
    for (std::size_t k = 0; k < count; ++k)
      for (int c = 0; c < dim_; ++c) dofs[k * dim_ + c] = column_nodes_[k] * dim_ + c;
    return dofs;
  };
  const auto owned_dofs = dofs_of(num_owned_nodes_);
  const auto column = dofs_of(column_nodes_.size());
  const GO n_global = num_nodes_ * dim_;
  owned_map_ = Teuchos::rcp(new Map(n_global, owned_dofs.data(), owned_dofs.size(), 0, comm_));
  column_map_ = Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                     column.data(), column.size(), 0, comm_));
  importer_ = Teuchos::rcp(new Import(owned_map_, column_map_));

  column_coordinates_ =
      Kokkos::View<double**>("grout::column_coordinates", column_nodes_.size(), dim_);
  for (std::size_t k = 0; k < column_nodes.size(); ++k)
    for (int d = 0; d < dim_; ++d)
      column_coordinates_(k, d) = mesh.coordinates[column_nodes[k].second * dim_ + d];
}

// Each block's assembled elements in ascending global id: the order in which every row sums
// them, whichever mesh they come from.
void SolidProblem::build_blocks(const MeshPart& part, const std::vector<char>& assembled) {
  const int rank = comm_->getRank();
  const bool plane_stress = input_.model.plane == PlaneKind::stress;
  for (const auto& block : part.local.blocks) {
    const MaterialInput& material = material_of(input_, block);
    const int npe = block.nodes_per_element;
    std::vector<std::pair<GlobalIndex, GlobalIndex>> local;  // (global, local) element
    for (GlobalIndex i = 0; i < block.num_elements(); ++i) {
      const GlobalIndex e = block.first_element + i;
      if (assembled[e]) local.emplace_back(part.element_gid[e], e);
    }
    std::sort(local.begin(), local.end());
    LocalBlock lb;
    lb.name = block.name;
    lb.topology = block.topology;
    lb.nodes_per_element = npe;
    lb.finite_strain = input_.model.strain == StrainKind::finite;
    lb.axisymmetric = dim_ == 2 && input_.model.plane == PlaneKind::axisymmetric;
    // Finite-strain plane stress: the 3D Lamé constants and a law that finds F33 from S33 = 0
    // (kernels/plane_stress_material.hpp); small strain: the plane-stress lambda* instead.
    lb.constants = elastic_constants(material.youngs_modulus, material.poissons_ratio, dim_,
                                     plane_stress && !lb.finite_strain);
    lb.poissons_ratio = material.poissons_ratio;
    lb.density = material.density;
    const bool neo_hookean = material.law == MaterialLaw::neo_hookean;
    if (dim_ == 2 && plane_stress)
      lb.law = neo_hookean ? HyperelasticLaw::neo_hookean_plane_stress
                           : HyperelasticLaw::saint_venant_kirchhoff_plane_stress;
    else
      lb.law = neo_hookean ? HyperelasticLaw::neo_hookean : HyperelasticLaw::saint_venant_kirchhoff;
    lb.nodes = Kokkos::View<int**>("grout::block_nodes", local.size(), npe);
    lb.global = Kokkos::View<GlobalIndex*>("grout::block_elements", local.size());
    lb.owned = Kokkos::View<bool*>("grout::block_owned", local.size());
    for (std::size_t i = 0; i < local.size(); ++i) {
      const auto [global, e] = local[i];
      const GlobalIndex* conn = &block.connectivity[(e - block.first_element) * npe];
      for (int a = 0; a < npe; ++a) lb.nodes(i, a) = column_of_local_[conn[a]];
      lb.global(i) = global;
      lb.owned(i) = part.element_owner[e] == rank;
    }
    blocks_.push_back(lb);
  }
}

// Row (owned node k, component c) couples with every column dof of every local element that
// contains node k. Built in local indices, rows sorted.
void SolidProblem::build_graph() {
  std::vector<std::vector<int>> node_neighbours(num_owned_nodes_);
  for (const auto& block : blocks_) {
    for (std::size_t e = 0; e < block.nodes.extent(0); ++e) {
      for (int a = 0; a < block.nodes_per_element; ++a) {
        const int k = block.nodes(e, a);
        if (k >= num_owned_nodes_) continue;
        for (int b = 0; b < block.nodes_per_element; ++b)
          node_neighbours[k].push_back(block.nodes(e, b));
      }
    }
  }
  const std::size_t n_rows = std::size_t(num_owned_nodes_) * dim_;
  Kokkos::View<std::size_t*> row_ptr("grout::graph_rows", n_rows + 1);
  for (int k = 0; k < num_owned_nodes_; ++k) {
    auto& nb = node_neighbours[k];
    if (nb.empty()) nb.push_back(k);  // a node of no element keeps its diagonal
    std::sort(nb.begin(), nb.end());
    nb.erase(std::unique(nb.begin(), nb.end()), nb.end());
    for (int c = 0; c < dim_; ++c) row_ptr(k * dim_ + c + 1) = nb.size() * dim_;
  }
  for (std::size_t i = 0; i < n_rows; ++i) row_ptr(i + 1) += row_ptr(i);
  Kokkos::View<LO*> entries("grout::graph_entries", row_ptr(n_rows));
  for (int k = 0; k < num_owned_nodes_; ++k) {
    for (int c = 0; c < dim_; ++c) {
      std::size_t p = row_ptr(k * dim_ + c);
      for (int m : node_neighbours[k])
        for (int d = 0; d < dim_; ++d) entries(p++) = m * dim_ + d;
    }
  }
  graph_ = Teuchos::rcp(new Graph(owned_map_, column_map_, row_ptr, entries));
  graph_->fillComplete(owned_map_, owned_map_);
}

void SolidProblem::build_loads() {
  for (std::size_t l = 0; l < input_.loads.size(); ++l) {
    const SideSet* set = mesh_.find_side_set(input_.loads[l].side_set);
    if (!set) {
      throw InputError(input_.file + ": grout/loads/" + input_.loads[l].name +
                       "/side_set: no side set '" + input_.loads[l].side_set + "' in mesh '" +
                       mesh_.file + "'");
    }
    for (std::size_t i = 0; i < set->elements.size(); ++i) {
      const GlobalIndex e = set->elements[i];
      const ElementBlock* block = mesh_.block_of(e);
      int local[max_side_nodes];
      const int n = side_local_nodes(block->topology, set->sides[i], local);
      LoadedFace face;
      face.topology = side_topology(block->topology);
      face.num_nodes = n;
      face.load = l;
      bool touches_owned = false;
      for (int a = 0; a < n; ++a) {
        const GlobalIndex node =
            block->connectivity[(e - block->first_element) * block->nodes_per_element + local[a]];
        face.nodes[a] = column_of_local_[node];
        touches_owned |= face.nodes[a] >= 0 && face.nodes[a] < num_owned_nodes_;
      }
      if (touches_owned) faces_.push_back(face);
    }
  }
}

Teuchos::RCP<Matrix> SolidProblem::create_matrix() const {
  return Teuchos::rcp(new Matrix(graph_));
}

Teuchos::RCP<Vector> SolidProblem::create_vector() const {
  return Teuchos::rcp(new Vector(owned_map_));
}

void SolidProblem::import_to_column(const Vector& u, Vector& u_column) const {
  u_column.doImport(u, *importer_, Tpetra::INSERT);
}

bool SolidProblem::assemble(const Vector& u, Vector& f_int, Matrix* K,
                            const Vector* u_start) const {
  Vector u_column(column_map_);
  u_column.doImport(u, *importer_, Tpetra::INSERT);
  const auto u_view =
      Kokkos::subview(u_column.getLocalViewHost(Tpetra::Access::ReadOnly), Kokkos::ALL(), 0);
  const bool energy_momentum = u_start != nullptr;
  Teuchos::RCP<Vector> u_start_column;  // only for energy_momentum
  if (energy_momentum) {
    u_start_column = Teuchos::rcp(new Vector(column_map_));
    u_start_column->doImport(*u_start, *importer_, Tpetra::INSERT);
  }
  const auto u_start_view =
      energy_momentum ? Kokkos::subview(u_start_column->getLocalViewHost(Tpetra::Access::ReadOnly),
                                        Kokkos::ALL(), 0)
                      : u_view;
  f_int.putScalar(0.0);
  auto f_view =
      Kokkos::subview(f_int.getLocalViewHost(Tpetra::Access::ReadWrite), Kokkos::ALL(), 0);
  if (K) {
    K->resumeFill();
    K->setAllToScalar(0.0);
  }
  const auto local_matrix = K ? K->getLocalMatrixHost() : Matrix::local_matrix_host_type();
  const auto row_map = local_matrix.graph.row_map;
  const auto entries = local_matrix.graph.entries;
  const auto values = local_matrix.values;
  const bool with_tangent = K != nullptr;
  const int dim = dim_;
  const int n_owned = num_owned_nodes_;
  const auto X_all = column_coordinates_;
  bool any_collapsed = false;
  round_off2_ = 0.0;

  for (const auto& block : blocks_) {
    const auto nodes = block.nodes;
    const auto global = block.global;
    const Topology topology = block.topology;
    const int npe = block.nodes_per_element;
    const ElasticConstants constants = block.constants;
    const bool finite_strain = block.finite_strain;
    const bool axisymmetric = block.axisymmetric;
    const HyperelasticLaw law = block.law;
    GlobalIndex first_inverted = std::numeric_limits<GlobalIndex>::max();
    const Kokkos::View<int, Kokkos::HostSpace> collapsed("grout::collapsed_elements");
    const Kokkos::View<double, Kokkos::HostSpace> round_off2("grout::solid_round_off");
    Kokkos::parallel_reduce(
        "grout::assemble_solid",
        Kokkos::RangePolicy<Kokkos::DefaultHostExecutionSpace>(0, nodes.extent(0)),
        KOKKOS_LAMBDA(const int e, GlobalIndex& bad) {
          double X[max_element_dofs], ue[max_element_dofs], fe[max_element_dofs];
          double ue_start[max_element_dofs];
          double Ke[max_element_dofs * max_element_dofs];
          const int n = npe * dim;
          for (int a = 0; a < npe; ++a) {
            for (int d = 0; d < dim; ++d) {
              const int k = nodes(e, a);
              X[a * dim + d] = X_all(k, d);
              ue[a * dim + d] = u_view(k * dim + d);
              ue_start[a * dim + d] = energy_momentum ? u_start_view(k * dim + d) : 0.0;
            }
          }
          double* const Ke_or_null = with_tangent ? Ke : nullptr;
          // Axisymmetric models have no dynamics (io/input.cpp), so no energy-momentum path.
          const ElementStatus status =
              !finite_strain && axisymmetric
                  ? axisymmetric_elastic_element<double>(topology, X, ue, constants, fe, Ke_or_null)
              : !finite_strain
                  ? linear_elastic_element<double>(topology, dim, X, ue, constants, fe, Ke_or_null)
              : energy_momentum
                  ? energy_momentum_force_and_tangent(topology, dim, X, ue_start, ue, law,
                                                      constants, fe, Ke_or_null)
                  : total_lagrangian_force_and_tangent(topology, dim, X, ue, law, constants, fe,
                                                       Ke_or_null, axisymmetric);
          if (status == ElementStatus::collapsed) {
            Kokkos::atomic_increment(&collapsed());
            return;
          }
          if (status != ElementStatus::ok) {
            bad = global(e) < bad ? global(e) : bad;
            return;
          }
          // Scatter. The dim rows of a node share one column pattern (build_graph: node
          // columns m*dim .. m*dim+dim-1, sorted by m), so the offset of each element node in
          // the node's first row is found once (binary search) and reused for its dim rows.
          // Each entry still receives one addition per element, in element order: the sums
          // are those of sumIntoValues, bit for bit.
          const double h_e = finite_strain && with_tangent ? element_size(npe, dim, X) : 0.0;
          for (int a = 0; a < npe; ++a) {
            const int k = nodes(e, a);
            if (k >= n_owned) continue;
            for (int d = 0; d < dim; ++d) Kokkos::atomic_add(&f_view(k * dim + d), fe[a * dim + d]);
            if (!with_tangent) continue;
            if (finite_strain) {
              // Round-off of f_int under finite strain (residual_floor): F = I + grad u is
              // known to eps |grad u| and, through its identity part, to eps absolutely, as is
              // C = F^T F near I; a strain error eps is that of a displacement error eps h_e
              // (h_e the element's size). So each row is known to
              // eps sum_k |K_rk| (|u_k| + h_e). Without h_e a stiff body at rest (the steel
              // ring of inputs/ring_pendulum, E = 2.069e11, under gravity) stalled at
              // |F| = 2e-5 far above the estimate, and every step failed.
              for (int d = 0; d < dim; ++d) {
                double row = 0.0;
                for (int m = 0; m < n; ++m)
                  row += std::abs(Ke[(a * dim + d) * n + m]) * (std::abs(ue[m]) + h_e);
                row *= std::numeric_limits<double>::epsilon();
                Kokkos::atomic_add(&round_off2(), row * row);
              }
            }
            const auto first = row_map(k * dim);
            int offset[max_element_nodes];
            for (int b = 0; b < npe; ++b) {
              const int column = nodes(e, b) * dim;
              offset[b] =
                  int(lower_bound_in_row(entries, first, row_map(k * dim + 1), column) - first);
            }
            for (int d = 0; d < dim; ++d) {
              const double* Ke_row = &Ke[(a * dim + d) * n];
              const auto row_start = row_map(k * dim + d);
              for (int b = 0; b < npe; ++b)
                for (int c = 0; c < dim; ++c)
                  Kokkos::atomic_add(&values(row_start + offset[b] + c), Ke_row[b * dim + c]);
            }
          }
        },
        Kokkos::Min<GlobalIndex>(first_inverted));
    if (first_inverted != std::numeric_limits<GlobalIndex>::max()) {
      throw InputError("mesh '" + mesh_.file + "': element " + std::to_string(first_inverted + 1) +
                       " of block '" + block.name + "' is inverted (det J <= 0)");
    }
    any_collapsed |= collapsed() > 0;
    round_off2_ += round_off2();
  }
  if (K) K->fillComplete(owned_map_, owned_map_);
  return !any_collapsed;
}

bool SolidProblem::tangent_is_constant() const {
  for (const auto& block : blocks_)
    if (block.finite_strain) return false;
  return true;
}

double SolidProblem::round_off_estimate() const {
  double sum = 0.0;
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, round_off2_, Teuchos::outArg(sum));
  return std::sqrt(sum);
}

double SolidProblem::stored_energy(const Vector& u) const {
  Vector u_column(column_map_);
  u_column.doImport(u, *importer_, Tpetra::INSERT);
  const auto u_view =
      Kokkos::subview(u_column.getLocalViewHost(Tpetra::Access::ReadOnly), Kokkos::ALL(), 0);
  double local = 0.0;
  for (const auto& block : blocks_) {
    for (std::size_t e = 0; e < block.nodes.extent(0); ++e) {
      if (!block.owned(e)) continue;
      double X[max_element_dofs], ue[max_element_dofs], fe[max_element_dofs];
      const int n = block.nodes_per_element * dim_;
      for (int a = 0; a < block.nodes_per_element; ++a) {
        for (int d = 0; d < dim_; ++d) {
          X[a * dim_ + d] = column_coordinates_(block.nodes(e, a), d);
          ue[a * dim_ + d] = u_view(block.nodes(e, a) * dim_ + d);
        }
      }
      if (block.finite_strain) {
        // W of a state assemble() accepted: no collapsed element (the status is then ok).
        double W = 0.0;
        if (total_lagrangian_element<double>(block.topology, dim_, X, ue, block.law,
                                             block.constants, fe, &W,
                                             block.axisymmetric) == ElementStatus::ok)
          local += W;
      } else {
        if (block.axisymmetric)
          axisymmetric_elastic_element<double>(block.topology, X, ue, block.constants, fe, nullptr);
        else
          linear_elastic_element<double>(block.topology, dim_, X, ue, block.constants, fe, nullptr);
        double W = 0.0;
        for (int k = 0; k < n; ++k) W += ue[k] * fe[k];
        local += 0.5 * W;
      }
    }
  }
  double sum = 0.0;
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, local, Teuchos::outArg(sum));
  return sum;
}

void SolidProblem::external_force(double t, Vector& f_ext) const {
  const bool axisymmetric = dim_ == 2 && input_.model.plane == PlaneKind::axisymmetric;
  f_ext.putScalar(0.0);
  auto f = Kokkos::subview(f_ext.getLocalViewHost(Tpetra::Access::ReadWrite), Kokkos::ALL(), 0);
  for (const auto& face : faces_) {
    const LoadInput& load = input_.loads[face.load];
    double X[max_side_nodes * 3] = {}, p[max_side_nodes] = {}, tr[max_side_nodes * 3] = {};
    double fe[max_side_nodes * 3] = {};
    for (int a = 0; a < face.num_nodes; ++a) {
      double x[3] = {0.0, 0.0, 0.0};
      for (int d = 0; d < dim_; ++d) x[d] = X[a * dim_ + d] = column_coordinates_(face.nodes[a], d);
      if (load.type == LoadKind::pressure) {
        p[a] = load.value(t, x[0], x[1], x[2]);
      } else {
        for (int d = 0; d < dim_; ++d) tr[a * dim_ + d] = load.components[d](t, x[0], x[1], x[2]);
      }
    }
    const bool pressure = load.type == LoadKind::pressure;
    surface_load(face.topology, dim_, X, pressure ? p : nullptr, pressure ? nullptr : tr, fe,
                 axisymmetric);
    for (int a = 0; a < face.num_nodes; ++a) {
      if (face.nodes[a] >= num_owned_nodes_) continue;
      for (int d = 0; d < dim_; ++d) f(face.nodes[a] * dim_ + d) += fe[a * dim_ + d];
    }
  }
}

std::vector<double> SolidProblem::prescribed_displacements(double t) const {
  std::vector<double> value(column_map_->getNodeNumElements(),
                            std::numeric_limits<double>::quiet_NaN());
  const LO invalid = Teuchos::OrdinalTraits<LO>::invalid();
  for (const DirichletInput* bc : dirichlet_) {
    const NodeSet* set = mesh_.find_node_set(bc->node_set);
    if (!set) {
      throw InputError(input_.file + ": grout/dirichlet/" + bc->name + "/node_set: no node set '" +
                       bc->node_set + "' in mesh '" + mesh_.file + "'");
    }
    for (GlobalIndex n : set->nodes) {  // nodes of mesh_
      double x[3] = {0.0, 0.0, 0.0};
      for (int d = 0; d < dim_; ++d) x[d] = mesh_.coordinates[n * dim_ + d];
      const GlobalIndex global = node_gid_.empty() ? n : node_gid_[n];
      const LO k = column_map_->getLocalElement(GO(global) * dim_ + bc->component);
      if (k == invalid) continue;  // a node of no local element (replicated mesh: another rank's)
      value[std::size_t(k)] = bc->value(t, x[0], x[1], x[2]);
    }
  }
  return value;
}

std::vector<GlobalIndex> SolidProblem::owned_elements() const {
  std::vector<GlobalIndex> out;
  for (const auto& block : blocks_)
    for (std::size_t e = 0; e < block.nodes.extent(0); ++e)
      if (block.owned(e)) out.push_back(block.global(e));
  return out;
}

std::vector<std::vector<double>> SolidProblem::element_stresses(const Vector& u) const {
  Vector u_column(column_map_);
  u_column.doImport(u, *importer_, Tpetra::INSERT);
  const auto u_view =
      Kokkos::subview(u_column.getLocalViewHost(Tpetra::Access::ReadOnly), Kokkos::ALL(), 0);
  const bool plane_strain = input_.model.plane == PlaneKind::strain;
  // Kernel Voigt order (linear_elastic_stress) -> output order (stress_names):
  // 2D (xx, yy, xy, zz) -> (xx, yy, zz, xy); 3D is the same order, σ_xz = σ_zx.
  const int n_components = dim_ == 2 ? 4 : 6;
  const int output_index_2d[4] = {0, 1, 3, 2};
  std::vector<std::vector<double>> stress(n_components);
  for (const auto& block : blocks_) {
    for (std::size_t e = 0; e < block.nodes.extent(0); ++e) {
      if (!block.owned(e)) continue;
      double X[max_element_dofs], ue[max_element_dofs], s[6];
      for (int a = 0; a < block.nodes_per_element; ++a) {
        for (int d = 0; d < dim_; ++d) {
          X[a * dim_ + d] = column_coordinates_(block.nodes(e, a), d);
          ue[a * dim_ + d] = u_view(block.nodes(e, a) * dim_ + d);
        }
      }
      if (block.finite_strain) {
        // Elements collapsed at a converged state cannot occur (assemble refuses them).
        total_lagrangian_cauchy_stress(block.topology, dim_, X, ue, block.law, block.constants, s,
                                       block.axisymmetric);
      } else if (block.axisymmetric) {
        axisymmetric_elastic_stress(block.topology, X, ue, block.constants, s);  // zz: hoop
      } else {
        linear_elastic_stress(block.topology, dim_, X, ue, block.constants, plane_strain,
                              block.poissons_ratio, s);
      }
      for (int c = 0; c < n_components; ++c)
        stress[dim_ == 2 ? output_index_2d[c] : c].push_back(s[c]);
    }
  }
  return stress;
}

std::vector<std::string> SolidProblem::stress_names() const {
  if (dim_ == 2) return {"stress_xx", "stress_yy", "stress_zz", "stress_xy"};
  return {"stress_xx", "stress_yy", "stress_zz", "stress_xy", "stress_yz", "stress_zx"};
}

std::string describe_solid_holdings(const SolidProblem& solid) {
  RankHoldings mine;
  mine.owned_nodes = solid.num_owned_nodes();
  mine.ghost_nodes = (long long)solid.column_coordinates().extent(0) - mine.owned_nodes;
  for (const auto& block : solid.local_blocks())
    for (std::size_t e = 0; e < block.owned.extent(0); ++e)
      ++(block.owned(e) ? mine.owned_elements : mine.ghost_elements);
  return describe_rank_holdings(*solid.comm(), "solid", mine, solid.num_global_nodes(),
                                solid.num_global_elements());
}

}  // namespace grout
