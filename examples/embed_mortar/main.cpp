// A host code's use of Grout's mortar terms (docs/embedding.md): two curved, non-matching
// contact surfaces built here, handed to grout::MortarCoupling as plain arrays, and three
// checks on what comes back:
//   1. Σ_j D_jj = the slave surface's measure (length in 2D, area in 3D);
//   2. the nodal gap g̃_j / D_jj of a master placed at a known normal offset δ equals δ up to
//      the chord error of the faceted surfaces;
//   3. the contact forces of a pressure field balance: Σ f¹ + Σ f² = 0;
//   4. with standard multipliers (D a full matrix), registered through Kokkos Views:
//      Σ_jk D_jk = the slave measure and Σ_l M_jl = Σ_k D_jk per row;
//   5. a master that covers part of the slave: every row whose D_jj ≤ 0 or whose nodal gap is
//      not δ is flagged by row_status() (not `full`), and the `full` rows give δ;
//   6. results live in the coupling's vectors: update() overwrites them, a copy keeps them;
//   7. the index accessors: ∂g̃_j/∂x²_l = n_j M_jl + Σ_l' (n_j · x²_l') ∂M_jl'/∂x²_l at a
//      master node l (g̃_j = −n_j·(D_jj x¹_j − Σ_l M_jl x²_l), n_j of the slave only), the
//      derivative columns decoded by dof(), the M entries and M-derivative rows by M_entry();
//   8. the forces summed to the owners of the nodes equal a one-rank coupling's;
//   9. Grout's contact law at the slave rows (grout/contact_law.hpp) against its formulas
//      (contact_law.cpp).
// 2D: slave arc of radius R (LINE2), master arc of radius R + δ. 3D: slave cylinder patch of
// radius R (QUAD4), master patch of radius R + δ (TRI3). Runs serially or on any number of
// ranks (each rank owns a slice of the faces of both surfaces). Exits 1 if a check fails.

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <grout/mortar_coupling.hpp>
#include <map>
#include <stdexcept>
#include <vector>

bool check_contact_law(int dim, MPI_Comm comm, double delta, const std::vector<long long>& ids,
                       const grout::MortarCoupling& coupling, const std::vector<double>& D_sum,
                       const std::vector<double>& g_sum);  // contact_law.cpp

// The installed API puts no Grout-internal header on the host's include path.
#if __has_include(<kernels/mortar_types.hpp>) || __has_include(<mortar_types.hpp>)
#error "Grout's internal headers are reachable from the host: Grout::mortar should not add them"
#endif

