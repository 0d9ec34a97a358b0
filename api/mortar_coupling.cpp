// grout::MortarCoupling: checks of the host's data, the local interface (with a communicator,
// through the parallel coarse search of assembly/contact_distribution) and the read-back. The
// evaluation paths are in mortar_coupling_evaluate.cpp, the Kokkos View entry points in
// mortar_coupling_views.cpp.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <functional>
#include <limits>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "assembly/contact_distribution.hpp"
#include "kernels/face_normal.hpp"
#include "mortar_coupling_impl.hpp"

namespace grout {

namespace {

const char* side_name(int side) {
  return side == 0 ? "slave" : "master";
}

/// Copies and checks one surface: face type, node indices, ids.
HostSurface copy_surface(int dim, int side, const SurfaceArrays& in, long long default_first_id) {
  const std::string what = std::string("grout::MortarCoupling: ") + side_name(side) + " surface: ";
  HostSurface s;
  s.cols = in.nodes_per_face;
  const bool type_ok = dim == 2 ? s.cols == 2 : (s.cols == 3 || s.cols == 4);
  if (!type_ok)
    throw MortarCouplingError(what + "nodes_per_face = " + std::to_string(s.cols) + " in " +
                              std::to_string(dim) +
                              "D (LINE2: 2 in 2D; TRI3: 3 or QUAD4: 4 in 3D)");
  if (in.n_faces > 0 && !in.faces)
    throw MortarCouplingError(what + "faces is null for n_faces = " + std::to_string(in.n_faces));
  if (in.n_nodes > 0 && !in.coordinates)
    throw MortarCouplingError(what +
                              "coordinates is null for n_nodes = " + std::to_string(in.n_nodes));
  s.n_nodes = in.n_nodes;
  s.faces.assign(in.faces, in.faces + in.n_faces * s.cols);
  s.x.assign(in.coordinates, in.coordinates + in.n_nodes * dim);
  for (std::size_t f = 0; f < in.n_faces; ++f) {
    const int* row = &s.faces[f * s.cols];
    const int n = s.cols == 4 && row[3] == -1 ? 3 : s.cols;
    for (int a = 0; a < s.cols; ++a) {
      const bool padding = a == 3 && n == 3;
      if (!padding && (row[a] < 0 || std::size_t(row[a]) >= in.n_nodes))
        throw MortarCouplingError(what + "face " + std::to_string(f) + " node " +
                                  std::to_string(a) + " = " + std::to_string(row[a]) +
                                  " is not a coordinate row (0 … " + std::to_string(in.n_nodes) +
                                  " − 1)" + (a == 3 ? "; −1 marks a TRI3 row" : ""));
      for (int b = 0; b < a && !padding; ++b)
        if (row[b] == row[a])
          throw MortarCouplingError(what + "face " + std::to_string(f) + " repeats node " +
                                    std::to_string(row[a]) + " (degenerate face)");
    }
  }
  if (in.node_ids) {
    s.ids.assign(in.node_ids, in.node_ids + in.n_nodes);
  } else {
    s.ids.resize(in.n_nodes);
    for (std::size_t i = 0; i < in.n_nodes; ++i) s.ids[i] = default_first_id + (long long)i;
  }
  std::vector<long long> sorted = s.ids;
  std::sort(sorted.begin(), sorted.end());
  const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
  if (twice != sorted.end())
    throw MortarCouplingError(what + "node id " + std::to_string(*twice) + " is given twice");
  if (!sorted.empty() && sorted.front() < 0)
    throw MortarCouplingError(what + "node id " + std::to_string(sorted.front()) + " < 0");
  return s;
}

/// Non-finite coordinates and degenerate (zero length/area) faces of one surface, at the
/// coordinates x (n_nodes × dim): throws MortarCouplingError naming the first one.
void check_geometry(int dim, int side, const HostSurface& s, const double* x) {
  const std::string what = std::string("grout::MortarCoupling: ") + side_name(side) + " surface: ";
  for (std::size_t i = 0; i < s.n_nodes * dim; ++i)
    if (!std::isfinite(x[i]))
      throw MortarCouplingError(what + "coordinate " + std::to_string(i % dim) + " of row " +
                                std::to_string(i / dim) + " is " + std::to_string(x[i]));
  for (std::size_t f = 0; f < s.n_faces(); ++f) {
    const int n = s.face_nodes(f);
    double xf[max_face_nodes][3] = {}, normal[3];
    for (int a = 0; a < n; ++a)
      for (int d = 0; d < dim; ++d) xf[a][d] = x[s.faces[f * s.cols + a] * dim + d];
    if (face_normal(dim, n, xf, normal) != MortarStatus::ok) {
      std::string nodes;
      for (int a = 0; a < n; ++a) nodes += " " + std::to_string(s.faces[f * s.cols + a]);
      throw MortarCouplingError(what + "face " + std::to_string(f) + " (rows" + nodes +
                                ") is degenerate: zero " + (dim == 2 ? "length" : "area") +
                                " or no normal");
    }
  }
}

/// The optional inside points of one surface (SurfaceArrays::inside_points): each face normal
/// must point away from its face's point, n_e · (x̄_e − p_e) > 0 (x̄_e the face centroid);
/// throws MortarCouplingError naming the first face oriented into its body.
void check_inside_points(int dim, int side, const HostSurface& s, const double* points) {
  if (!points) return;
  const std::string what = std::string("grout::MortarCoupling: ") + side_name(side) + " surface: ";
  for (std::size_t f = 0; f < s.n_faces(); ++f) {
    const int n = s.face_nodes(f);
    double xf[max_face_nodes][3] = {}, normal[3], side_of = 0.0;
    for (int a = 0; a < n; ++a)
      for (int d = 0; d < dim; ++d) xf[a][d] = s.x[s.faces[f * s.cols + a] * dim + d];
    if (face_normal(dim, n, xf, normal) != MortarStatus::ok) continue;  // check_geometry's
    for (int d = 0; d < dim; ++d) {
      double centroid = 0.0;
      for (int a = 0; a < n; ++a) centroid += xf[a][d] / n;
      side_of += normal[d] * (centroid - points[f * dim + d]);
    }
    if (!(side_of > 0.0)) {
      std::string nodes;
      for (int a = 0; a < n; ++a) nodes += " " + std::to_string(s.faces[f * s.cols + a]);
      throw MortarCouplingError(
          what + "face " + std::to_string(f) + " (rows" + nodes +
          ") has its normal pointing into its body (towards its inside point): the surface is "
          "oriented inwards; reverse the node order of its faces (LINE2 x1 -> x2 has the normal "
          "(dy, -dx)/L; TRI3/QUAD4 counter-clockwise seen from outside the body)");
    }
  }
}

/// True if a face of s has zero length/area at the coordinates x: face_normal's criterion
/// (|n|² > 0 fails) without the normalisation. The values path's cheap master check.
bool has_degenerate_face(int dim, const HostSurface& s, const double* x) {
  bool degenerate = false;
  for (std::size_t f = 0; f < s.n_faces(); ++f) {
    const int* row = &s.faces[f * s.cols];
    double nn;
    if (dim == 2) {
      const double* a = x + 2 * row[0];
      const double* b = x + 2 * row[1];
      const double dx = b[0] - a[0], dy = b[1] - a[1];
      nn = dx * dx + dy * dy;
    } else {
      const bool quad = s.cols == 4 && row[3] >= 0;
      const double* p0 = x + 3 * row[0];
      const double* p1 = x + 3 * row[1];
      const double* p2 = x + 3 * row[2];
      const double* q = quad ? x + 3 * row[3] : p0;
      double u[3], v[3], c[3];
      for (int d = 0; d < 3; ++d) {  // QUAD4: diagonals; TRI3: edges (face_normal.hpp)
        u[d] = quad ? p2[d] - p0[d] : p1[d] - p0[d];
        v[d] = quad ? q[d] - p1[d] : p2[d] - p0[d];
      }
      cross_product(u, v, c);
      nn = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
    }
    degenerate = degenerate || !(nn > 0.0);
  }
  return degenerate;
}

/// The host's faces of one surface as a FaceSet (global face ids, node ids, coordinates).
FaceSet face_set(int dim, const HostSurface& s) {
  FaceSet set;
  set.dimension = dim;
  for (std::size_t f = 0; f < s.n_faces(); ++f) {
    const int n = s.face_nodes(f);
    GlobalIndex nodes[max_face_nodes];
    double x[max_face_nodes][3] = {};
    for (int a = 0; a < n; ++a) {
      const int row = s.faces[f * s.cols + a];
      nodes[a] = s.ids[row];
      for (int d = 0; d < dim; ++d) x[a][d] = s.x[row * dim + d];
    }
    set.add(s.first_face_id + (long long)f, n, nodes, x);
  }
  return set;
}

/// Appends faces of `set` to `faces` (the rows `keep` selects, all if empty).
void append_faces(const FaceSet& set, SurfaceFaces& faces, const std::vector<char>& keep = {}) {
  for (std::size_t f = 0; f < set.size(); ++f) {
    if (!keep.empty() && !keep[f]) continue;
    faces.nodes.push_back(set.nodes[f]);
    faces.num_nodes.push_back(set.num_nodes[f]);
    faces.ids.push_back(set.ids[f]);
    faces.blocks.push_back(nullptr);
  }
}

}  // namespace

/// Runs `phase`; with a communicator, an error on any rank is thrown on every rank (the lowest
/// failing rank's message), so that no rank is left waiting in a collective.
void agree_on_error(MPI_Comm comm, const std::function<void()>& phase) {
  if (comm == MPI_COMM_NULL) {
    phase();
    return;
  }
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  std::string message;
  bool failed = false;
  try {
    phase();
  } catch (const std::exception& e) {
    failed = true;
    message = e.what();
  }
  int mine = failed ? rank : size, first = size;
  MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm);
  if (first == size) return;
  int length = int(message.size());
  MPI_Bcast(&length, 1, MPI_INT, first, comm);
  message.resize(length);
  MPI_Bcast(message.data(), length, MPI_CHAR, first, comm);
  throw MortarCouplingError(rank == first ? message
                                          : "rank " + std::to_string(first) + ": " + message);
}

