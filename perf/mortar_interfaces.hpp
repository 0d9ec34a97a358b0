#pragma once
// Non-matching contact interfaces for the mortar benchmarks (perf/bench_mortar.cpp,
// perf/bench_moertel.cpp) and the 3D launch test: plain arrays (no Kokkos, no Tpetra), so the
// same interface can be handed to Grout's kernels and to Moertel.
//
//  2D  slave:  n LINE2 segments on y = f(x), x ∈ [0, 1], left to right, so that its normal
//              (dy, −dx)/L points to −y, towards the master;
//      master: m = ⌊1.3 n⌋ + 1 segments on y = f(x) − gap over [−δ, 1 + δ], right to left (normal
//              towards +y), so every slave segment is fully covered and no master node
//              coincides with a slave node.
//      flat: f = 0; curved: f = 0.05 sin(2πx) (nodal normals then vary along the interface).
//  3D  slave:  n × n faces on z = 0 over [0, 1]²: QUAD4 (n × n cells) or TRI3 (n × n/2 cells
//              cut along one diagonal, n even), counter-clockwise seen from +z;
//      master: the same over [−δ, 1 + δ]² at z = gap (on the side of the slave normal +z),
//              m = ⌊1.3 n⌋ + 1 cells per direction (TRI3: m × ⌈m/2⌉ cells cut along the other
//              diagonal), clockwise seen from +z.
// δ = h/4 and gap = 1e-3 h, h = 1/n the slave cell size. Node ids: slave nodes first, then
// master nodes. Face rows have `cols` entries (2 in 2D, 4 in 3D), −1 padding for TRI3.

#include <cmath>
#include <vector>

namespace grout::bench {

enum class FaceShape { line2, tri3, quad4 };

struct MortarInterface {
  int dim = 2;                 ///< 2 or 3
  int cols = 2;                ///< entries per face row
  std::vector<double> coords;  ///< (n_nodes × dim), row-major
  std::vector<int> slave;      ///< (n_slave × cols) node ids, −1 padding
  std::vector<int> master;     ///< (n_master × cols)
  int n_slave_nodes = 0;       ///< slave nodes are 0 .. n_slave_nodes − 1
  double slave_measure = 0.0;  ///< exact total slave length (2D) or area (3D)
  double gap = 0.0;            ///< normal offset of the master side (flat interfaces)

  int n_nodes() const { return static_cast<int>(coords.size()) / dim; }
  int n_slave() const { return static_cast<int>(slave.size()) / cols; }
  int n_master() const { return static_cast<int>(master.size()) / cols; }
};

/// Master cells per direction for n slave cells: ⌊1.3 n⌋ + 1 (never a multiple of n).
inline int master_cells(int n) {
  return (13 * n) / 10 + 1;
}

/// 2D interface with n slave segments; curved: on y = 0.05 sin(2πx), else flat (y = 0).
inline MortarInterface line_interface_2d(int n, bool curved) {
  MortarInterface mi;
  mi.dim = 2;
  mi.cols = 2;
  const double pi = 3.14159265358979323846, h = 1.0 / n, delta = 0.25 * h;
  mi.gap = 1e-3 * h;
  auto f = [&](double x) { return curved ? 0.05 * std::sin(2.0 * pi * x) : 0.0; };
  const int m = master_cells(n);
  mi.coords.reserve(2 * (n + 1 + m + 1));
  for (int i = 0; i <= n; ++i) {
    const double x = i * h;
    mi.coords.push_back(x);
    mi.coords.push_back(f(x));
  }
  mi.n_slave_nodes = n + 1;
  for (int i = 0; i <= m; ++i) {  // right to left
    const double x = 1.0 + delta - i * (1.0 + 2.0 * delta) / m;
    mi.coords.push_back(x);
    mi.coords.push_back(f(x) - mi.gap);
  }
  for (int e = 0; e < n; ++e) mi.slave.insert(mi.slave.end(), {e, e + 1});
  for (int e = 0; e < m; ++e) mi.master.insert(mi.master.end(), {n + 1 + e, n + 2 + e});
  for (int e = 0; e < n; ++e) {
    const double* a = &mi.coords[2 * e];
    mi.slave_measure += std::hypot(a[2] - a[0], a[3] - a[1]);
  }
  return mi;
}

namespace detail {
// Structured grid of nx × ny cells over [x0, x0 + lx] × [y0, y0 + ly] at height z, node ids from
// `first`; appends the faces (QUAD4, or TRI3 cut along the diagonal `rising` or the other one),
// counter-clockwise seen from +z unless `flip`.
inline void grid_faces(MortarInterface& mi, std::vector<int>& faces, FaceShape shape, int nx,
                       int ny, double x0, double y0, double lx, double ly, double z, bool rising,
                       bool flip) {
  const int first = mi.n_nodes();
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      mi.coords.push_back(x0 + lx * i / nx);
      mi.coords.push_back(y0 + ly * j / ny);
      mi.coords.push_back(z);
    }
  auto add = [&](int n_nodes, const int* ids) {
    int row[4] = {-1, -1, -1, -1};
    for (int k = 0; k < n_nodes; ++k) row[k] = ids[flip ? n_nodes - 1 - k : k];
    faces.insert(faces.end(), row, row + 4);
  };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = first + j * (nx + 1) + i, b = a + 1, c = a + nx + 2, d = a + nx + 1;
      if (shape == FaceShape::quad4) {
        const int q[4] = {a, b, c, d};
        add(4, q);
      } else if (rising) {  // diagonal a–c
        const int t1[3] = {a, b, c}, t2[3] = {a, c, d};
        add(3, t1), add(3, t2);
      } else {  // diagonal b–d
        const int t1[3] = {a, b, d}, t2[3] = {b, c, d};
        add(3, t1), add(3, t2);
      }
    }
}
}  // namespace detail

/// Flat 3D interface with n × n slave faces (see the file comment); TRI3 needs n even.
inline MortarInterface flat_interface_3d(int n, FaceShape slave_shape, FaceShape master_shape) {
  MortarInterface mi;
  mi.dim = 3;
  mi.cols = 4;
  const double h = 1.0 / n, delta = 0.25 * h;
  mi.gap = 1e-3 * h;
  const bool slave_tri = slave_shape == FaceShape::tri3;
  detail::grid_faces(mi, mi.slave, slave_shape, n, slave_tri ? n / 2 : n, 0.0, 0.0, 1.0, 1.0, 0.0,
                     true, false);
  mi.n_slave_nodes = mi.n_nodes();
  const int m = master_cells(n);
  const bool master_tri = master_shape == FaceShape::tri3;
  detail::grid_faces(mi, mi.master, master_shape, m, master_tri ? (m + 1) / 2 : m, -delta, -delta,
                     1.0 + 2.0 * delta, 1.0 + 2.0 * delta, mi.gap, false, true);
  mi.slave_measure = 1.0;
  return mi;
}

}  // namespace grout::bench
