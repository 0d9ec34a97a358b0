#include "assembly/contact_mortar.hpp"

#include <algorithm>
#include <stdexcept>

#include "kernels/coarse_search.hpp"
#include "kernels/face_node_weight.hpp"
#include "kernels/face_normal.hpp"
#include "kernels/mortar_pair_gradient.hpp"
#include "kernels/slave_frames.hpp"

namespace grout {

namespace {

using ExecSpace = Kokkos::DefaultExecutionSpace;
using MemSpace = ExecSpace::memory_space;

int position_of(const ContactSurface& s, GlobalIndex node) {
  return int(std::lower_bound(s.nodes.begin(), s.nodes.end(), node) - s.nodes.begin());
}

// Rows: the faces `rows` of `faces` (all if empty), nodes as positions in s.nodes.
Kokkos::View<int**, Kokkos::HostSpace> face_view(const ContactSurface& s, const SurfaceFaces& faces,
                                                 const std::vector<int>& rows = {}) {
  const std::size_t n = rows.empty() ? faces.size() : rows.size();
  Kokkos::View<int**, Kokkos::HostSpace> v("grout::contact_faces", n, max_face_nodes);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t f = rows.empty() ? i : std::size_t(rows[i]);
    for (int a = 0; a < max_face_nodes; ++a)
      v(i, a) = a < faces.num_nodes[f] ? position_of(s, faces.nodes[f][a]) : -1;
  }
  return v;
}

// Positions (n, dim) of the surface nodes.
Kokkos::View<double**, Kokkos::HostSpace> coordinate_view(
    const ContactSurface& s, const std::vector<std::array<double, 3>>& x) {
  const int dim = s.dimension;
  Kokkos::View<double**, Kokkos::HostSpace> coords("grout::contact_coords", s.nodes.size(), dim);
  for (std::size_t i = 0; i < s.nodes.size(); ++i)
    for (int d = 0; d < dim; ++d) coords(i, d) = x[i][d];
  return coords;
}

// A host view copied to the launches' memory space (the same view where that is the host).
template <class HostView>
auto on_device(const HostView& v) {
  return Kokkos::create_mirror_view_and_copy(MemSpace(), v);
}

}  // namespace

