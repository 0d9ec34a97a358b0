// Gap bands of the contact elements (parallel/contact_bands.hpp).

#include "parallel/contact_bands.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "parallel/directory.hpp"

namespace grout {

namespace {

/// A k-d tree over points stored in place: the median of each range along the range's
/// widest axis at its middle, the lower half before it, the upper half after it.
class KdTree {
 public:
  KdTree(const std::vector<double>& x, const std::vector<GlobalIndex>& ids)
      : x_(x), ids_(ids), order_(ids.size()), axis_(ids.size(), 0) {
    std::iota(order_.begin(), order_.end(), std::size_t(0));
    build(0, order_.size());
  }

  /// Squared distance from q to the nearest point whose id is not `id`.
  double nearest2(const double q[3], GlobalIndex id) const {
    double best = std::numeric_limits<double>::infinity();
    search(0, order_.size(), q, id, best);
    return best;
  }

 private:
  double at(std::size_t k, int d) const { return x_[3 * order_[k] + std::size_t(d)]; }

  void build(std::size_t lo, std::size_t hi) {
    if (hi - lo < 2) return;
    double low[3], high[3];
    for (int d = 0; d < 3; ++d) low[d] = high[d] = at(lo, d);
    for (std::size_t k = lo + 1; k < hi; ++k)
      for (int d = 0; d < 3; ++d)
        low[d] = std::min(low[d], at(k, d)), high[d] = std::max(high[d], at(k, d));
    int axis = 0;
    for (int d = 1; d < 3; ++d)
      if (high[d] - low[d] > high[axis] - low[axis]) axis = d;
    const std::size_t mid = lo + (hi - lo) / 2;
    std::nth_element(order_.begin() + std::ptrdiff_t(lo), order_.begin() + std::ptrdiff_t(mid),
                     order_.begin() + std::ptrdiff_t(hi), [&](std::size_t a, std::size_t b) {
                       return x_[3 * a + std::size_t(axis)] < x_[3 * b + std::size_t(axis)];
                     });
    axis_[mid] = axis;
    build(lo, mid);
    build(mid + 1, hi);
  }

  void search(std::size_t lo, std::size_t hi, const double q[3], GlobalIndex id,
              double& best) const {
    if (lo >= hi) return;
    const std::size_t mid = lo + (hi - lo) / 2;
    if (ids_[order_[mid]] != id) {
      double r2 = 0.0;
      for (int d = 0; d < 3; ++d) r2 += (q[d] - at(mid, d)) * (q[d] - at(mid, d));
      best = std::min(best, r2);
    }
    if (hi - lo == 1) return;
    const double off = q[axis_[mid]] - at(mid, axis_[mid]);
    // The side of the query first; the other only when its slab is nearer than the best.
    if (off < 0.0) {
      search(lo, mid, q, id, best);
      if (off * off < best) search(mid + 1, hi, q, id, best);
    } else {
      search(mid + 1, hi, q, id, best);
      if (off * off < best) search(lo, mid, q, id, best);
    }
  }

