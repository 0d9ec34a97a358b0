#pragma once
// Coarse contact search: candidate (slave, master) face pairs whose enlarged bounding boxes
// overlap (docs/design.md §3, "Coarse search"), in 2D and 3D.
//
//   box(e) = [min_k x_k − δ_e, max_k x_k + δ_e],  δ_e = factor · max_d (max_k x_kd − min_k x_kd)
//
// Master boxes are binned in a uniform grid of cell size h = 4 (2D) or 2 (3D) × the mean
// enlarged master box extent, stored as a hashed CSR: cells are grouped in blocks (64×64 in 2D,
// 4×4×4 in 3D) and bucket = (hash(block) + the cell's index in its block) mod 2^p, with
// 2^p ≥ n_master (2D) or 2 n_master (3D), so that a block's cells sit in nearby buckets (the
// queries along a curve or surface touch nearby memory) while distinct blocks are spread at
// random. One pass computes the master boxes and the grid bounds, then count → exclusive prefix
// sum → fill (counting the counts down, no second reset), with Kokkos::atomic_fetch_add so any
// execution space works. The query computes each slave box on the fly and visits only the cells
// it overlaps (O(1) per query for meshes of comparable size, O(n) overall); hash collisions
// only add box tests. The passes are compiled per dimension (coarse_search dispatches on dim).
// Output: candidate lists of any length in one CRS pair (SearchCandidates): the master ids of
// slave face s are masters[offsets(s) .. offsets(s+1)), sorted ascending. The query runs twice
// (STYLE.md item 13): a first pass counts the candidates of every slave face, an exclusive
// prefix sum gives the offsets, a second pass fills and sorts each row. A master is counted once
// per slave face however many grid cells the two boxes share: only in the cell holding the lower
// corner of the boxes' intersection, and only at its first entry in that cell's bucket (a
// master whose cells collide in the hash sits in a bucket more than once). In the common case
// the counting pass instead sorts the ids into a stack row of search_row_cache (dropping
// duplicates) and keeps that row in the workspace, so the fill pass only copies it; a longer row
// is counted by the rule above and its query repeated in the fill pass (as ArborX's query with
// a buffer size: the cache is a speed-up, not a limit). A brute-force
// O(n_s n_m) reference with the same contract is provided for tests.
//
// Repeated searches (every Newton iterate, or a benchmark) pass a CoarseSearchWorkspace: its
// work arrays (master boxes, bucket offsets and cursors, entries) grow to the largest size seen
// and are reused, and so does the SearchCandidates output (its master array grows, never
// shrinks), so a search of an unchanged or smaller problem allocates nothing. The overloads
// without a workspace use a temporary one.

#include <Kokkos_Core.hpp>
#include <cmath>
#include <cstdint>
#include <string>

#include "kernels/mortar_types.hpp"
#include "kernels/surface_normals.hpp"