void compress_gradient(SparseGradient& g) {
  std::stable_sort(g.begin(), g.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::size_t out = 0;
  for (std::size_t i = 0; i < g.size();) {
    const long long dof = g[i].first;
    double sum = 0.0;
    for (; i < g.size() && g[i].first == dof; ++i) sum += g[i].second;
    if (sum != 0.0) g[out++] = {dof, sum};
  }
  g.resize(out);
}

namespace {

// Self-contact filters of a candidate pair (slave face f, master face g of s), docs/input.md
// "Self-contact": the faces share no node (a face never pairs with itself or a neighbour) ...
bool shares_node(const ContactSurface& s, int f, int g) {
  const auto& a = s.slave.nodes[f];
  const auto& b = s.master.nodes[g];
  for (int i = 0; i < s.slave.num_nodes[f]; ++i)
    for (int j = 0; j < s.master.num_nodes[g]; ++j)
      if (a[i] == b[j]) return true;
  return false;
}

// ... their element normals face each other at positions x, n_f·n_g < 0 (the two flanks of a
// fold pair, neighbours round a bend do not; for two bodies too: see find_candidates) ...
bool faces_face(const ContactSurface& s, int f, int g,
                const std::vector<std::array<double, 3>>& x) {
  const auto normal = [&](const SurfaceFaces& faces, int i, double n[3]) {
    double p[max_face_nodes][3] = {};
    for (int a = 0; a < faces.num_nodes[i]; ++a)
      for (int d = 0; d < 3; ++d) p[a][d] = x[position_of(s, faces.nodes[i][a])][d];
    return face_normal(s.dimension, faces.num_nodes[i], p, n) == MortarStatus::ok;
  };
  double nf[3], ng[3];
  if (!normal(s.slave, f, nf) || !normal(s.master, g, ng)) return false;
  return nf[0] * ng[0] + nf[1] * ng[1] + nf[2] * ng[2] < 0.0;
}

// ... and f lies on the slave side, g on the master side of the step's choice (s.self_side).
bool on_sides(const ContactSurface& s, int f, int g) {
  if (s.self_side.empty()) return true;
  return s.self_side[s.slave.ids[f]] == 1 && s.self_side[s.master.ids[g]] == 0;
}

// The slave faces evaluated (surface.integrate) and, per evaluated face, its candidate master
// faces (indices into s.master, ascending): a coarse search on x, together with one on
// search_x when given.
struct Candidates {
  std::vector<int> evaluated;
  std::vector<std::vector<int>> masters;
};
Candidates find_candidates(const ContactSurface& s, const std::vector<std::array<double, 3>>& x,
                           const ContactMortarOptions& options,
                           const std::vector<std::array<double, 3>>* search_x) {
  Candidates c;
  for (std::size_t f = 0; f < s.slave.size(); ++f)
    if (s.integrate.empty() || s.integrate[f]) c.evaluated.push_back(int(f));
  const auto slave_faces = face_view(s, s.slave, c.evaluated);
  const auto master_faces = face_view(s, s.master);
  c.masters.resize(c.evaluated.size());
  const auto search_on = [&](const std::vector<std::array<double, 3>>& positions) {
    const auto coords = coordinate_view(s, positions);
    SearchCandidates<Kokkos::HostSpace> found;
    coarse_search(slave_faces, master_faces, coords, options.search_factor, found);
    for (std::size_t k = 0; k < c.evaluated.size(); ++k)
      for (int p = found.offsets(k); p < found.offsets(k + 1); ++p)
        c.masters[k].push_back(found.masters(p));
  };
  search_on(x);
  if (search_x) search_on(*search_x);
  for (std::size_t k = 0; k < c.evaluated.size(); ++k) {
    auto& m = c.masters[k];
    std::sort(m.begin(), m.end());
    m.erase(std::unique(m.begin(), m.end()), m.end());
    if (s.type == ContactKind::tied) continue;
    const int f = c.evaluated[k];
    // Contact pairs face each other (self-contact and two bodies alike): a master face whose
    // normal does not oppose the slave face's lies behind it or beside it (through the slave's
    // own wall: the crossed tubes' upper flank paired with the lower tube under it, README of
    // inputs/self_contact). Its projected overlap vanishes as it turns edge-on (n_f·n_g = 0),
    // so dropping it there leaves D and M continuous.
    m.erase(std::remove_if(m.begin(), m.end(),
                           [&](int g) {
                             const bool facing = faces_face(s, f, g, x) ||
                                                 (search_x && faces_face(s, f, g, *search_x));
                             return !facing ||
                                    (s.self && (shares_node(s, f, g) || !on_sides(s, f, g)));
                           }),
            m.end());
  }
  return c;
}

}  // namespace

std::vector<std::pair<GlobalIndex, GlobalIndex>> contact_pairs(
    const ContactSurface& s, const std::vector<std::array<double, 3>>& x,
    const ContactMortarOptions& options, const std::vector<std::array<double, 3>>* search_x) {
  const Candidates c = find_candidates(s, x, options, search_x);
  std::vector<std::pair<GlobalIndex, GlobalIndex>> pairs;
  for (std::size_t k = 0; k < c.evaluated.size(); ++k)
    for (int m : c.masters[k]) pairs.emplace_back(s.slave.ids[c.evaluated[k]], s.master.ids[m]);
  return pairs;
}

namespace {

// The frames of the slave nodes `framed` (indices in s.slave_nodes) at positions x
// (compute_slave_frames), their derivatives as global-dof gradients.
void evaluate_frames(const ContactSurface& s, const std::vector<int>& framed,
                     const Kokkos::View<const double**, MemSpace>& coords, bool derivatives,
                     std::vector<SlaveFrame>& frames) {
  const int dim = s.dimension;
  const int n = int(framed.size());
  Kokkos::View<int*, Kokkos::HostSpace> offsets("grout::frame_offsets", n + 1);
  for (int i = 0; i < n; ++i)
    offsets(i + 1) = offsets(i) + int(s.slave_node_faces[framed[i]].size());
  Kokkos::View<int*, Kokkos::HostSpace> node_faces("grout::frame_faces", offsets(n));
  for (int i = 0; i < n; ++i)
    for (std::size_t k = 0; k < s.slave_node_faces[framed[i]].size(); ++k)
      node_faces(offsets(i) + int(k)) = s.slave_node_faces[framed[i]][k];
  const int rows = dim * dim, columns = max_face_nodes * dim;
  Kokkos::View<double**, MemSpace> values("grout::frames", n, rows);
  Kokkos::View<double***, MemSpace> gradients(
      Kokkos::view_alloc("grout::frame_gradients", Kokkos::WithoutInitializing),
      derivatives ? offsets(n) : 0, rows, columns);
  const auto faces = on_device(face_view(s, s.slave));
  const auto d_offsets = on_device(offsets);
  const auto d_node_faces = on_device(node_faces);
  if (dim == 2)
    compute_slave_frames<2>(ExecSpace(), faces, coords, d_offsets, d_node_faces, derivatives,
                            values, gradients);
  else
    compute_slave_frames<3>(ExecSpace(), faces, coords, d_offsets, d_node_faces, derivatives,
                            values, gradients);
  const auto h_values = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), values);
  const auto h_gradients = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), gradients);
  // Rows of SlaveFrameLayout: n_d at d, τ_{k,d} at dim + k·dim + d.
  for (int i = 0; i < n; ++i) {
    SlaveFrame& frame = frames[framed[i]];
    for (int d = 0; d < dim; ++d) {
      frame.n[d] = h_values(i, d);
      for (int k = 0; k < dim - 1; ++k) frame.t[k][d] = h_values(i, dim + k * dim + d);
    }
    if (!derivatives) continue;
    for (int q = offsets(i); q < offsets(i + 1); ++q) {
      const int f = node_faces(q);
      for (int a = 0; a < s.slave.num_nodes[f]; ++a)
        for (int c = 0; c < dim; ++c) {
          const long long dof = s.slave.nodes[f][a] * dim + c;
          const int v = a * dim + c;
          for (int d = 0; d < dim; ++d) {
            if (const double g = h_gradients(q, d, v); g != 0.0) frame.dn[d].emplace_back(dof, g);
            for (int k = 0; k < dim - 1; ++k)
              if (const double g = h_gradients(q, dim + k * dim + d, v); g != 0.0)
                frame.dt[k][d].emplace_back(dof, g);
          }
        }
    }
    for (int d = 0; d < dim; ++d) {
      compress_gradient(frame.dn[d]);
      for (int k = 0; k < dim - 1; ++k) compress_gradient(frame.dt[k][d]);
    }
  }
}