SurfaceArrays surface_arrays(int nodes_per_face, const std::vector<int>& faces,
                             const std::vector<double>& coordinates, int dim,
                             const std::vector<long long>& node_ids) {
  if (nodes_per_face < 1 || faces.size() % nodes_per_face != 0 || dim < 1 ||
      coordinates.size() % dim != 0)
    throw MortarCouplingError("grout::surface_arrays: " + std::to_string(faces.size()) +
                              " face entries for " + std::to_string(nodes_per_face) +
                              " nodes per face, or " + std::to_string(coordinates.size()) +
                              " coordinates for dim " + std::to_string(dim));
  SurfaceArrays s;
  s.nodes_per_face = nodes_per_face;
  s.faces = faces.data();
  s.n_faces = faces.size() / nodes_per_face;
  s.coordinates = coordinates.data();
  s.n_nodes = coordinates.size() / dim;
  if (!node_ids.empty()) {
    if (node_ids.size() != s.n_nodes)
      throw MortarCouplingError("grout::surface_arrays: " + std::to_string(node_ids.size()) +
                                " node ids for " + std::to_string(s.n_nodes) + " rows");
    s.node_ids = node_ids.data();
  }
  return s;
}

MortarCoupling::MortarCoupling(int dim, const SurfaceArrays& slave, const SurfaceArrays& master,
                               const MortarCouplingOptions& options, MPI_Comm comm)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.comm = comm;
  if (comm != MPI_COMM_NULL) {
    MPI_Comm_rank(comm, &m.rank);
    MPI_Comm_size(comm, &m.size);
  }
  agree_on_error(comm, [&] {
    const std::string what = "grout::MortarCoupling: ";
    if (!Kokkos::is_initialized())
      throw MortarCouplingError(what + "Kokkos is not initialised (Kokkos::ScopeGuard first)");
    if (dim != 2 && dim != 3)
      throw MortarCouplingError(what + "dim = " + std::to_string(dim) + " (2 or 3)");
    if (options.multipliers != MultiplierBasis::dual &&
        options.multipliers != MultiplierBasis::standard)
      throw MortarCouplingError(what + "unknown multiplier basis");
    if (options.multipliers == MultiplierBasis::standard && options.derivatives)
      throw MortarCouplingError(what +
                                "exact derivatives are available for dual multipliers only "
                                "(the AD path, evaluate_contact_mortar, integrates the dual "
                                "basis): set derivatives = false or multipliers = dual");
    if (options.integration != MortarIntegration::exact &&
        options.integration != MortarIntegration::collocation)
      throw MortarCouplingError(what + "unknown integration scheme");
    if (options.collocation_points < 1 || options.collocation_points > 64)
      throw MortarCouplingError(what + "collocation_points = " +
                                std::to_string(options.collocation_points) + " (1 … 64)");
    if (!(options.search_factor >= 0.0) || !std::isfinite(options.search_factor))
      throw MortarCouplingError(what + "search_factor = " + std::to_string(options.search_factor) +
                                " (finite, ≥ 0)");
    if (m.size > 1 && (!slave.node_ids || !master.node_ids))
      throw MortarCouplingError(what + "node_ids are required for both surfaces on " +
                                std::to_string(m.size) + " ranks");
    m.dim = dim;
    m.options = options;
    m.slave = copy_surface(dim, 0, slave, 0);
    m.master = copy_surface(dim, 1, master, (long long)slave.n_nodes);
    check_inside_points(dim, 0, m.slave, slave.inside_points);
    check_inside_points(dim, 1, m.master, master.inside_points);
    std::unordered_set<long long> slave_ids(m.slave.ids.begin(), m.slave.ids.end());
    for (long long id : m.master.ids)
      if (slave_ids.count(id))
        throw MortarCouplingError(what + "node id " + std::to_string(id) +
                                  " is on both surfaces (ids come from one numbering; a node "
                                  "belongs to one surface)");
  });
  if (comm != MPI_COMM_NULL) {  // global face ids: this rank's faces after the lower ranks'
    long long counts[2] = {(long long)m.slave.n_faces(), (long long)m.master.n_faces()};
    long long firsts[2] = {0, 0};
    MPI_Exscan(counts, firsts, 2, MPI_LONG_LONG, MPI_SUM, comm);
    if (m.rank > 0) m.slave.first_face_id = firsts[0], m.master.first_face_id = firsts[1];
  }
  // Owners of the nodes (the lowest rank passing each as a row) for ForceSum::owners, and
  // the sums by id of row_status.
  std::vector<long long> ids = m.slave.ids;
  ids.insert(ids.end(), m.master.ids.begin(), m.master.ids.end());
  m.directory = NodeDirectory(comm, ids);
  m.slave_owner.assign(m.directory.owners().begin(),
                       m.directory.owners().begin() + m.slave.n_nodes);
  m.master_owner.assign(m.directory.owners().begin() + m.slave.n_nodes, m.directory.owners().end());
  if (options.derivatives) {  // the orientation check on a values coupling of the same surfaces
    MortarCouplingOptions values = options;
    values.derivatives = false;
    const MortarCoupling probe(dim, slave, master, values, comm);
  }
  update(m.slave.x, m.master.x);
  if (!options.derivatives) check_orientation();
}

