#include "assembly/contact_mortar.hpp"

#include <Sacado.hpp>
#include <algorithm>
#include <type_traits>

#include "io/errors.hpp"
#include "kernels/coarse_search.hpp"
#include "kernels/mortar_2d.hpp"
#include "kernels/mortar_3d.hpp"
#include "kernels/surface_normals.hpp"

namespace grout {

namespace {

using DFad = Sacado::Fad::DFad<double>;
constexpr int pair_vars_2d = 12;  // slave x (2x2), slave normals (2x2), master x (2x2)
constexpr int pair_vars_3d = 24;  // slave x (4x3), master x (4x3)

// A pair is integrated in SFad over its nodal coordinates when the derivatives are wanted, in
// double otherwise (the same operations on the values: the same D and M, for a ~25th of the
// work; the reference geometry re-integrates D and M without derivatives when the pairing
// changes).
inline void seed(double&, int, int) {}
template <int N>
void seed(Sacado::Fad::SFad<double, N>& v, int i, int n) {
  v.diff(i, n);
}
inline double value_of(double v) {
  return v;
}
template <int N>
double value_of(const Sacado::Fad::SFad<double, N>& v) {
  return v.val();
}

int position_of(const ContactSurface& s, GlobalIndex node) {
  return int(std::lower_bound(s.nodes.begin(), s.nodes.end(), node) - s.nodes.begin());
}

// n_j = normalise(Σ_f n_f) over the slave faces f around node j, n_f the unit face normal
// (Popp et al. 2010, §3.1), differentiated with respect to the positions of the patch nodes.
SlaveFrame slave_frame(const ContactSurface& s, const std::vector<std::array<double, 3>>& x, int j,
                       bool derivatives) {
  const int dim = s.dimension;
  std::vector<GlobalIndex> patch;
  for (int f : s.slave_node_faces[j])
    patch.insert(patch.end(), s.slave.nodes[f].begin(),
                 s.slave.nodes[f].begin() + s.slave.num_nodes[f]);
  std::sort(patch.begin(), patch.end());
  patch.erase(std::unique(patch.begin(), patch.end()), patch.end());
  const int n_vars = derivatives ? int(patch.size()) * dim : 0;

  DFad n[3] = {0.0, 0.0, 0.0};
  for (int f : s.slave_node_faces[j]) {
    DFad xf[max_face_nodes][3];
    for (int a = 0; a < s.slave.num_nodes[f]; ++a) {
      const GlobalIndex node = s.slave.nodes[f][a];
      const int p = int(std::lower_bound(patch.begin(), patch.end(), node) - patch.begin());
      for (int d = 0; d < 3; ++d) {
        xf[a][d] = x[position_of(s, node)][d];
        if (derivatives && d < dim) xf[a][d].diff(p * dim + d, n_vars);
      }
    }
    DFad nf[3];
    face_normal(dim, s.slave.num_nodes[f], xf, nf);
    for (int d = 0; d < 3; ++d) n[d] += nf[d];
  }
  DFad t[2][3];
  if (dim == 2) {
    normalize_vector<2>(n);
    tangent_2d(n, t[0]);
  } else {
    normalize_vector<3>(n);
    tangents_3d(n, t[0], t[1]);
  }
  SlaveFrame frame;
  auto gradient = [&](const DFad& v, SparseGradient& g) {
    for (int i = 0; i < v.size(); ++i)
      if (v.dx(i) != 0.0) g.emplace_back(patch[i / dim] * dim + i % dim, v.dx(i));
  };
  for (int d = 0; d < dim; ++d) {
    frame.n[d] = n[d].val();
    gradient(n[d], frame.dn[d]);
    for (int k = 0; k < dim - 1; ++k) {
      frame.t[k][d] = t[k][d].val();
      gradient(t[k][d], frame.dt[k][d]);
    }
  }
  return frame;
}

// Adds the pair derivative of `v` (a Fad over the pair variables) to `out`, chaining the
// slave-normal variables through the frames' dn.
template <class Fad>
void add_pair_gradient(const Fad& v, const std::vector<long long>& var_dof,
                       const std::vector<std::pair<int, int>>& var_normal,
                       const std::vector<SlaveFrame>& frames, SparseGradient& out) {
  for (int i = 0; i < v.size(); ++i) {
    const double d = v.dx(i);
    if (d == 0.0) continue;
    if (var_dof[i] >= 0) {
      out.emplace_back(var_dof[i], d);
    } else if (var_normal[i].first >= 0) {
      for (const auto& [dof, dn] : frames[var_normal[i].first].dn[var_normal[i].second])
        out.emplace_back(dof, d * dn);
    }
  }
}

template <class Scalar>
MortarStatus integrate_pair(const ContactSurface& s, int dim, const Scalar xs[4][3],
                            const Scalar ns[4][3], int n_slave, const Scalar xm[4][3], int n_master,
                            const ContactMortarOptions& options, MortarPairResult<Scalar>& out) {
  const bool exact = options.scheme == MortarIntegration::exact;
  if (dim == 2) {
    const Scalar xs2[2][2] = {{xs[0][0], xs[0][1]}, {xs[1][0], xs[1][1]}};
    const Scalar ns2[2][2] = {{ns[0][0], ns[0][1]}, {ns[1][0], ns[1][1]}};
    const Scalar xm2[2][2] = {{xm[0][0], xm[0][1]}, {xm[1][0], xm[1][1]}};
    return exact ? integrate_mortar_2d(xs2, ns2, xm2, out)
                 : integrate_mortar_2d_collocation(xs2, ns2, xm2, options.collocation_points, out);
  }
  (void)s;
  return exact ? integrate_mortar_3d(n_slave, xs, ns, n_master, xm, out)
               : integrate_mortar_3d_collocation(n_slave, xs, ns, n_master, xm,
                                                 options.collocation_points, out);
}

// Dual-basis coefficients A_e (Fad or double) of the last 3D slave face: they depend on the
// slave coordinates only, which are the first pair variables of every pair of that face, so
// the candidates of one slave face share them (a 16-point mass matrix and its inverse).
template <class Scalar>
struct SlaveDualCache {
  int face = -1;
  MortarStatus status = MortarStatus::degenerate;
  Scalar A[max_face_nodes][max_face_nodes];
};

// One (slave face f, master face m) pair: integrate (with AD when Fad is an SFad over NVars
// variables, in double when it is double) and accumulate D, M.
template <class Fad, int NVars>
void add_pair(const ContactSurface& s, const std::vector<std::array<double, 3>>& x,
              const ContactMortarOptions& options, int f, int m, ContactMortar& result,
              SlaveDualCache<Fad>* dual_cache) {
  constexpr bool with_derivatives = !std::is_same_v<Fad, double>;
  const int dim = s.dimension;
  const int n_slave = s.slave.num_nodes[f], n_master = s.master.num_nodes[m];
  std::vector<long long> var_dof(NVars, -1);
  std::vector<std::pair<int, int>> var_normal(NVars, {-1, -1});
  Fad xs[4][3] = {}, ns[4][3] = {}, xm[4][3] = {};
  int v = 0;
  int slave_index[4];
  for (int a = 0; a < n_slave; ++a) {
    const GlobalIndex node = s.slave.nodes[f][a];
    slave_index[a] = s.slave_index.at(node);
    for (int d = 0; d < 3; ++d) {
      xs[a][d] = x[position_of(s, node)][d];
      ns[a][d] = result.frames[slave_index[a]].n[d];
      if (d < dim) {
        seed(xs[a][d], v, NVars);
        var_dof[v++] = node * dim + d;
      }
    }
  }
  if (dim == 2) {  // the 2D projection follows the slave nodal normals
    for (int a = 0; a < n_slave; ++a)
      for (int d = 0; d < dim; ++d) {
        seed(ns[a][d], v, NVars);
        var_normal[v++] = {slave_index[a], d};
      }
  }
  for (int b = 0; b < n_master; ++b) {
    const GlobalIndex node = s.master.nodes[m][b];
    for (int d = 0; d < 3; ++d) {
      xm[b][d] = x[position_of(s, node)][d];
      if (d < dim) {
        seed(xm[b][d], v, NVars);
        var_dof[v++] = node * dim + d;
      }
    }
  }
  MortarPairResult<Fad> pair;
  MortarStatus status;
  const bool exact_3d = dual_cache && dim == 3 && options.scheme == MortarIntegration::exact &&
                        (n_slave == 3 || n_slave == 4) && (n_master == 3 || n_master == 4);
  if (exact_3d) {  // integrate_mortar_3d with the face's cached A_e
    SlaveDualCache<Fad>& cache = *dual_cache;
    if (cache.face != f) {
      cache.face = f;
      cache.status = dual_basis_coefficients_3d(n_slave, xs, cache.A);
    }
    detail3d::reset_pair_result(n_slave, n_master, pair);
    status = cache.status != MortarStatus::ok
                 ? MortarStatus::degenerate
                 : integrate_mortar_3d_dual(n_slave, xs, cache.A, n_master, xm, pair);
  } else {
    status = integrate_pair(s, dim, xs, ns, n_slave, xm, n_master, options, pair);
  }
  if (status != MortarStatus::ok) return;  // no overlap (or a harmless far-away candidate)
  ++result.pairs;
  for (int j = 0; j < n_slave; ++j) {
    MortarValue& D = result.D[slave_index[j]];
    D.value += value_of(pair.D[j]);
    if constexpr (with_derivatives)
      add_pair_gradient(pair.D[j], var_dof, var_normal, result.frames, D.gradient);
    for (int l = 0; l < n_master; ++l) {
      MortarValue& M = result.M[{slave_index[j], s.master.nodes[m][l]}];
      M.value += value_of(pair.M[j][l]);
      if constexpr (with_derivatives)
        add_pair_gradient(pair.M[j][l], var_dof, var_normal, result.frames, M.gradient);
    }
  }
}

// Rows: the faces `rows` of `faces` (all if empty), nodes as positions in s.nodes.
Kokkos::View<int**> face_view(const ContactSurface& s, const SurfaceFaces& faces,
                              const std::vector<int>& rows = {}) {
  const std::size_t n = rows.empty() ? faces.size() : rows.size();
  Kokkos::View<int**> v("grout::contact_faces", n, max_face_nodes);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t f = rows.empty() ? i : std::size_t(rows[i]);
    for (int a = 0; a < max_face_nodes; ++a)
      v(i, a) = a < faces.num_nodes[f] ? position_of(s, faces.nodes[f][a]) : -1;
  }
  return v;
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
  const int dim = s.dimension;
  const auto slave_faces = face_view(s, s.slave, c.evaluated);
  const auto master_faces = face_view(s, s.master);
  c.masters.resize(c.evaluated.size());
  const auto search_on = [&](const std::vector<std::array<double, 3>>& positions) {
    Kokkos::View<double**> coords("grout::contact_coords", s.nodes.size(), dim);
    for (std::size_t i = 0; i < s.nodes.size(); ++i)
      for (int d = 0; d < dim; ++d) coords(i, d) = positions[i][d];
    SearchCandidates<Kokkos::HostSpace> found;
    coarse_search(slave_faces, master_faces, coords, options.search_factor, found);
    for (std::size_t k = 0; k < c.evaluated.size(); ++k)
      for (int p = found.offsets(k); p < found.offsets(k + 1); ++p)
        c.masters[k].push_back(found.masters(p));
  };
  search_on(x);
  if (search_x) search_on(*search_x);
  for (auto& m : c.masters) {
    std::sort(m.begin(), m.end());
    m.erase(std::unique(m.begin(), m.end()), m.end());
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
  std::vector<char> framed(n_slave_nodes, 0);
  for (int f : candidates.evaluated)
    for (int a = 0; a < s.slave.num_nodes[f]; ++a)
      framed[s.slave_index.at(s.slave.nodes[f][a])] = 1;
  for (int j = 0; j < n_slave_nodes; ++j)
    if (framed[j]) result.frames[j] = slave_frame(s, x, j, options.derivatives);

  // Pairs in (slave face, master face) order: the master faces are in id order, so every
  // sum over pairs runs in the same order however the faces are distributed.
  using Fad2 = Sacado::Fad::SFad<double, pair_vars_2d>;
  using Fad3 = Sacado::Fad::SFad<double, pair_vars_3d>;
  SlaveDualCache<Fad3> dual_cache;
  SlaveDualCache<double> dual_cache_values;
  for (std::size_t k = 0; k < candidates.evaluated.size(); ++k) {
    const int f = candidates.evaluated[k];
    for (int m : candidates.masters[k]) {
      if (s.dimension == 2 && options.derivatives)
        add_pair<Fad2, pair_vars_2d>(s, x, options, f, m, result, nullptr);
      else if (s.dimension == 2)
        add_pair<double, pair_vars_2d>(s, x, options, f, m, result, nullptr);
      else if (options.derivatives)
        add_pair<Fad3, pair_vars_3d>(s, x, options, f, m, result, &dual_cache);
      else
        add_pair<double, pair_vars_3d>(s, x, options, f, m, result, &dual_cache_values);
    }
  }
  for (auto& D : result.D) compress_gradient(D.gradient);
  for (auto& [key, M] : result.M) compress_gradient(M.gradient);
  return result;
}

}  // namespace grout