// The pairs of `candidates` integrated by mortar_integrate_gradients (values and, if
// options.derivatives, derivatives), summed into result.D and result.M in (slave face, master
// face) order with the chain rule through the frames for the 2D normal variables.
template <int Dim, class Pair>
void add_pairs(const ContactSurface& s, const Candidates& candidates,
               const Kokkos::View<const double**, MemSpace>& coords,
               const ContactMortarOptions& options, ContactMortar& result) {
  using Vars = MortarPairVariables<Dim>;
  constexpr bool derivatives = std::is_same<Pair, MortarPairGradient<Dim>>::value;
  const std::size_t n_evaluated = candidates.evaluated.size();
  Kokkos::View<int*, Kokkos::HostSpace> offsets("grout::pair_offsets", n_evaluated + 1);
  for (std::size_t k = 0; k < n_evaluated; ++k)
    offsets(k + 1) = offsets(k) + int(candidates.masters[k].size());
  const int n_pairs = offsets(n_evaluated);
  Kokkos::View<int*, Kokkos::HostSpace> masters("grout::pair_masters", n_pairs);
  for (std::size_t k = 0; k < n_evaluated; ++k)
    for (std::size_t c = 0; c < candidates.masters[k].size(); ++c)
      masters(offsets(k) + int(c)) = candidates.masters[k][c];
  // The launch projects along the slave nodal normals (2D); master rows stay zero.
  Kokkos::View<double**, Kokkos::HostSpace> normals("grout::pair_normals", s.nodes.size(), Dim);
  for (std::size_t j = 0; j < s.slave_nodes.size(); ++j)
    for (int d = 0; d < Dim; ++d)
      normals(position_of(s, s.slave_nodes[j]), d) = result.frames[j].n[d];
  Kokkos::View<Pair*, MemSpace> pairs(
      Kokkos::view_alloc("grout::mortar_pairs", Kokkos::WithoutInitializing), n_pairs);
  const MortarStatus status = mortar_integrate_gradients<Dim, Pair>(
      ExecSpace(), on_device(face_view(s, s.slave, candidates.evaluated)),
      on_device(face_view(s, s.master)), coords, on_device(normals), on_device(offsets),
      on_device(masters), options.mortar, pairs);
  if (status == MortarStatus::capacity_exceeded)
    throw std::logic_error("evaluate_contact_mortar: pair storage too short");
  const auto h_pairs = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), pairs);

  // Global dof of each pair variable (−1 for a normal variable, chained through the frame).
  long long var_dof[Vars::count];
  int var_normal[Vars::count][2];  // {slave node index, component} of a normal variable
  for (std::size_t k = 0; k < n_evaluated; ++k) {
    const int f = candidates.evaluated[k];
    const int n_slave = s.slave.num_nodes[f];
    int slave_index[max_face_nodes];
    for (int v = 0; v < Vars::count; ++v) var_dof[v] = -1, var_normal[v][0] = -1;
    for (int a = 0; a < n_slave && a < Vars::face_nodes; ++a) {
      slave_index[a] = s.slave_index.at(s.slave.nodes[f][a]);
      for (int d = 0; d < Dim; ++d) {
        var_dof[Vars::slave(a, d)] = s.slave.nodes[f][a] * Dim + d;
        if constexpr (Dim == 2) {
          var_normal[Vars::normal(a, d)][0] = slave_index[a];
          var_normal[Vars::normal(a, d)][1] = d;
        }
      }
    }
    for (int p = offsets(k); p < offsets(k + 1); ++p) {
      const Pair& pair = h_pairs(p);
      if (pair.status != int(MortarStatus::ok)) continue;  // no overlap, or a far candidate
      ++result.pairs;
      const int m = masters(p);
      for (int b = 0; b < pair.n_master; ++b)
        for (int d = 0; d < Dim; ++d) var_dof[Vars::master(b, d)] = s.master.nodes[m][b] * Dim + d;
      const auto add_gradient = [&](const double(&dv)[Vars::count], SparseGradient& out) {
        for (int v = 0; v < Vars::count; ++v) {
          const double g = dv[v];
          if (g == 0.0) continue;
          if (var_dof[v] >= 0) {
            out.emplace_back(var_dof[v], g);
          } else if (var_normal[v][0] >= 0) {
            for (const auto& [dof, dn] : result.frames[var_normal[v][0]].dn[var_normal[v][1]])
              out.emplace_back(dof, g * dn);
          }
        }
      };
      for (int j = 0; j < pair.n_slave; ++j) {
        MortarValue& D = result.D[slave_index[j]];
        D.value += pair.D[j];
        if constexpr (derivatives) add_gradient(pair.dD[j], D.gradient);
        for (int l = 0; l < pair.n_master; ++l) {
          MortarValue& M = result.M[{slave_index[j], s.master.nodes[m][l]}];
          M.value += pair.M[j][l];
          if constexpr (derivatives) add_gradient(pair.dM[j][l], M.gradient);
        }
      }
    }
  }
}