namespace grout {

/// \brief Enlarged bounding box of one face (see file comment). Unused dimensions stay 0.
KOKKOS_INLINE_FUNCTION void face_bounding_box(int dim, int n_nodes,
                                              const double x[max_face_nodes][3], double factor,
                                              double lo[3], double hi[3]) {
  double extent = 0.0;
  for (int d = 0; d < 3; ++d) {
    lo[d] = hi[d] = x[0][d];
    for (int k = 1; k < n_nodes; ++k) {
      lo[d] = x[k][d] < lo[d] ? x[k][d] : lo[d];
      hi[d] = x[k][d] > hi[d] ? x[k][d] : hi[d];
    }
    if (d < dim) extent = hi[d] - lo[d] > extent ? hi[d] - lo[d] : extent;
  }
  for (int d = 0; d < dim; ++d) {
    lo[d] -= factor * extent;
    hi[d] += factor * extent;
  }
}

namespace detail {
/// face_bounding_box of row f of a face table (−1 padding), read straight from coords
/// (same values as gather_face_coordinates + face_bounding_box, without the copy).
template <class Faces, class Coords>
KOKKOS_INLINE_FUNCTION void face_box(const Faces& faces, int f, const Coords& coords, int dim,
                                     double factor, double lo[3], double hi[3]) {
  const int n_cols = static_cast<int>(faces.extent(1));
  lo[2] = hi[2] = 0.0;
  const int n0 = n_cols > 0 ? faces(f, 0) : -1;
  for (int d = 0; d < dim; ++d) lo[d] = hi[d] = n0 >= 0 ? coords(n0, d) : 0.0;
  for (int k = 1; k < n_cols && k < max_face_nodes; ++k) {
    const int node = faces(f, k);
    if (node < 0 || n0 < 0) break;
    for (int d = 0; d < dim; ++d) {
      const double x = coords(node, d);
      lo[d] = x < lo[d] ? x : lo[d];
      hi[d] = x > hi[d] ? x : hi[d];
    }
  }
  double extent = 0.0;
  for (int d = 0; d < dim; ++d) extent = hi[d] - lo[d] > extent ? hi[d] - lo[d] : extent;
  for (int d = 0; d < dim; ++d) {
    lo[d] -= factor * extent;
    hi[d] += factor * extent;
  }
}
}  // namespace detail

/// \brief Closed boxes a and b (rows: lo[0..2], hi[0..2]) intersect in the first dim axes.
template <class BoxA, class BoxB>
KOKKOS_INLINE_FUNCTION bool boxes_overlap(int dim, const BoxA& a, int i, const BoxB& b, int j) {
  for (int d = 0; d < dim; ++d)
    if (a(i, d) > b(j, 3 + d) || b(j, d) > a(i, 3 + d)) return false;
  return true;
}

/// \brief Work arrays of coarse_search, reused across calls: each grows (without
/// initialisation) to the largest size requested and is never shrunk.
template <class MemorySpace>
struct CoarseSearchWorkspace {
  /// (≥ n_faces, 6); slave_boxes is kept for compatibility, coarse_search no longer fills it
  Kokkos::View<double**, MemorySpace> slave_boxes, master_boxes;
  Kokkos::View<int*, MemorySpace> offsets;    ///< (≥ n_buckets + 1) bucket → first entry
  Kokkos::View<int*, MemorySpace> cursor;     ///< (≥ n_buckets) counts, then fill cursors
  Kokkos::View<int*, MemorySpace> entries;    ///< (≥ Σ cells per master box) master ids
  Kokkos::View<int*, MemorySpace> row_cache;  ///< (≥ n_slave · search_row_cache) first ids
};

/// Candidate ids per slave face kept by the counting pass of the query (rows are longer only on
/// graded meshes; then the fill pass repeats that face's query). 2D interfaces have ~3
/// candidates per slave face, 3D ~8 (QUAD4) to ~18 (TRI3) (docs/performance.md).
constexpr int search_row_cache = 32;

namespace detail {
/// Grows v to at least n rows (contents undefined after a growth).
template <class View>
void ensure_rows(View& v, const char* label, size_t n) {
  if (v.extent(0) >= n && v.data() != nullptr) return;
  if constexpr (View::rank == 1)
    v = View(Kokkos::view_alloc(Kokkos::WithoutInitializing, std::string(label)), n);
  else
    v = View(Kokkos::view_alloc(Kokkos::WithoutInitializing, std::string(label)), n, 6);
}
}  // namespace detail

/// Writes the enlarged boxes of a face table into rows [0, n_faces) of boxes (≥ n_faces, 6),
/// launch "grout::coarse_search_boxes".
template <class ExecSpace>
void fill_face_boxes(const ExecSpace& space,
                     Kokkos::View<const int**, typename ExecSpace::memory_space> faces,
                     Kokkos::View<const double**, typename ExecSpace::memory_space> coords,
                     double factor,
                     Kokkos::View<double**, typename ExecSpace::memory_space> boxes) {
  const int dim = static_cast<int>(coords.extent(1));
  Kokkos::parallel_for(
      "grout::coarse_search_boxes", Kokkos::RangePolicy<ExecSpace>(space, 0, faces.extent(0)),
      KOKKOS_LAMBDA(const int f) {
        double x[max_face_nodes][3], lo[3], hi[3];
        const int n = gather_face_coordinates(faces, f, coords, x);
        face_bounding_box(dim, n, x, factor, lo, hi);
        for (int d = 0; d < 3; ++d) {
          boxes(f, d) = lo[d];
          boxes(f, 3 + d) = hi[d];
        }
      });
}

/// Enlarged boxes (n_faces, 6) of a face table, launch "grout::coarse_search_boxes".
template <class ExecSpace>
Kokkos::View<double**, typename ExecSpace::memory_space> compute_face_boxes(
    const ExecSpace& space, Kokkos::View<const int**, typename ExecSpace::memory_space> faces,
    Kokkos::View<const double**, typename ExecSpace::memory_space> coords, double factor) {
  Kokkos::View<double**, typename ExecSpace::memory_space> boxes("grout::face_boxes",
                                                                 faces.extent(0), 6);
  fill_face_boxes(space, faces, coords, factor, boxes);
  return boxes;
}

/// Uniform grid over the master boxes: origin, cell size, cells per axis, bucket mask.
struct SearchGrid {
  double origin[3] = {0.0, 0.0, 0.0};
  double h = 1.0, inv_h = 1.0;  ///< cell size and its inverse
  std::int64_t n_cells[3] = {1, 1, 1};
  std::uint64_t mask = 0;  ///< n_buckets − 1 (n_buckets a power of two)