  const std::vector<double>& x_;
  const std::vector<GlobalIndex>& ids_;
  std::vector<std::size_t> order_;
  std::vector<int> axis_;
};

/// Collective. Every rank's `mine`, concatenated in rank order, on every rank.
std::vector<double> gather_all(const Comm& comm, const std::vector<double>& mine) {
  return answer(comm, std::vector<std::vector<double>>(std::size_t(comm.getSize()), mine));
}

}  // namespace

std::vector<double> nearest_distances(const std::vector<double>& points,
                                      const std::vector<GlobalIndex>& point_ids,
                                      const std::vector<double>& queries,
                                      const std::vector<GlobalIndex>& query_ids) {
  const KdTree tree(points, point_ids);
  std::vector<double> out(query_ids.size());
  for (std::size_t i = 0; i < query_ids.size(); ++i)
    out[i] = std::sqrt(tree.nearest2(&queries[3 * i], query_ids[i]));
  return out;
}

int num_gap_bands(GlobalIndex num_contact, int num_parts) {
  const GlobalIndex bands = num_contact / (64 * GlobalIndex(std::max(num_parts, 1)));
  return int(std::clamp<GlobalIndex>(bands, 1, 8));
}

std::vector<int> contact_gap_bands(const Comm& comm, const std::vector<GlobalIndex>& ids,
                                   const std::vector<double>& centroids,
                                   const std::vector<char>& slave,
                                   const std::vector<char>& master) {
  // Every rank gets the centroids and ids of every slave and master element (a surface's
  // worth each, as the contact search bins every master face on every rank).
  const auto surface = [&](const std::vector<char>& on, std::vector<double>& points,
                           std::vector<GlobalIndex>& point_ids) {
    std::vector<double> mine;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      if (!on[i]) continue;
      mine.insert(mine.end(), centroids.begin() + std::ptrdiff_t(3 * i),
                  centroids.begin() + std::ptrdiff_t(3 * i + 3));
      mine.push_back(double(ids[i]));  // exact: ids < 2^53
    }
    const std::vector<double> all = gather_all(comm, mine);
    for (std::size_t k = 0; k + 3 < all.size(); k += 4) {
      points.insert(points.end(), all.begin() + std::ptrdiff_t(k),
                    all.begin() + std::ptrdiff_t(k + 3));
      point_ids.push_back(GlobalIndex(all[k + 3]));
    }
  };
  std::vector<int> band(ids.size(), -1);
  std::vector<std::size_t> at;
  long long counts[2] = {0, 0}, totals[2] = {0, 0};  // slave and master elements
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (slave[i] || master[i]) at.push_back(i), band[i] = slave[i] ? 0 : 1;
    counts[0] += slave[i] != 0, counts[1] += master[i] != 0;
  }
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 2, counts, totals);
  if (totals[0] == 0 || totals[1] == 0) return band;
  std::vector<double> slave_points, master_points;
  std::vector<GlobalIndex> slave_ids, master_ids;
  surface(slave, slave_points, slave_ids);
  surface(master, master_points, master_ids);
  // A slave element's distance to the master surface, a master element's to the slave
  // surface (the smaller for an element on both).
  std::vector<double> d(at.size(), std::numeric_limits<double>::infinity());
  for (const bool to_master : {true, false}) {
    std::vector<double> queries;
    std::vector<GlobalIndex> query_ids;
    std::vector<std::size_t> which;
    for (std::size_t k = 0; k < at.size(); ++k) {
      const std::size_t i = at[k];
      if (!(to_master ? slave[i] : master[i])) continue;
      which.push_back(k);
      query_ids.push_back(ids[i]);
      queries.insert(queries.end(), centroids.begin() + std::ptrdiff_t(3 * i),
                     centroids.begin() + std::ptrdiff_t(3 * i + 3));
    }
    const std::vector<double> near =
        to_master ? nearest_distances(master_points, master_ids, queries, query_ids)
                  : nearest_distances(slave_points, slave_ids, queries, query_ids);
    for (std::size_t j = 0; j < which.size(); ++j) d[which[j]] = std::min(d[which[j]], near[j]);
  }
  std::vector<double> sorted = gather_all(comm, d);
  std::sort(sorted.begin(), sorted.end());
  const int bands = num_gap_bands(GlobalIndex(sorted.size()), comm.getSize());
  std::vector<double> bounds;  // band b holds the distances in [bounds[b-1], bounds[b])
  for (int b = 1; b < bands; ++b)
    bounds.push_back(sorted[sorted.size() * std::size_t(b) / std::size_t(bands)]);
  // Slave and master elements of a band in groups of their own (2 b and 2 b + 1): one cut of
  // both would fall between the bodies wherever the band's two sides lie farther apart than
  // they are wide.
  for (std::size_t k = 0; k < at.size(); ++k)
    band[at[k]] = 2 * int(std::upper_bound(bounds.begin(), bounds.end(), d[k]) - bounds.begin()) +
                  (slave[at[k]] ? 0 : 1);
  return band;
}

}  // namespace grout