MortarCoupling::~MortarCoupling() = default;
MortarCoupling::MortarCoupling(MortarCoupling&&) noexcept = default;
MortarCoupling& MortarCoupling::operator=(MortarCoupling&&) noexcept = default;

void MortarCoupling::update(const std::vector<double>& slave_coordinates,
                            const std::vector<double>& master_coordinates) {
  const Impl& m = *impl_;
  agree_on_error(m.comm, [&] {
    if (slave_coordinates.size() != m.slave.n_nodes * m.dim ||
        master_coordinates.size() != m.master.n_nodes * m.dim)
      throw MortarCouplingError(
          "grout::MortarCoupling::update: " + std::to_string(slave_coordinates.size()) +
          " slave and " + std::to_string(master_coordinates.size()) + " master coordinates, " +
          std::to_string(m.slave.n_nodes * m.dim) + " and " +
          std::to_string(m.master.n_nodes * m.dim) + " expected (n_nodes × dim)");
  });
  update(slave_coordinates.data(), master_coordinates.data());
}

void MortarCoupling::update(const double* slave_coordinates, const double* master_coordinates) {
  Impl& m = *impl_;
  // The distributed and derivative paths keep a copy of the coordinates (the parallel search
  // and evaluate_contact_mortar read the face sets); the serial values path reads the host's
  // arrays once, into the kernels' View, and checks them on the way (refresh_coordinates).
  const bool copy = m.comm != MPI_COMM_NULL || m.options.derivatives || !m.built;
  agree_on_error(m.comm, [&] {
    if ((m.slave.n_nodes > 0 && !slave_coordinates) ||
        (m.master.n_nodes > 0 && !master_coordinates))
      throw MortarCouplingError("grout::MortarCoupling::update: null coordinates");
    if (!copy) return;
    if (slave_coordinates != m.slave.x.data())
      std::copy(slave_coordinates, slave_coordinates + m.slave.x.size(), m.slave.x.begin());
    if (master_coordinates != m.master.x.data())
      std::copy(master_coordinates, master_coordinates + m.master.x.size(), m.master.x.begin());
    check_geometry(m.dim, 0, m.slave, m.slave.x.data());
    check_geometry(m.dim, 1, m.master, m.master.x.data());
  });
  if (copy) slave_coordinates = m.slave.x.data(), master_coordinates = m.master.x.data();
  if (m.comm != MPI_COMM_NULL || !m.built) m.build();
  agree_on_error(m.comm, [&] {
    const bool finite = m.refresh_coordinates(slave_coordinates, master_coordinates);
    if (!copy && (!finite || has_degenerate_face(m.dim, m.master, master_coordinates))) {
      check_geometry(m.dim, 0, m.slave, slave_coordinates);
      check_geometry(m.dim, 1, m.master, master_coordinates);
    }
    m.tangents_ready = false;
    m.status_ready = false;
    if (m.options.derivatives) {
      m.evaluate_derivatives();
    } else if (!m.evaluate_values()) {  // a degenerate slave face: name it
      check_geometry(m.dim, 0, m.slave, slave_coordinates);
      throw MortarCouplingError("grout::MortarCoupling::update: a slave face has no normal");
    }
  });
  if (m.comm != MPI_COMM_NULL) m.fill_row_status();  // collective: sums by node id
}