  /// Cells [c_lo, c_hi] (clamped to the grid) covered along axis d by [lo, hi]; false if the
  /// interval misses the grid (or is NaN). floor(t) for t ≥ 0 is the truncation, and
  /// t ↦ (t − origin)·(1/h) is monotonic, so the binning and the query, which both use this
  /// function, see overlapping boxes in overlapping cell ranges.
  KOKKOS_INLINE_FUNCTION bool axis_cells(double lo, double hi, int d, std::int64_t& c_lo,
                                         std::int64_t& c_hi) const {
    const double a = (lo - origin[d]) * inv_h, b = (hi - origin[d]) * inv_h;
    const double last = static_cast<double>(n_cells[d] - 1);
    if (!(b >= 0.0) || !(a < last + 1.0)) return false;
    c_lo = a < 0.0 ? 0 : static_cast<std::int64_t>(a);
    c_hi = b >= last ? n_cells[d] - 1 : static_cast<std::int64_t>(b);
    return true;
  }
  /// Cell along axis d of the lower end x of an interval, computed as c_lo in axis_cells (so
  /// for x = max(lo_a, lo_b) it is the larger of the two intervals' first cells).
  KOKKOS_INLINE_FUNCTION std::int64_t lower_cell(double x, int d) const {
    const double a = (x - origin[d]) * inv_h;
    return a < 0.0 ? 0 : static_cast<std::int64_t>(a);
  }
  /// Cell range [c_lo, c_hi] (clamped to the grid) of the box [lo, hi]; false if it misses the
  /// grid.
  KOKKOS_INLINE_FUNCTION bool cell_range(const double lo[3], const double hi[3], int dim,
                                         std::int64_t c_lo[3], std::int64_t c_hi[3]) const {
    for (int d = 0; d < 3; ++d) c_lo[d] = c_hi[d] = 0;
    for (int d = 0; d < dim; ++d)
      if (!axis_cells(lo[d], hi[d], d, c_lo[d], c_hi[d])) return false;
    return true;
  }
  /// cell_range of row f of boxes (rows: lo[0..2], hi[0..2]).
  template <class Boxes>
  KOKKOS_INLINE_FUNCTION bool cell_range(const Boxes& boxes, int f, int dim, std::int64_t c_lo[3],
                                         std::int64_t c_hi[3]) const {
    for (int d = 0; d < 3; ++d) c_lo[d] = c_hi[d] = 0;
    for (int d = 0; d < dim; ++d)
      if (!axis_cells(boxes(f, d), boxes(f, 3 + d), d, c_lo[d], c_hi[d])) return false;
    return true;
  }
  /// Bucket of cell (i, j, k): cells are grouped in blocks of 2^shift[0] × 2^shift[1]
  /// (× 2^shift[2]) cells (4×4×4 in 3D, 64×64 in 2D); the bucket is the splitmix64 finaliser of
  /// the linear block index plus the cell's linear index inside its block, mod n_buckets: a
  /// block's cells get nearby buckets (locality for neighbouring queries), blocks land at
  /// random offsets (not aligned to the block size, so a sparsely used block does not reserve
  /// a whole aligned range).
  KOKKOS_INLINE_FUNCTION std::uint64_t bucket(std::int64_t i, std::int64_t j,
                                              std::int64_t k) const {
    const std::int64_t nb0 = (n_cells[0] >> shift[0]) + 1, nb1 = (n_cells[1] >> shift[1]) + 1;
    std::uint64_t z = static_cast<std::uint64_t>((i >> shift[0]) +
                                                 nb0 * ((j >> shift[1]) + nb1 * (k >> shift[2])));
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    const std::uint64_t local = static_cast<std::uint64_t>(
        (i & ((std::int64_t(1) << shift[0]) - 1)) +
        ((j & ((std::int64_t(1) << shift[1]) - 1)) << shift[0]) +
        ((k & ((std::int64_t(1) << shift[2]) - 1)) << (shift[0] + shift[1])));
    return (z + local) & mask;
  }
  int shift[3] = {2, 2, 2};  ///< log2(block cells) per axis
};

/// Reduction of the master boxes: bounds and total extent (for the grid).
struct BoxStats {
  double lo[3], hi[3], extent;
};

template <class ExecSpace>
struct BoxStatsReduce {
  using value_type = BoxStats;
  Kokkos::View<const double**, typename ExecSpace::memory_space> boxes;
  int dim;
  KOKKOS_INLINE_FUNCTION void init(value_type& v) const {
    for (int d = 0; d < 3; ++d) {
      v.lo[d] = Kokkos::Experimental::infinity<double>::value;
      v.hi[d] = -Kokkos::Experimental::infinity<double>::value;
    }
    v.extent = 0.0;
  }
  KOKKOS_INLINE_FUNCTION void join(volatile value_type& a, const volatile value_type& b) const {
    for (int d = 0; d < 3; ++d) {
      a.lo[d] = b.lo[d] < a.lo[d] ? b.lo[d] : a.lo[d];
      a.hi[d] = b.hi[d] > a.hi[d] ? b.hi[d] : a.hi[d];
    }
    a.extent += b.extent;
  }
  KOKKOS_INLINE_FUNCTION void operator()(const int f, value_type& v) const {
    double e = 0.0;
    for (int d = 0; d < dim; ++d) {
      v.lo[d] = boxes(f, d) < v.lo[d] ? boxes(f, d) : v.lo[d];
      v.hi[d] = boxes(f, 3 + d) > v.hi[d] ? boxes(f, 3 + d) : v.hi[d];
      e = boxes(f, 3 + d) - boxes(f, d) > e ? boxes(f, 3 + d) - boxes(f, d) : e;
    }
    v.extent += e;
  }
};

/// Fused master pass: writes the enlarged box of every face into rows of `boxes` and reduces
/// their BoxStats (as BoxStatsReduce over those rows).
template <class ExecSpace, int Dim>
struct FaceBoxesStatsReduce {
  using value_type = BoxStats;
  using memory_space = typename ExecSpace::memory_space;
  Kokkos::View<const int**, memory_space> faces;
  Kokkos::View<const double**, memory_space> coords;
  Kokkos::View<double**, memory_space> boxes;
  double factor;
  static constexpr int dim = Dim;
  KOKKOS_INLINE_FUNCTION void init(value_type& v) const {
    BoxStatsReduce<ExecSpace>{boxes, dim}.init(v);
  }
  KOKKOS_INLINE_FUNCTION void join(volatile value_type& a, const volatile value_type& b) const {
    BoxStatsReduce<ExecSpace>{boxes, dim}.join(a, b);
  }
  KOKKOS_INLINE_FUNCTION void operator()(const int f, value_type& v) const {
    double lo[3], hi[3];
    detail::face_box(faces, f, coords, dim, factor, lo, hi);
    double e = 0.0;
    for (int d = 0; d < 3; ++d) {
      boxes(f, d) = lo[d];
      boxes(f, 3 + d) = hi[d];
    }
    for (int d = 0; d < dim; ++d) {
      v.lo[d] = lo[d] < v.lo[d] ? lo[d] : v.lo[d];
      v.hi[d] = hi[d] > v.hi[d] ? hi[d] : v.hi[d];
      e = hi[d] - lo[d] > e ? hi[d] - lo[d] : e;
    }
    v.extent += e;
  }
};

namespace detail {
/// Grid cell size in units of the mean enlarged master box extent: larger cells mean fewer
/// cells per box (fewer bucket lookups, less memory) and more boxes per cell (more box tests).
/// Measured optimum (bench_mortar, 1e3-1e6 faces): 4 for curves (2D: the boxes per cell grow
/// like the factor), 2 for surfaces (3D: like its square).
template <int Dim>
constexpr double search_cell_factor = Dim == 2 ? 4.0 : 2.0;

/// Buckets of the hashed grid per master face (rounded up to a power of two): at least as many
/// buckets as occupied cells (a master box covers about 1.5 cells in 2D, 2-4 in 3D).
template <int Dim>
constexpr std::uint64_t search_buckets_per_master = Dim == 2 ? 1 : 2;

/// Hashed grid of n_m master boxes with known BoxStats (see bin_master_boxes).
template <int Dim, class ExecSpace>
SearchGrid bin_boxes(const ExecSpace& space,
                     Kokkos::View<const double**, typename ExecSpace::memory_space> boxes, int n_m,
                     const BoxStats& stats,
                     CoarseSearchWorkspace<typename ExecSpace::memory_space>& ws) {
  constexpr int dim = Dim;
  SearchGrid grid;
  std::uint64_t n_buckets = 1;
  while (n_buckets < search_buckets_per_master<Dim> * static_cast<std::uint64_t>(n_m))
    n_buckets *= 2;
  grid.mask = n_buckets - 1;
  if (n_m > 0) {
    double span = 0.0;
    for (int d = 0; d < dim; ++d)
      span = stats.hi[d] - stats.lo[d] > span ? stats.hi[d] - stats.lo[d] : span;
    grid.h = search_cell_factor<Dim> * stats.extent / n_m;
    if (!(grid.h > 1e-12 * span)) grid.h = span > 0.0 ? span : 1.0;  // point-like masters
    grid.inv_h = 1.0 / grid.h;
    for (int d = 0; d < dim; ++d) {
      grid.origin[d] = stats.lo[d];
      grid.n_cells[d] = static_cast<std::int64_t>((stats.hi[d] - stats.lo[d]) * grid.inv_h) + 1;
    }
  }
  if (dim == 2) {  // 64×64 cells: a curve crossing a block stays in a 16 KiB range of offsets
    grid.shift[0] = grid.shift[1] = 6;
    grid.shift[2] = 0;
  }
  detail::ensure_rows(ws.offsets, "grout::search_offsets", n_buckets + 1);
  detail::ensure_rows(ws.cursor, "grout::search_cursor", n_buckets);
  const auto offsets = ws.offsets;
  const auto cursor = ws.cursor;
  Kokkos::deep_copy(space, Kokkos::subview(cursor, Kokkos::make_pair(size_t(0), size_t(n_buckets))),
                    0);
  Kokkos::parallel_for(
      "grout::coarse_search_count", Kokkos::RangePolicy<ExecSpace>(space, 0, n_m),
      KOKKOS_LAMBDA(const int m) {
        std::int64_t a[3], b[3];
        if (!grid.cell_range(boxes, m, dim, a, b)) return;
        for (std::int64_t k = a[2]; k <= b[2]; ++k)
          for (std::int64_t j = a[1]; j <= b[1]; ++j)
            for (std::int64_t i = a[0]; i <= b[0]; ++i)
              Kokkos::atomic_fetch_add(&cursor(grid.bucket(i, j, k)), 1);
      });
  int total = 0;
  Kokkos::parallel_scan(
      "grout::coarse_search_offsets", Kokkos::RangePolicy<ExecSpace>(space, 0, n_buckets),
      KOKKOS_LAMBDA(const int b, int& partial, const bool final) {
        if (final) offsets(b) = partial;
        partial += cursor(b);
        if (final && b + 1 == static_cast<int>(n_buckets)) offsets(b + 1) = partial;
      },
      total);
  detail::ensure_rows(ws.entries, "grout::search_entries", static_cast<size_t>(total));
  const auto entries = ws.entries;
  // The counts left in cursor count down to 0: a bucket is filled from its end (the order
  // inside a bucket is irrelevant: the query sorts each candidate row).
  Kokkos::parallel_for(
      "grout::coarse_search_fill", Kokkos::RangePolicy<ExecSpace>(space, 0, n_m),
      KOKKOS_LAMBDA(const int m) {
        std::int64_t a[3], b[3];
        if (!grid.cell_range(boxes, m, dim, a, b)) return;
        for (std::int64_t k = a[2]; k <= b[2]; ++k)
          for (std::int64_t j = a[1]; j <= b[1]; ++j)
            for (std::int64_t i = a[0]; i <= b[0]; ++i) {
              const std::uint64_t bk = grid.bucket(i, j, k);
              entries(offsets(bk) + Kokkos::atomic_fetch_add(&cursor(bk), -1) - 1) = m;
            }
      });
  return grid;
}
}  // namespace detail

/// \brief Builds the hashed grid of the n_m master boxes (rows of `boxes`): counts per bucket
/// (atomic), exclusive prefix sum into ws.offsets (n_buckets + 1), fill of ws.entries (master
/// ids), all in the workspace. Launches "grout::coarse_search_bounds", "..._count",
/// "..._offsets", "..._fill".
template <class ExecSpace>
SearchGrid bin_master_boxes(const ExecSpace& space,
                            Kokkos::View<const double**, typename ExecSpace::memory_space> boxes,
                            int n_m, int dim,
                            CoarseSearchWorkspace<typename ExecSpace::memory_space>& ws) {
  BoxStats stats;
  Kokkos::parallel_reduce("grout::coarse_search_bounds",
                          Kokkos::RangePolicy<ExecSpace>(space, 0, n_m),
                          BoxStatsReduce<ExecSpace>{boxes, dim}, stats);
  return dim == 2 ? detail::bin_boxes<2>(space, boxes, n_m, stats, ws)
                  : detail::bin_boxes<3>(space, boxes, n_m, stats, ws);
}

/// bin_master_boxes into fresh offsets (n_buckets + 1) and entries arrays.
template <class ExecSpace>
SearchGrid bin_master_boxes(const ExecSpace& space,
                            Kokkos::View<const double**, typename ExecSpace::memory_space> boxes,
                            int dim, Kokkos::View<int*, typename ExecSpace::memory_space>& offsets,
                            Kokkos::View<int*, typename ExecSpace::memory_space>& entries) {
  CoarseSearchWorkspace<typename ExecSpace::memory_space> ws;
  const SearchGrid grid =
      bin_master_boxes(space, boxes, static_cast<int>(boxes.extent(0)), dim, ws);
  offsets = ws.offsets;
  entries = ws.entries;
  return grid;
}

/// \brief Candidate lists of every slave face in CRS layout (STYLE.md item 13): the master face
/// ids of slave face s are masters(offsets(s)) … masters(offsets(s + 1) − 1), ascending, and
/// offsets(n_slave) = n_pairs is the number of candidate pairs. Reused across searches:
/// offsets is reallocated when the number of slave faces changes, masters only grows.
template <class MemorySpace>
struct SearchCandidates {
  Kokkos::View<int*, MemorySpace> offsets;  ///< (n_slave + 1) first pair of each slave face
  Kokkos::View<int*, MemorySpace> masters;  ///< (≥ n_pairs) master face ids
  int n_pairs = 0;                          ///< offsets(n_slave), on the host
};

namespace detail {
/// Binned query of coarse_search for a fixed dimension. visit<false>(s, f) calls f(m) for every
/// master face m whose box overlaps the box of slave face s, once per bucket entry (a master
/// may come several times); visit<true>(s, f) calls it exactly once per such master. Both in no
/// particular order.
template <int Dim, class MemorySpace>
struct GridQuery {
  Kokkos::View<const int**, MemorySpace> slave_faces;
  Kokkos::View<const double**, MemorySpace> coords;
  Kokkos::View<const double**, MemorySpace> m_boxes;
  Kokkos::View<const int*, MemorySpace> offsets;  ///< bucket → first entry
  Kokkos::View<const int*, MemorySpace> entries;  ///< master ids per bucket
  SearchGrid grid;
  double factor;

