// The derivative launch of the mortar pair kernels (kernels/mortar_pair_gradient.hpp): its
// values against mortar_integrate's (the values-only launch), and its derivatives against
// central differences of mortar_integrate's values, for every pair variable (slave and master
// coordinates; in 2D the slave nodal normals too), on curved non-matching 2D and 3D interfaces.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "kernels/mortar_pair_gradient.hpp"
#include "kernels/surface_normals.hpp"

namespace grout {
namespace {

// Slave faces 0..n_s−1 and master faces over one node table; every (slave, master) pair is a
// candidate.
struct Interface {
  int dim;
  std::vector<std::vector<int>> slave, master;
  std::vector<double> x;        // n_nodes × dim
  std::vector<double> normals;  // n_nodes × dim (slave nodal normals; master rows unused)
};

// Slave: 3 LINE2 on y = 0.1 x² (x ∈ [−1, 1]); master: 4 LINE2 on y = −0.02 + 0.05 x² − 0.03 x
// oriented the other way, overlapping partly.
Interface arcs_2d() {
  Interface c{2, {}, {}, {}, {}};
  for (double x : {-1.0, -0.3, 0.35, 1.0}) c.x.insert(c.x.end(), {x, 0.1 * x * x});
  for (double x : {1.2, 0.55, -0.05, -0.6, -1.3})
    c.x.insert(c.x.end(), {x, -0.02 + 0.05 * x * x - 0.03 * x});
  for (int f = 0; f < 3; ++f) c.slave.push_back({f, f + 1});
  for (int f = 0; f < 4; ++f) c.master.push_back({4 + f, 5 + f});
  return c;
}

// Slave: a QUAD4 and a TRI3 on a gently curved surface; master: two QUAD4 and a TRI3 just below,
// rotated and shifted so that every clip polygon is a general one.
Interface patches_3d() {
  Interface c{3, {}, {}, {}, {}};
  const auto z_s = [](double x, double y) { return 0.05 * x * x - 0.04 * x * y + 0.03 * y * y; };
  const double slave_xy[][2] = {{0, 0}, {1, 0.1}, {1.1, 1}, {0.05, 0.95}, {2, 0.4}};
  for (const auto& p : slave_xy) c.x.insert(c.x.end(), {p[0], p[1], z_s(p[0], p[1])});
  c.slave = {{0, 1, 2, 3}, {1, 4, 2}};
  const double ca = std::cos(0.3), sa = std::sin(0.3);
  const double master_xy[][2] = {{-0.2, -0.3}, {0.8, -0.3}, {1.8, -0.3},
                                 {-0.2, 0.8},  {0.8, 0.8},  {1.8, 0.8}};
  for (const auto& p : master_xy) {
    const double x = 0.2 + ca * p[0] - sa * p[1], y = 0.1 + sa * p[0] + ca * p[1];
    c.x.insert(c.x.end(), {x, y, -0.01 + 0.02 * x - 0.03 * y});
  }
  // Master faces oriented opposite to the slave (their normals point up, into the slave).
  c.master = {{5, 8, 9, 6}, {6, 9, 10}, {6, 10, 7}};
  return c;
}

Kokkos::View<int**> face_table(const std::vector<std::vector<int>>& faces) {
  Kokkos::View<int**> t("faces", faces.size(), max_face_nodes);
  Kokkos::deep_copy(t, -1);
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (std::size_t a = 0; a < faces[f].size(); ++a) t(f, a) = faces[f][a];
  return t;
}

Kokkos::View<double**> node_table(const std::vector<double>& v, int dim) {
  Kokkos::View<double**> t("nodes", v.size() / dim, dim);
  for (std::size_t i = 0; i < v.size() / dim; ++i)
    for (int d = 0; d < dim; ++d) t(i, d) = v[i * dim + d];
  return t;
}

void set_normals(Interface& c) {
  Kokkos::View<double**> normals("normals", c.x.size() / c.dim, c.dim);
  ASSERT_EQ(compute_nodal_normals(face_table(c.slave), node_table(c.x, c.dim), normals),
            MortarStatus::ok);
  c.normals.assign(c.x.size(), 0.0);
  for (std::size_t i = 0; i < c.x.size() / c.dim; ++i)
    for (int d = 0; d < c.dim; ++d) c.normals[i * c.dim + d] = normals(i, d);
}

struct Candidates {
  Kokkos::View<int*> offsets, masters;
};
Candidates all_pairs(const Interface& c) {
  Candidates k{Kokkos::View<int*>("offsets", c.slave.size() + 1),
               Kokkos::View<int*>("masters", c.slave.size() * c.master.size())};
  for (std::size_t s = 0; s < c.slave.size(); ++s) {
    k.offsets(s + 1) = int((s + 1) * c.master.size());
    for (std::size_t m = 0; m < c.master.size(); ++m) k.masters(s * c.master.size() + m) = int(m);
  }
  return k;
}

template <int Dim>
Kokkos::View<MortarPairResult<double>*> values_of(const Interface& c) {
  const Candidates k = all_pairs(c);
  Kokkos::View<MortarPairResult<double>*> out("pairs", k.masters.extent(0));
  mortar_integrate<Dim>(Kokkos::DefaultExecutionSpace(), face_table(c.slave), face_table(c.master),
                        node_table(c.x, Dim), node_table(c.normals, Dim), k.offsets, k.masters,
                        MortarOptions(), out);
  return out;
}

template <int Dim, class Pair = MortarPairGradient<Dim>>
Kokkos::View<Pair*> gradients_of(const Interface& c) {
  const Candidates k = all_pairs(c);
  Kokkos::View<Pair*> out("gradients", k.masters.extent(0));
  mortar_integrate_gradients<Dim, Pair>(
      Kokkos::DefaultExecutionSpace(), face_table(c.slave), face_table(c.master),
      node_table(c.x, Dim), node_table(c.normals, Dim), k.offsets, k.masters, MortarOptions(), out);
  return out;
}

template <int Dim>
void check_values(Interface c) {
  set_normals(c);
  const auto v = values_of<Dim>(c);
  int overlapping = 0;
  const auto compare = [&](const auto& g, bool count) {
    for (std::size_t p = 0; p < v.extent(0); ++p) {
      if (g(p).status != int(MortarStatus::ok)) continue;
      overlapping += count;
      for (int j = 0; j < g(p).n_slave; ++j) {
        EXPECT_NEAR(g(p).D[j], v(p).D[j], 1e-15) << p;
        for (int l = 0; l < g(p).n_master; ++l) EXPECT_NEAR(g(p).M[j][l], v(p).M[j][l], 1e-15);
      }
    }
  };
  compare(gradients_of<Dim>(c), true);
  compare(gradients_of<Dim, MortarPairValues<Dim>>(c), false);
  EXPECT_GE(overlapping, 4);  // the interfaces are built so that several pairs overlap
}

// Each variable v of each pair: ∂D/∂v, ∂M/∂v against central differences of mortar_integrate.
template <int Dim>
void check_derivatives(Interface c) {
  using Vars = MortarPairVariables<Dim>;
  set_normals(c);
  const Candidates k = all_pairs(c);
  const auto g = gradients_of<Dim>(c);
  const double h = 1e-6;
  int checked = 0;
  for (std::size_t s = 0; s < c.slave.size(); ++s)
    for (std::size_t m = 0; m < c.master.size(); ++m) {
      const std::size_t p = s * c.master.size() + m;
      if (g(p).status != int(MortarStatus::ok)) continue;
      for (int v = 0; v < Vars::count; ++v) {
        // The node value that variable v moves.
        std::vector<double>* field = &c.x;
        int node, d;
        if (v >= Vars::master_offset) {
          const int b = (v - Vars::master_offset) / Dim;
          if (b >= int(c.master[m].size())) continue;
          node = c.master[m][b], d = (v - Vars::master_offset) % Dim;
        } else if (Dim == 2 && v >= Vars::normal_offset) {
          field = &c.normals;
          node = c.slave[s][(v - Vars::normal_offset) / Dim], d = (v - Vars::normal_offset) % Dim;
        } else {
          if (v / Dim >= int(c.slave[s].size())) continue;
          node = c.slave[s][v / Dim], d = v % Dim;
        }
        const double saved = (*field)[node * Dim + d];
        (*field)[node * Dim + d] = saved + h;
        const auto plus = values_of<Dim>(c);
        (*field)[node * Dim + d] = saved - h;
        const auto minus = values_of<Dim>(c);
        (*field)[node * Dim + d] = saved;
        for (int j = 0; j < g(p).n_slave; ++j) {
          EXPECT_NEAR(g(p).dD[j][v], (plus(p).D[j] - minus(p).D[j]) / (2 * h), 1e-7)
              << "pair " << p << " D_" << j << " variable " << v;
          for (int l = 0; l < g(p).n_master; ++l)
            EXPECT_NEAR(g(p).dM[j][l][v], (plus(p).M[j][l] - minus(p).M[j][l]) / (2 * h), 1e-7)
                << "pair " << p << " M_" << j << l << " variable " << v;
        }
        ++checked;
      }
    }
  EXPECT_GT(checked, 3 * Vars::count / 2);
}

TEST(MortarPairGradient, ValuesEqualTheValuesLaunch2D) {
  check_values<2>(arcs_2d());
}
TEST(MortarPairGradient, ValuesEqualTheValuesLaunch3D) {
  check_values<3>(patches_3d());
}
TEST(MortarPairGradient, DerivativesMatchCentralDifferences2D) {
  check_derivatives<2>(arcs_2d());
}
TEST(MortarPairGradient, DerivativesMatchCentralDifferences3D) {
  check_derivatives<3>(patches_3d());
}

}  // namespace
}  // namespace grout