namespace {

constexpr double R = 1.0, delta = 0.01, t0 = 0.2, t1 = 1.2, length = 0.8, pad = 0.05;

/// One surface as the host holds it: global node ids and coordinates, faces by global id.
struct Surface {
  int nodes_per_face = 2;
  std::vector<long long> ids;
  std::vector<double> x;
  std::vector<long long> faces;
};

/// Nodes of a structured (n_t + 1) × (n_z + 1) grid on the cylinder of radius r over the angles
/// [a, b] and heights [z0, z1] (2D: one row, z ignored), ids from `first`.
void add_grid_nodes(Surface& s, int dim, int n_t, int n_z, double r, double a, double b, double z0,
                    double z1, long long first) {
  for (int j = 0; j <= (dim == 2 ? 0 : n_z); ++j)
    for (int i = 0; i <= n_t; ++i) {
      const double t = a + (b - a) * i / n_t;
      s.ids.push_back(first++);
      s.x.insert(s.x.end(), {r * std::cos(t), r * std::sin(t)});
      if (dim == 3) s.x.push_back(z0 + (z1 - z0) * j / n_z);
    }
}

/// Slave: n_t (× n_t in 3D) faces at radius R, normals outward (towards the master).
/// Master: m_t (× m_t) faces at radius R + δ over a wider patch, normals inward.
void build_surfaces(int dim, int n_t, int m_t, Surface& slave, Surface& master,
                    double master_from = t1 + pad, double master_to = t0 - pad) {
  slave.nodes_per_face = dim == 2 ? 2 : 4;
  master.nodes_per_face = dim == 2 ? 2 : 3;
  add_grid_nodes(slave, dim, n_t, n_t, R, t0, t1, 0.0, length, 0);
  const long long first_master = (long long)slave.ids.size();
  add_grid_nodes(master, dim, m_t, m_t, R + delta, master_from, master_to, -pad, length + pad,
                 first_master);
  if (dim == 2) {
    for (int i = 0; i < n_t; ++i) slave.faces.insert(slave.faces.end(), {i, i + 1});
    for (int i = 0; i < m_t; ++i)
      master.faces.insert(master.faces.end(), {first_master + i, first_master + i + 1});
    return;
  }
  for (int j = 0; j < n_t; ++j)
    for (int i = 0; i < n_t; ++i) {
      const long long a = j * (n_t + 1) + i;
      slave.faces.insert(slave.faces.end(), {a, a + 1, a + n_t + 2, a + n_t + 1});
    }
  // The master grid runs from large to small angles: its faces, in the slave's (a, b, c, d)
  // order cut in two triangles, have inward normals (towards the slave).
  for (int j = 0; j < m_t; ++j)
    for (int i = 0; i < m_t; ++i) {
      const long long a = first_master + j * (m_t + 1) + i, b = a + 1, c = a + m_t + 2,
                      d = a + m_t + 1;
      master.faces.insert(master.faces.end(), {a, b, d, b, c, d});
    }
}

/// This rank's slice of a surface's faces, as SurfaceArrays rows: the nodes of those faces
/// only (local rows), with their global ids.
struct RankArrays {
  std::vector<int> faces;
  std::vector<double> x;
  std::vector<long long> ids;
};
RankArrays my_part(const Surface& s, int dim, int rank, int size) {
  const std::size_t n = s.faces.size() / s.nodes_per_face;
  const std::size_t f0 = n * rank / size, f1 = n * (rank + 1) / size;
  RankArrays part;
  std::vector<int> row(s.ids.size(), -1);
  const long long first = s.ids.front();
  for (std::size_t f = f0; f < f1; ++f)
    for (int a = 0; a < s.nodes_per_face; ++a) {
      const std::size_t node = std::size_t(s.faces[f * s.nodes_per_face + a] - first);
      if (row[node] < 0) {
        row[node] = int(part.ids.size());
        part.ids.push_back(s.ids[node]);
        part.x.insert(part.x.end(), &s.x[node * dim], &s.x[node * dim] + dim);
      }
      part.faces.push_back(row[node]);
    }
  return part;
}

/// The chord error of a faceted arc of radius r with angular step h: r (1 − cos(h/2)).
double sagitta(double r, double h) {
  return r * (1.0 - std::cos(0.5 * h));
}

/// Per slave node id, the sum over the ranks of a per-row value (rows: coupling.slave_id).
std::vector<double> by_id(const grout::MortarCoupling& c, const std::vector<double>& v,
                          std::size_t n_ids, MPI_Comm comm) {
  std::vector<double> total(n_ids, 0.0);
  for (std::size_t r = 0; r < c.num_slave_nodes(); ++r) total[c.slave_id(r)] += v[r];
  MPI_Allreduce(MPI_IN_PLACE, total.data(), int(n_ids), MPI_DOUBLE, MPI_SUM, comm);
  return total;
}

bool all_ranks(bool ok, MPI_Comm comm) {
  int v = ok ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &v, 1, MPI_INT, MPI_MIN, comm);
  return v == 1;
}