  template <bool Once, class F>
  KOKKOS_INLINE_FUNCTION void visit(int s, F&& f) const {
    constexpr int dim = Dim;
    double lo[3], hi[3];
    face_box(slave_faces, s, coords, dim, factor, lo, hi);
    std::int64_t a[3], b[3];
    if (!grid.cell_range(lo, hi, dim, a, b)) return;
    for (std::int64_t k = a[2]; k <= b[2]; ++k)
      for (std::int64_t j = a[1]; j <= b[1]; ++j)
        for (std::int64_t i = a[0]; i <= b[0]; ++i) {
          const std::int64_t cell[3] = {i, j, k};
          const std::uint64_t bk = grid.bucket(i, j, k);
          const int first = offsets(bk), last = offsets(bk + 1);
          for (int e = first; e < last; ++e) {
            const int m = entries(e);
            bool take = true;
            for (int d = 0; d < dim && take; ++d) {
              const double m_lo = m_boxes(m, d);
              take = !(lo[d] > m_boxes(m, 3 + d) || m_lo > hi[d]);
              // Once: the intersection's lower corner lies in this cell (the cell ranges of
              // both boxes contain that cell, so exactly one visited cell passes) ...
              if (Once && take) take = grid.lower_cell(lo[d] > m_lo ? lo[d] : m_lo, d) == cell[d];
            }
            // ... and this is m's first entry in the bucket.
            if (Once)
              for (int e2 = first; e2 < e && take; ++e2) take = entries(e2) != m;
            if (take) f(m);
          }
        }
  }
};

/// Reference query: visit<Once>(s, f) tests the box of slave face s against every master box
/// and calls f(m) for each overlap, once, in ascending m.
template <class MemorySpace>
struct BruteForceQuery {
  Kokkos::View<const double**, MemorySpace> s_boxes, m_boxes;
  int dim;