// w_j = Σ_e ∫_e N¹_j dA over the faces of slave node j (index in s.slave_nodes) at positions x
// (dA = 2π r ds when axisymmetric).
double slave_node_weight(const ContactSurface& s, int j,
                         const std::vector<std::array<double, 3>>& x, bool axisymmetric) {
  double w = 0.0;
  for (int f : s.slave_node_faces[j]) {
    double p[max_face_nodes][3] = {};
    int a = -1;
    for (int b = 0; b < s.slave.num_nodes[f]; ++b) {
      const std::array<double, 3>& xb = x[position_of(s, s.slave.nodes[f][b])];
      for (int d = 0; d < 3; ++d) p[b][d] = xb[d];
      if (s.slave.nodes[f][b] == s.slave_nodes[j]) a = b;
    }
    if (a >= 0) w += face_node_weight(s.dimension, s.slave.num_nodes[f], p, a, axisymmetric);
  }
  return w;
}

}  // namespace

ContactMortar evaluate_contact_mortar(const ContactSurface& s,
                                      const std::vector<std::array<double, 3>>& x,
                                      const ContactMortarOptions& options,
                                      const std::vector<std::array<double, 3>>* search_x) {
  ContactMortar result;
  const int n_slave_nodes = int(s.slave_nodes.size());
  result.frames.resize(n_slave_nodes);
  result.D.resize(n_slave_nodes);
  // The slave faces evaluated here and their candidate master faces; the nodal frames their
  // pairs use.
  const Candidates candidates = find_candidates(s, x, options, search_x);
  std::vector<char> is_framed(n_slave_nodes, 0);
  for (int f : candidates.evaluated)
    for (int a = 0; a < s.slave.num_nodes[f]; ++a)
      is_framed[s.slave_index.at(s.slave.nodes[f][a])] = 1;
  std::vector<int> framed;
  for (int j = 0; j < n_slave_nodes; ++j)
    if (is_framed[j]) framed.push_back(j);
  const auto coords = on_device(coordinate_view(s, x));
  evaluate_frames(s, framed, coords, options.derivatives, result.frames);
  result.W.assign(n_slave_nodes, 0.0);
  for (int j : framed) result.W[j] = slave_node_weight(s, j, x, options.mortar.axisymmetric);

  // Pairs in (slave face, master face) order: the master faces are in id order, so every
  // sum over pairs runs in the same order however the faces are distributed.
  if (s.dimension == 2 && options.derivatives)
    add_pairs<2, MortarPairGradient<2>>(s, candidates, coords, options, result);
  else if (s.dimension == 2)
    add_pairs<2, MortarPairValues<2>>(s, candidates, coords, options, result);
  else if (options.derivatives)
    add_pairs<3, MortarPairGradient<3>>(s, candidates, coords, options, result);
  else
    add_pairs<3, MortarPairValues<3>>(s, candidates, coords, options, result);
  for (auto& D : result.D) compress_gradient(D.gradient);
  for (auto& [key, M] : result.M) compress_gradient(M.gradient);
  return result;
}

}  // namespace grout