/// Checks 5–8 (file comment).
bool check_contract(int dim, MPI_Comm comm, const RankArrays& s, const RankArrays& m,
                    const Surface& slave, const Surface& master, grout::MortarCoupling& coupling) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const int n_t = dim == 2 ? 24 : 8, m_t = dim == 2 ? 31 : 11;
  const double tol = sagitta(R, (t1 - t0) / n_t) + sagitta(R + delta, (t1 - t0 + 2 * pad) / m_t);

  // 5. A master over part of the slave's angles (its edge inside a slave face).
  Surface ps, pm;
  build_surfaces(dim, n_t, m_t, ps, pm, t1 + pad, t0 + 0.43 * (t1 - t0));
  const RankArrays qs = my_part(ps, dim, rank, size), qm = my_part(pm, dim, rank, size);
  const grout::MortarCoupling partial(
      dim, grout::surface_arrays(ps.nodes_per_face, qs.faces, qs.x, dim, qs.ids),
      grout::surface_arrays(pm.nodes_per_face, qm.faces, qm.x, dim, qm.ids), {}, comm);
  const std::size_t n_ids = ps.ids.size();
  const std::vector<double> D = by_id(partial, partial.D(), n_ids, comm),
                            g = by_id(partial, partial.weighted_gaps(), n_ids, comm);
  int flagged = 0, negative = 0, unflagged_bad = 0;
  for (std::size_t r = 0; r < partial.num_slave_nodes(); ++r) {
    const long long id = partial.slave_id(r);
    const bool full = partial.row_status()[r] == grout::RowStatus::full;
    const bool gap_is_delta = D[id] > 0.0 && std::abs(g[id] / D[id] - delta) <= tol;
    flagged += !full;
    negative += D[id] < 0.0;
    unflagged_bad += full && !gap_is_delta;
  }
  MPI_Allreduce(MPI_IN_PLACE, &flagged, 1, MPI_INT, MPI_SUM, comm);  // rows of all ranks
  MPI_Allreduce(MPI_IN_PLACE, &negative, 1, MPI_INT, MPI_SUM, comm);
  const bool partial_ok = all_ranks(unflagged_bad == 0, comm) && flagged > 0;

  // 6. Lifetime: the vectors returned belong to the coupling; update() overwrites them.
  const std::vector<double>& gaps = coupling.weighted_gaps();
  const std::vector<double> kept = gaps;  // the host's copy
  const double widen = (R + delta + 0.005) / (R + delta);
  std::vector<double> xm_out = m.x;
  for (double& v : xm_out) v *= widen;
  if (dim == 3)  // only the radius
    for (std::size_t i = 0; i < m.ids.size(); ++i) xm_out[i * 3 + 2] = m.x[i * 3 + 2];
  coupling.update(s.x, xm_out);
  bool lifetime_ok = &gaps == &coupling.weighted_gaps();
  for (std::size_t r = 0; r < gaps.size(); ++r) {
    const double D_r = coupling.D()[r];
    lifetime_ok = lifetime_ok && std::abs(gaps[r] - (delta + 0.005) * D_r) <= 2 * tol * D_r &&
                  std::abs(kept[r] - delta * D_r) <= 2 * tol * D_r;
  }
  coupling.update(s.x, m.x);
  lifetime_ok = all_ranks(lifetime_ok, comm);

  // 7. Index spaces: ∂g̃_j/∂x²_l,d = n_j,d M_jl (the normals depend on the slave only).
  grout::MortarCouplingOptions with_derivatives;
  with_derivatives.derivatives = true;
  const grout::MortarCoupling exact(
      dim, grout::surface_arrays(slave.nodes_per_face, s.faces, s.x, dim, s.ids),
      grout::surface_arrays(master.nodes_per_face, m.faces, m.x, dim, m.ids), with_derivatives,
      comm);
  std::map<std::pair<std::size_t, long long>, double> M;
  for (std::size_t k = 0; k < exact.M_values().size(); ++k) {
    const grout::MEntry e = exact.M_entry(k);
    M[{e.row, e.master_node}] = exact.M_values()[k];
  }
  const long long first_master = (long long)slave.ids.size();
  // Σ_l' (n_j · x²_l') ∂M_jl'/∂x²_l,d: the M derivatives' rows through M_entry, their columns
  // through dof.
  std::map<std::pair<std::size_t, long long>, double> through_M;
  for (const grout::DerivativeTriplet& t : exact.M_derivatives()) {
    if (exact.dof(t.column).node < first_master) continue;
    const grout::MEntry e = exact.M_entry(std::size_t(t.row));
    const double* x_l = &master.x[std::size_t(e.master_node - first_master) * dim];
    double n_x = 0.0;
    for (int d = 0; d < dim; ++d) n_x += exact.normals()[e.row * dim + d] * x_l[d];
    through_M[{e.row, t.column}] += n_x * t.value;
  }
  double worst_derivative = 0.0;
  int master_columns = 0;
  for (const grout::DerivativeTriplet& t : exact.gap_derivatives()) {
    const grout::Dof dof = exact.dof(t.column);
    if (dof.node < first_master) continue;
    ++master_columns;
    const auto it = M.find({std::size_t(t.row), dof.node});
    const auto jt = through_M.find({std::size_t(t.row), t.column});
    const double expected =
        (it == M.end() ? 0.0
                       : exact.normals()[std::size_t(t.row) * dim + dof.component] * it->second) +
        (jt == through_M.end() ? 0.0 : jt->second);
    worst_derivative = std::max(worst_derivative, std::abs(t.value - expected));
  }
  const bool index_ok = all_ranks(master_columns > 0 && worst_derivative <= 1e-14, comm);

  // 8. Forces summed to the owners against one rank's coupling of the whole surfaces.
  const RankArrays all_s = my_part(slave, dim, 0, 1), all_m = my_part(master, dim, 0, 1);
  const grout::MortarCoupling one(
      dim, grout::surface_arrays(slave.nodes_per_face, all_s.faces, all_s.x, dim, all_s.ids),
      grout::surface_arrays(master.nodes_per_face, all_m.faces, all_m.x, dim, all_m.ids), {},
      MPI_COMM_NULL);
  const auto lambda_of = [&](const std::vector<long long>& ids) {
    std::vector<double> lambda(ids.size() * dim);
    for (std::size_t r = 0; r < ids.size(); ++r)
      for (int d = 0; d < dim; ++d) lambda[r * dim + d] = 2.0 + std::sin(double(ids[r] + d));
    return lambda;
  };
  const grout::ContactForces owned =
      coupling.contact_forces(lambda_of(s.ids), grout::ForceSum::owners);
  const grout::ContactForces whole = one.contact_forces(lambda_of(all_s.ids));
  const std::size_t n_all = slave.ids.size() + master.ids.size();
  std::vector<double> total(n_all * dim, 0.0), reference(n_all * dim, 0.0);
  for (std::size_t r = 0; r < s.ids.size(); ++r)
    for (int d = 0; d < dim; ++d) total[s.ids[r] * dim + d] += owned.slave[r * dim + d];
  for (std::size_t l = 0; l < owned.master_nodes.size(); ++l)
    for (int d = 0; d < dim; ++d)
      total[owned.master_nodes[l] * dim + d] += owned.master[l * dim + d];
  MPI_Allreduce(MPI_IN_PLACE, total.data(), int(total.size()), MPI_DOUBLE, MPI_SUM, comm);
  for (std::size_t r = 0; r < all_s.ids.size(); ++r)
    for (int d = 0; d < dim; ++d) reference[all_s.ids[r] * dim + d] = whole.slave[r * dim + d];
  for (std::size_t l = 0; l < whole.master_nodes.size(); ++l)
    for (int d = 0; d < dim; ++d)
      reference[whole.master_nodes[l] * dim + d] = whole.master[l * dim + d];
  double worst_owner = 0.0;
  for (std::size_t i = 0; i < total.size(); ++i)
    worst_owner = std::max(worst_owner, std::abs(total[i] - reference[i]));
  const bool owners_ok = worst_owner <= 4e-13;

  if (rank == 0) {
    std::printf(
        "  partly covered master: %d rows (over the ranks) flagged, %d with D < 0, none unflagged "
        "with a "
        "wrong gap %s\n",
        flagged, negative, partial_ok ? "ok" : "FAILED");
    std::printf("  lifetime: update() overwrote the gaps, the host's copy kept them %s\n",
                lifetime_ok ? "ok" : "FAILED");
    std::printf(
        "  index accessors: %d master columns of dg, worst |dg - (n M + n.x dM)| = %.3g %s\n",
        master_columns, worst_derivative, index_ok ? "ok" : "FAILED");
    std::printf("  forces summed to owners: worst |f - f(1 rank)| = %.3g %s\n", worst_owner,
                owners_ok ? "ok" : "FAILED");
  }
  return partial_ok && lifetime_ok && index_ok && owners_ok;
}

