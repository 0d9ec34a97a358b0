// grout::MortarCoupling's Kokkos View entry points: host Views of any layout as the arrays of
// the pointer interface (contiguous LayoutRight Views read in place, others gathered).

#include <string>
#include <vector>

#include "mortar_coupling_impl.hpp"

namespace grout {

namespace {

/// A 2D host View as a row-major array: in place if it is contiguous LayoutRight, else
/// gathered into `buffer`.
template <class T, class View>
const T* row_major(const View& v, std::vector<T>& buffer) {
  const std::size_t rows = v.extent(0), cols = v.extent(1);
  if (rows * cols == 0) return nullptr;
  if (v.stride(1) == 1 && (rows == 1 || v.stride(0) == cols)) return v.data();
  buffer.resize(rows * cols);
  for (std::size_t i = 0; i < rows; ++i)
    for (std::size_t j = 0; j < cols; ++j) buffer[i * cols + j] = v(i, j);
  return buffer.data();
}

/// SurfaceArrays over SurfaceViews (strided Views gathered into the buffers).
SurfaceArrays arrays_of(const SurfaceViews& v, const char* side, int dim, std::vector<int>& faces,
                        std::vector<double>& x, std::vector<long long>& ids,
                        std::vector<double>& inside) {
  const std::string what = std::string("grout::MortarCoupling: ") + side + " surface: ";
  if (int(v.coordinates.extent(1)) != dim)
    throw MortarCouplingError(what + "coordinates View is " +
                              std::to_string(v.coordinates.extent(0)) + " × " +
                              std::to_string(v.coordinates.extent(1)) + ", dim " +
                              std::to_string(dim) + " expected (n_nodes × dim)");
  SurfaceArrays a;
  a.nodes_per_face = int(v.faces.extent(1));
  a.n_faces = v.faces.extent(0);
  a.faces = row_major<int>(v.faces, faces);
  a.n_nodes = v.coordinates.extent(0);
  a.coordinates = row_major<double>(v.coordinates, x);
  if (v.node_ids.extent(0) > 0) {
    if (v.node_ids.extent(0) != a.n_nodes)
      throw MortarCouplingError(what + std::to_string(v.node_ids.extent(0)) + " node ids for " +
                                std::to_string(a.n_nodes) + " coordinate rows");
    ids.resize(a.n_nodes);
    for (std::size_t i = 0; i < a.n_nodes; ++i) ids[i] = v.node_ids(i);
    a.node_ids = ids.data();
  }
  if (v.inside_points.extent(0) > 0) {
    if (v.inside_points.extent(0) != a.n_faces || int(v.inside_points.extent(1)) != dim)
      throw MortarCouplingError(
          what + "inside_points View is " + std::to_string(v.inside_points.extent(0)) + " × " +
          std::to_string(v.inside_points.extent(1)) + ", " + std::to_string(a.n_faces) + " × " +
          std::to_string(dim) + " expected (n_faces × dim)");
    a.inside_points = row_major<double>(v.inside_points, inside);
  }
  return a;
}

/// The dimension of a pair of SurfaceViews (coordinates.extent(1) of the slave).
int dim_of(const SurfaceViews& slave) {
  return int(slave.coordinates.extent(1));
}

struct ViewBuffers {
  std::vector<int> faces[2];
  std::vector<double> x[2];
  std::vector<long long> ids[2];
  std::vector<double> inside[2];
};

}  // namespace

MortarCoupling::MortarCoupling(const SurfaceViews& slave, const SurfaceViews& master,
                               const MortarCouplingOptions& options, MPI_Comm comm) {
  ViewBuffers b;  // strided Views gathered; the arrays are copied by the constructor below
  SurfaceArrays s, m;
  const int dim = dim_of(slave);
  agree_on_error(comm, [&] {
    s = arrays_of(slave, "slave", dim, b.faces[0], b.x[0], b.ids[0], b.inside[0]);
    m = arrays_of(master, "master", dim, b.faces[1], b.x[1], b.ids[1], b.inside[1]);
  });
  *this = MortarCoupling(dim, s, m, options, comm);
}

void MortarCoupling::update(const HostCoordinates& slave_coordinates,
                            const HostCoordinates& master_coordinates) {
  Impl& m = *impl_;
  const double *xs = nullptr, *xm = nullptr;
  agree_on_error(m.comm, [&] {
    const auto rows = [&](const HostCoordinates& v, std::size_t n) {
      return v.extent(0) == n && int(v.extent(1)) == m.dim;
    };
    if (!rows(slave_coordinates, m.slave.n_nodes) || !rows(master_coordinates, m.master.n_nodes))
      throw MortarCouplingError(
          "grout::MortarCoupling::update: Views of " + std::to_string(slave_coordinates.extent(0)) +
          " × " + std::to_string(slave_coordinates.extent(1)) + " slave and " +
          std::to_string(master_coordinates.extent(0)) + " × " +
          std::to_string(master_coordinates.extent(1)) + " master coordinates, " +
          std::to_string(m.slave.n_nodes) + " × " + std::to_string(m.dim) + " and " +
          std::to_string(m.master.n_nodes) + " × " + std::to_string(m.dim) + " expected");
    xs = row_major<double>(slave_coordinates, m.view_x[0]);
    xm = row_major<double>(master_coordinates, m.view_x[1]);
  });
  update(xs, xm);
}

}  // namespace grout