void MortarCoupling::Impl::build() {
  const FaceSet own_slave = face_set(dim, slave), own_master = face_set(dim, master);
  SurfaceFaces slaves, masters;
  append_faces(own_slave, slaves);
  n_own_slave_faces = own_slave.size();
  if (comm == MPI_COMM_NULL) {
    append_faces(own_master, masters);
  } else {
    // The slave faces of other ranks around this rank's slave nodes (for the nodal normals),
    // and the master faces that can overlap this rank's slave faces: the driver's search.
    const double factor = options.search_factor;
    const SearchRegion region = search_region(own_slave, factor);
    const FaceSet near_slave = ghost_master_faces(own_slave, region, factor, comm);
    const FaceSet near_master = ghost_master_faces(own_master, region, factor, comm);
    std::unordered_set<long long> own_nodes(slave.ids.begin(), slave.ids.end());
    std::vector<char> neighbour(near_slave.size(), 0);
    const long long own_end = slave.first_face_id + (long long)slave.n_faces();
    for (std::size_t f = 0; f < near_slave.size(); ++f) {
      if (near_slave.ids[f] >= slave.first_face_id && near_slave.ids[f] < own_end) continue;
      for (int a = 0; a < near_slave.num_nodes[f]; ++a)
        if (own_nodes.count(near_slave.nodes[f][a])) neighbour[f] = 1;
    }
    append_faces(near_slave, slaves, neighbour);
    append_faces(near_master, masters);
    // Coordinates of the nodes that are not host rows come with the faces.
    surface = ContactSurface();
    surface.dimension = dim;
    set_slave_faces(surface, std::move(slaves));
    set_master_faces(surface, std::move(masters));
    x.assign(surface.nodes.size(), {0.0, 0.0, 0.0});
    for (const FaceSet* set : {&near_slave, &near_master})
      for (std::size_t f = 0; f < set->size(); ++f)
        for (int a = 0; a < set->num_nodes[f]; ++a) {
          const std::size_t i =
              std::lower_bound(surface.nodes.begin(), surface.nodes.end(), set->nodes[f][a]) -
              surface.nodes.begin();
          if (i < surface.nodes.size() && surface.nodes[i] == set->nodes[f][a])
            for (int d = 0; d < 3; ++d) x[i][d] = set->coordinates[f][3 * a + d];
        }
  }
  if (comm == MPI_COMM_NULL) {
    surface = ContactSurface();
    surface.dimension = dim;
    set_slave_faces(surface, std::move(slaves));
    set_master_faces(surface, std::move(masters));
    x.assign(surface.nodes.size(), {0.0, 0.0, 0.0});
  }
  surface.integrate.assign(surface.slave.size(), 0);
  std::fill(surface.integrate.begin(), surface.integrate.begin() + n_own_slave_faces, 1);

  // Host rows of the interface nodes, and the slave rows' places in the interface.
  const auto position = [&](long long id) {
    const auto it = std::lower_bound(surface.nodes.begin(), surface.nodes.end(), id);
    return it != surface.nodes.end() && *it == id ? int(it - surface.nodes.begin()) : -1;
  };
  host_row.assign(surface.nodes.size(), {-1, -1});
  slave_row_index.assign(slave.n_nodes, -1);
  slave_row_position.assign(slave.n_nodes, -1);
  for (std::size_t r = 0; r < slave.n_nodes; ++r) {
    const int i = position(slave.ids[r]);
    if (i < 0) continue;
    host_row[i] = {0, int(r)};
    slave_row_position[r] = i;
    slave_row_index[r] = surface.slave_index.at(slave.ids[r]);
  }
  for (std::size_t r = 0; r < master.n_nodes; ++r) {
    const int i = position(master.ids[r]);
    if (i >= 0) host_row[i] = {1, int(r)};
  }
  // Each slave row's own faces and its local node in them, faces in ascending order.
  row_face_offsets.assign(slave.n_nodes + 1, 0);
  row_faces.clear();
  for (std::size_t r = 0; r < slave.n_nodes; ++r) {
    const int j = slave_row_index[r];
    if (j >= 0)
      for (int f : surface.slave_node_faces[j]) {
        if (std::size_t(f) >= n_own_slave_faces) continue;
        int a = 0;
        while (surface.slave.nodes[f][a] != slave.ids[r]) ++a;
        row_faces.emplace_back(f, a);
      }
    row_face_offsets[r + 1] = int(row_faces.size());
  }
  slot.assign(surface.nodes.size(), -1);

  if (!options.derivatives) {  // the Views of the kernel launches
    // Packed pair records (integrate_pairs): LINE2 × LINE2, or QUAD4-wide in 3D (a TRI3-wide
    // variant, 13 doubles instead of 21, would double the 3D launches in one unit for a
    // kernel-bound case; the compiler then stopped inlining the 3D shape functions).
    slave_width = master_width = dim == 2 ? 2 : max_face_nodes;
    const std::size_t cols = dim == 2 ? 2 : max_face_nodes;
    const auto table = [&](const SurfaceFaces& faces, const char* label) {
      Kokkos::View<int**> v(std::string(label), faces.size(), cols);
      for (std::size_t f = 0; f < faces.size(); ++f)
        for (std::size_t a = 0; a < cols; ++a)
          v(f, a) = int(a) < faces.num_nodes[f] ? position(faces.nodes[f][a]) : -1;
      return v;
    };
    normal_faces = table(surface.slave, "grout::MortarCoupling::slave_faces");
    master_faces = table(surface.master, "grout::MortarCoupling::master_faces");
    slave_faces = Kokkos::subview(
        normal_faces, Kokkos::make_pair(std::size_t(0), n_own_slave_faces), Kokkos::ALL);
    const std::size_t n = surface.nodes.size();
    coords = Kokkos::View<double**>("grout::MortarCoupling::coords", n, dim);
    nodal_normals = Kokkos::View<double**>("grout::MortarCoupling::normals", n, dim);
    nodal_tangents = Kokkos::View<double***>("grout::MortarCoupling::tangents", n, dim - 1, dim);
    for (std::size_t i = 0; i < n; ++i)
      for (int d = 0; d < dim; ++d) coords(i, d) = x[i][d];
    own_face_rows.assign(n_own_slave_faces * slave_width, -1);
    for (std::size_t f = 0; f < n_own_slave_faces; ++f)
      for (int a = 0; a < slave_width && normal_faces(f, a) >= 0; ++a)
        if (host_row[normal_faces(f, a)].first == 0)
          own_face_rows[f * slave_width + a] = host_row[normal_faces(f, a)].second;
  }
  pattern_valid = false;  // the read-back's pattern is of the previous faces
  built = true;
}

bool MortarCoupling::Impl::refresh_coordinates(const double* xs, const double* xm) {
  const bool views = !options.derivatives;
  double nan_probe = 0.0;  // x · 0 is NaN for an infinite or NaN x, 0 otherwise
  for (std::size_t i = 0; i < host_row.size(); ++i) {
    const auto [side, row] = host_row[i];
    if (side < 0) continue;
    const double* from = (side == 0 ? xs : xm) + std::size_t(row) * dim;
    for (int d = 0; d < dim; ++d) {
      nan_probe += from[d] * 0.0;
      if (views)
        coords(i, d) = from[d];
      else
        x[i][d] = from[d];
    }
  }
  return nan_probe == 0.0;
}

int MortarCoupling::Impl::position_of(long long id) const {
  return int(std::lower_bound(surface.nodes.begin(), surface.nodes.end(), id) -
             surface.nodes.begin());
}

}  // namespace grout