int check(int dim, MPI_Comm comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const int n_t = dim == 2 ? 24 : 8, m_t = dim == 2 ? 31 : 11;
  Surface slave, master;
  build_surfaces(dim, n_t, m_t, slave, master);
  const RankArrays s = my_part(slave, dim, rank, size), m = my_part(master, dim, rank, size);

  // The calls: construct (checks the data, first update), update at each new configuration,
  // read back.
  grout::MortarCouplingOptions options;  // exact integration, dual multipliers
  grout::MortarCoupling coupling(
      dim, grout::surface_arrays(slave.nodes_per_face, s.faces, s.x, dim, s.ids),
      grout::surface_arrays(master.nodes_per_face, m.faces, m.x, dim, m.ids), options, comm);
  // (unchanged here; a host calls this after every motion). Host Views work as well as
  // vectors or pointers: here unmanaged Views over the host's own arrays, read in place.
  using HostMatrix = Kokkos::View<const double**, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>;
  const HostMatrix xs_view(s.x.data(), s.ids.size(), dim), xm_view(m.x.data(), m.ids.size(), dim);
  coupling.update(xs_view, xm_view);

  // D and g̃ are this rank's contributions: sum them over the ranks by node id (a host would
  // assemble them like its element vectors).
  const std::size_t n_slave_nodes = slave.ids.size();
  std::vector<double> D(n_slave_nodes, 0.0), g(n_slave_nodes, 0.0);
  for (std::size_t r = 0; r < s.ids.size(); ++r) {
    D[s.ids[r]] += coupling.D()[r];
    g[s.ids[r]] += coupling.weighted_gaps()[r];
  }
  MPI_Allreduce(MPI_IN_PLACE, D.data(), int(n_slave_nodes), MPI_DOUBLE, MPI_SUM, comm);
  MPI_Allreduce(MPI_IN_PLACE, g.data(), int(n_slave_nodes), MPI_DOUBLE, MPI_SUM, comm);

  // 1. Σ D = slave measure (the faceted surface's: chords × axial length).
  const double chord = 2.0 * R * std::sin(0.5 * (t1 - t0) / n_t);
  const double measure = n_t * chord * (dim == 3 ? length : 1.0);
  double sum_D = 0.0;
  for (double d : D) sum_D += d;
  const bool area_ok = std::abs(sum_D - measure) <= 1e-12 * measure;

  // 2. Nodal gap g̃_j / D_jj = δ within the chord errors of both surfaces.
  const double tol = sagitta(R, (t1 - t0) / n_t) + sagitta(R + delta, (t1 - t0 + 2 * pad) / m_t);
  double worst_gap = 0.0;
  for (std::size_t j = 0; j < n_slave_nodes; ++j)
    worst_gap = std::max(worst_gap, std::abs(g[j] / D[j] - delta));
  const bool gap_ok = worst_gap <= tol;

  // 3. Forces of a uniform pressure p (λ_j = p n_j, Grout's sign: λ_n > 0 in compression)
  // plus a tangential part: Σ f¹ + Σ f² = 0, summed over the ranks.
  const double p = 2.5;
  std::vector<double> lambda(s.ids.size() * dim);
  for (std::size_t r = 0; r < s.ids.size(); ++r)
    for (int d = 0; d < dim; ++d)
      lambda[r * dim + d] =
          p * coupling.normals()[r * dim + d] + 0.3 * coupling.tangents()[r * (dim - 1) * dim + d];
  const grout::ContactForces f = coupling.contact_forces(lambda);
  double total[3] = {0.0, 0.0, 0.0}, slave_total[3] = {0.0, 0.0, 0.0};
  for (std::size_t r = 0; r < s.ids.size(); ++r)
    for (int d = 0; d < dim; ++d) slave_total[d] += f.slave[r * dim + d];
  for (std::size_t l = 0; l < f.master_nodes.size(); ++l)
    for (int d = 0; d < dim; ++d) total[d] += f.master[l * dim + d];
  for (int d = 0; d < dim; ++d) total[d] += slave_total[d];
  MPI_Allreduce(MPI_IN_PLACE, total, 3, MPI_DOUBLE, MPI_SUM, comm);
  MPI_Allreduce(MPI_IN_PLACE, slave_total, 3, MPI_DOUBLE, MPI_SUM, comm);
  const double imbalance =
      std::sqrt(total[0] * total[0] + total[1] * total[1] + total[2] * total[2]);
  const double resultant =
      std::sqrt(slave_total[0] * slave_total[0] + slave_total[1] * slave_total[1] +
                slave_total[2] * slave_total[2]);
  const bool balance_ok = resultant > 0.0 && imbalance <= 1e-13 * p * measure;

  // 4. Standard multipliers, surfaces as Kokkos Views: D is a sparse slave × slave matrix.
  using HostFaces = Kokkos::View<const int**, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>;
  using HostIds = Kokkos::View<const long long*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>;
  grout::MortarCouplingOptions standard_options;
  standard_options.multipliers = grout::MultiplierBasis::standard;
  const grout::MortarCoupling standard(
      grout::SurfaceViews{
          HostFaces(s.faces.data(), s.faces.size() / slave.nodes_per_face, slave.nodes_per_face),
          xs_view, HostIds(s.ids.data(), s.ids.size())},
      grout::SurfaceViews{
          HostFaces(m.faces.data(), m.faces.size() / master.nodes_per_face, master.nodes_per_face),
          xm_view, HostIds(m.ids.data(), m.ids.size())},
      standard_options, comm);
  double sum_D_standard = 0.0, worst_row = 0.0;
  for (std::size_t r = 0; r < s.ids.size(); ++r) {
    double row_D = 0.0, row_M = 0.0;
    for (std::size_t k = standard.D_offsets()[r]; k < standard.D_offsets()[r + 1]; ++k)
      row_D += standard.D_values()[k];
    for (std::size_t k = standard.M_offsets()[r]; k < standard.M_offsets()[r + 1]; ++k)
      row_M += standard.M_values()[k];
    sum_D_standard += row_D;
    worst_row = std::max(worst_row, std::abs(row_D - row_M));
  }
  MPI_Allreduce(MPI_IN_PLACE, &sum_D_standard, 1, MPI_DOUBLE, MPI_SUM, comm);
  MPI_Allreduce(MPI_IN_PLACE, &worst_row, 1, MPI_DOUBLE, MPI_MAX, comm);
  const bool standard_ok =
      std::abs(sum_D_standard - measure) <= 1e-12 * measure && worst_row <= 1e-14;

  const bool contract_ok = check_contract(dim, comm, s, m, slave, master, coupling);

  if (rank == 0) {
    std::printf("embed_mortar %dD on %d rank%s: sum D = %.15g (slave %s %.15g) %s\n", dim, size,
                size > 1 ? "s" : "", sum_D, dim == 2 ? "length" : "area", measure,
                area_ok ? "ok" : "FAILED");
    std::printf("  gap of the offset %g: worst |g - delta| = %.3g (chord bound %.3g) %s\n", delta,
                worst_gap, tol, gap_ok ? "ok" : "FAILED");
    std::printf("  forces: |sum f_slave| = %.6g, |sum f_slave + sum f_master| = %.3g %s\n",
                resultant, imbalance, balance_ok ? "ok" : "FAILED");
    std::printf(
        "  standard multipliers (Views): sum D_jk = %.15g, worst |row D - row M| = %.3g %s\n",
        sum_D_standard, worst_row, standard_ok ? "ok" : "FAILED");
  }
  const bool law_ok = check_contact_law(dim, comm, delta, s.ids, coupling, D, g);
  return area_ok && gap_ok && balance_ok && standard_ok && contract_ok && law_ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int failed = 0;
  {
    Kokkos::ScopeGuard kokkos(argc, argv);  // the host initialises Kokkos (and MPI) itself
    try {
      failed = check(2, MPI_COMM_WORLD) + check(3, MPI_COMM_WORLD);
    } catch (const std::invalid_argument& e) {  // MortarCouplingError, ContactLawError
      std::fprintf(stderr, "embed_mortar: %s\n", e.what());
      failed = 1;
    }
  }
  MPI_Finalize();
  return failed ? 1 : 0;
}