  template <bool Once, class F>
  KOKKOS_INLINE_FUNCTION void visit(int s, F&& f) const {
    const int n_m = static_cast<int>(m_boxes.extent(0));
    for (int m = 0; m < n_m; ++m)
      if (boxes_overlap(dim, s_boxes, s, m_boxes, m)) f(m);
  }
};

/// \brief Inserts id into the ascending list row[0..count) of capacity search_row_cache,
/// ignoring duplicates. \return false (row unchanged) if id is new and the row is full.
KOKKOS_INLINE_FUNCTION bool insert_candidate(int row[search_row_cache], int& count, int id) {
  int pos = 0;
  while (pos < count && row[pos] < id) ++pos;
  if (pos < count && row[pos] == id) return true;
  if (count == search_row_cache) return false;
  for (int k = count; k > pos; --k) row[k] = row[k - 1];
  row[pos] = id;
  ++count;
  return true;
}

/// Count, scan, fill (STYLE.md item 13) of the candidate lists of n_s slave faces from a query
/// with visit<Once>(s, f). "grout::coarse_search_query_count" gathers the ids of slave face s
/// into a sorted, duplicate-free stack row of search_row_cache; if they fit, the row goes to
/// ws.row_cache and its length to offsets(s), else the exact count (visit<true>) does.
/// "..._query_offsets" turns the counts into exclusive prefix sums in place; "..._query_fill"
/// copies each cached row, or repeats the query of a longer one (visit<true>) and sorts it
/// (insertion sort). \return the number of pairs.
template <class ExecSpace, class Query>
int count_scan_fill(const ExecSpace& space, int n_s, const Query& query,
                    CoarseSearchWorkspace<typename ExecSpace::memory_space>& ws,
                    SearchCandidates<typename ExecSpace::memory_space>& out) {
  using Offsets = Kokkos::View<int*, typename ExecSpace::memory_space>;
  constexpr int K = search_row_cache;
  ensure_rows(ws.row_cache, "grout::search_row_cache", static_cast<size_t>(n_s) * K);
  const Offsets cache = ws.row_cache;
  if (out.offsets.extent(0) != static_cast<size_t>(n_s) + 1 || out.offsets.data() == nullptr)
    out.offsets = Offsets(
        Kokkos::view_alloc(Kokkos::WithoutInitializing, std::string("grout::candidate_offsets")),
        n_s + 1);
  const Offsets offsets = out.offsets;
  Kokkos::parallel_for(
      "grout::coarse_search_query_count", Kokkos::RangePolicy<ExecSpace>(space, 0, n_s),
      KOKKOS_LAMBDA(const int s) {
        int row[K];
        int count = 0;
        bool fits = true;
        query.template visit<false>(s, [&](int m) {
          if (fits) fits = insert_candidate(row, count, m);
        });
        if (fits) {
          for (int c = 0; c < count; ++c) cache(static_cast<size_t>(s) * K + c) = row[c];
        } else {
          count = 0;
          query.template visit<true>(s, [&](int) { ++count; });
        }
        offsets(s) = count;
      });
  int total = 0;
  // In place: the final call of s reads its count before overwriting it with the offset.
  Kokkos::parallel_scan(
      "grout::coarse_search_query_offsets", Kokkos::RangePolicy<ExecSpace>(space, 0, n_s),
      KOKKOS_LAMBDA(const int s, int& partial, const bool final) {
        const int count = offsets(s);
        if (final) offsets(s) = partial;
        partial += count;
        if (final && s + 1 == n_s) offsets(n_s) = partial;
      },
      total);
  if (n_s == 0) Kokkos::deep_copy(space, offsets, 0);
  ensure_rows(out.masters, "grout::candidate_masters", static_cast<size_t>(total));
  const Offsets masters = out.masters;
  Kokkos::parallel_for(
      "grout::coarse_search_query_fill", Kokkos::RangePolicy<ExecSpace>(space, 0, n_s),
      KOKKOS_LAMBDA(const int s) {
        const int begin = offsets(s), n = offsets(s + 1) - begin;
        if (n <= K) {
          for (int c = 0; c < n; ++c) masters(begin + c) = cache(static_cast<size_t>(s) * K + c);
          return;
        }
        int c = 0;
        query.template visit<true>(s, [&](int m) { masters(begin + c++) = m; });
        for (int p = begin + 1; p < begin + n; ++p) {
          const int id = masters(p);
          int q = p;
          for (; q > begin && masters(q - 1) > id; --q) masters(q) = masters(q - 1);
          masters(q) = id;
        }
      });
  out.n_pairs = total;
  return total;
}

/// coarse_search after the argument checks, for a fixed dimension.
template <int Dim, class ExecSpace>
void coarse_search_impl(const ExecSpace& space,
                        CoarseSearchWorkspace<typename ExecSpace::memory_space>& workspace,
                        Kokkos::View<const int**, typename ExecSpace::memory_space> slave_faces,
                        Kokkos::View<const int**, typename ExecSpace::memory_space> master_faces,
                        Kokkos::View<const double**, typename ExecSpace::memory_space> coords,
                        double factor,
                        SearchCandidates<typename ExecSpace::memory_space>& candidates) {
  using memory_space = typename ExecSpace::memory_space;
  const int n_m = static_cast<int>(master_faces.extent(0));
  detail::ensure_rows(workspace.master_boxes, "grout::master_boxes", master_faces.extent(0));
  const auto m_boxes = workspace.master_boxes;
  // One pass over the masters computes their boxes and the grid bounds; the slave boxes are
  // computed inside the query (no slave box array).
  BoxStats stats;
  Kokkos::parallel_reduce(
      "grout::coarse_search_bounds", Kokkos::RangePolicy<ExecSpace>(space, 0, n_m),
      FaceBoxesStatsReduce<ExecSpace, Dim>{master_faces, coords, m_boxes, factor}, stats);
  const SearchGrid grid = detail::bin_boxes<Dim, ExecSpace>(space, m_boxes, n_m, stats, workspace);
  const GridQuery<Dim, memory_space> query{slave_faces,       coords, m_boxes, workspace.offsets,
                                           workspace.entries, grid,   factor};
  count_scan_fill(space, static_cast<int>(slave_faces.extent(0)), query, workspace, candidates);
}
}  // namespace detail

/// \brief Candidate master faces of every slave face (binned search, see file comment), as
/// CRS lists in `candidates` (SearchCandidates: any number per slave face).
/// \pre faces: (n, ≤ max_face_nodes) node ids, −1 padding; coords (n_nodes, dim), dim ∈ {2, 3}.
/// \return degenerate for a bad dim (candidates untouched), ok otherwise.
/// The work arrays come from (and stay in) `workspace`, the output arrays are reused: no
/// allocation once both are large enough.
template <class ExecSpace>
MortarStatus coarse_search(const ExecSpace& space,
                           CoarseSearchWorkspace<typename ExecSpace::memory_space>& workspace,
                           Kokkos::View<const int**, typename ExecSpace::memory_space> slave_faces,
                           Kokkos::View<const int**, typename ExecSpace::memory_space> master_faces,
                           Kokkos::View<const double**, typename ExecSpace::memory_space> coords,
                           double factor,
                           SearchCandidates<typename ExecSpace::memory_space>& candidates) {
  const int dim = static_cast<int>(coords.extent(1));
  if (dim != 2 && dim != 3) return MortarStatus::degenerate;
  if (dim == 2)
    detail::coarse_search_impl<2>(space, workspace, slave_faces, master_faces, coords, factor,
                                  candidates);
  else
    detail::coarse_search_impl<3>(space, workspace, slave_faces, master_faces, coords, factor,
                                  candidates);
  return MortarStatus::ok;
}

/// coarse_search with a temporary workspace (allocates its work arrays on every call).
template <class ExecSpace>
MortarStatus coarse_search(const ExecSpace& space,
                           Kokkos::View<const int**, typename ExecSpace::memory_space> slave_faces,
                           Kokkos::View<const int**, typename ExecSpace::memory_space> master_faces,
                           Kokkos::View<const double**, typename ExecSpace::memory_space> coords,
                           double factor,
                           SearchCandidates<typename ExecSpace::memory_space>& candidates) {
  CoarseSearchWorkspace<typename ExecSpace::memory_space> workspace;
  return coarse_search(space, workspace, slave_faces, master_faces, coords, factor, candidates);
}

/// Default-execution-space overload of coarse_search.
inline MortarStatus coarse_search(
    Kokkos::View<const int**> slave_faces, Kokkos::View<const int**> master_faces,
    Kokkos::View<const double**> coords, double factor,
    SearchCandidates<Kokkos::DefaultExecutionSpace::memory_space>& candidates) {
  return coarse_search(Kokkos::DefaultExecutionSpace(), slave_faces, master_faces, coords, factor,
                       candidates);
}

/// Default-execution-space overload of coarse_search with a workspace.
inline MortarStatus coarse_search(
    CoarseSearchWorkspace<Kokkos::DefaultExecutionSpace::memory_space>& workspace,
    Kokkos::View<const int**> slave_faces, Kokkos::View<const int**> master_faces,
    Kokkos::View<const double**> coords, double factor,
    SearchCandidates<Kokkos::DefaultExecutionSpace::memory_space>& candidates) {
  return coarse_search(Kokkos::DefaultExecutionSpace(), workspace, slave_faces, master_faces,
                       coords, factor, candidates);
}

/// \brief Brute-force reference of coarse_search (every slave box against every master box,
/// O(n_s n_m)), same outputs and status; launches "grout::coarse_search_query_*". Tests only.
template <class ExecSpace>
MortarStatus coarse_search_brute_force(
    const ExecSpace& space, Kokkos::View<const int**, typename ExecSpace::memory_space> slave_faces,
    Kokkos::View<const int**, typename ExecSpace::memory_space> master_faces,
    Kokkos::View<const double**, typename ExecSpace::memory_space> coords, double factor,
    SearchCandidates<typename ExecSpace::memory_space>& candidates) {
  const int dim = static_cast<int>(coords.extent(1));
  if (dim != 2 && dim != 3) return MortarStatus::degenerate;
  const detail::BruteForceQuery<typename ExecSpace::memory_space> query{
      compute_face_boxes(space, slave_faces, coords, factor),
      compute_face_boxes(space, master_faces, coords, factor), dim};
  CoarseSearchWorkspace<typename ExecSpace::memory_space> workspace;
  detail::count_scan_fill(space, static_cast<int>(slave_faces.extent(0)), query, workspace,
                          candidates);
  return MortarStatus::ok;
}

}  // namespace grout
