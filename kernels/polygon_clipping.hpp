#pragma once
// Intersection of two convex polygons in a plane (2D coordinates), for the 3D mortar
// segmentation (Puso & Laursen 2004, sec. 4; Popp et al. 2010, sec. 3.2, "clipping").
//
// Sutherland–Hodgman: the subject polygon is clipped successively by the half-plane left of
// every (counter-clockwise) edge (a, b) of the clip polygon,
//   s(p) = (b − a) × (p − a) ≥ 0   (inside),
// an edge p→q crossing the line contributing p + t (q − p), t = s(p) / (s(p) − s(q)).
// Robustness: |s| ≤ τ |b − a| L (L: size of the two polygons, τ = clip_on_line_tolerance)
// counts as "on the line": such a vertex is kept unchanged and never used as one end of an
// intersection, so t is only formed when s(p) and s(q) have opposite signs beyond the
// tolerance (no 0/0: coincident edges and vertices give no NaN, in values or derivatives).
// An on-line vertex where the polygon does cross the line (a clip vertex exactly on a subject
// edge) is re-formed as the intersection of the edge from its inside neighbour, so that its
// derivatives are those of one of the neighbouring configurations.
// Afterwards consecutive vertices closer than clip_merge_tolerance · L are merged and a
// result of area ≤ rel_area_tol · min(area₁, area₂) (sliver, touching at a point or edge)
// is dropped.
//
// Templated on the scalar (double or Sacado::Fad::SFad): the decisions compare values only;
// the output vertices are differentiable functions of the input vertices between
// topology changes.

#include <cmath>

#include "kernels/kernel_macros.hpp"
#include "kernels/mortar_types.hpp"

namespace grout {

constexpr double clip_on_line_tolerance = 1e-12;      ///< τ, relative
constexpr double clip_merge_tolerance = 1e-12;        ///< duplicate vertices, relative to L
constexpr double clip_sliver_area_tolerance = 1e-12;  ///< default rel_area_tol

/// \brief Signed area ½ Σ_i (p_i × p_{i+1}) of a polygon (> 0 counter-clockwise).
template <class Scalar>
GROUT_INLINE_FUNCTION Scalar polygon_signed_area(int n, const Scalar p[][2]) {
  Scalar a = 0.0;
  for (int i = 0; i < n; ++i) {
    const int j = i + 1 == n ? 0 : i + 1;
    a += p[i][0] * p[j][1] - p[j][0] * p[i][1];
  }
  return 0.5 * a;
}

/// \brief Clip polygon `subject` (n_subject vertices) by polygon `clip` (n_clip vertices),
/// both convex, in either orientation; `result` receives the convex intersection polygon,
/// counter-clockwise.
/// \pre 3 ≤ n_subject, n_clip ≤ max_clip_vertices.
/// \return ok (n_result ≥ 3); no_overlap (n_result = 0: disjoint, touching, or a sliver of
/// relative area ≤ rel_area_tol); degenerate (an input with < 3 vertices or zero area);
/// capacity_exceeded (more than max_clip_vertices result vertices; cannot happen for convex
/// tri/quad inputs).
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus clip_polygons(int n_subject, const Scalar subject[][2],
                                                 int n_clip, const Scalar clip[][2],
                                                 Scalar result[max_clip_vertices][2], int& n_result,
                                                 double rel_area_tol = clip_sliver_area_tolerance) {
  using std::abs;
  constexpr int cap = 2 * max_clip_vertices;  // working capacity (intermediate polygons)
  n_result = 0;
  if (n_subject < 3 || n_clip < 3 || n_subject > max_clip_vertices || n_clip > max_clip_vertices)
    return MortarStatus::degenerate;
  const Scalar area_s = polygon_signed_area(n_subject, subject);
  const Scalar area_c = polygon_signed_area(n_clip, clip);
  const Scalar abs_s = abs(area_s), abs_c = abs(area_c);
  // size L of the configuration: largest coordinate extent of both polygons
  Scalar lo[2] = {subject[0][0], subject[0][1]}, hi[2] = {lo[0], lo[1]};
  for (int i = 0; i < n_subject + n_clip; ++i)
    for (int d = 0; d < 2; ++d) {
      const Scalar& v = i < n_subject ? subject[i][d] : clip[i - n_subject][d];
      if (v < lo[d]) lo[d] = v;
      if (v > hi[d]) hi[d] = v;
    }
  const Scalar L = (hi[0] - lo[0]) > (hi[1] - lo[1]) ? hi[0] - lo[0] : hi[1] - lo[1];
  if (!(abs_s > 1e-14 * L * L) || !(abs_c > 1e-14 * L * L)) return MortarStatus::degenerate;

  // working copies, both counter-clockwise
  Scalar buf[2][cap][2];
  Scalar c[max_clip_vertices][2];
  int n = n_subject;
  for (int i = 0; i < n_subject; ++i) {
    const int k = area_s > 0.0 ? i : n_subject - 1 - i;
    buf[0][i][0] = subject[k][0], buf[0][i][1] = subject[k][1];
  }
  for (int i = 0; i < n_clip; ++i) {
    const int k = area_c > 0.0 ? i : n_clip - 1 - i;
    c[i][0] = clip[k][0], c[i][1] = clip[k][1];
  }
  int cur = 0;
  for (int e = 0; e < n_clip && n > 0; ++e) {
    const Scalar* a = c[e];
    const Scalar* b = c[e + 1 == n_clip ? 0 : e + 1];
    const Scalar ex = b[0] - a[0], ey = b[1] - a[1];
    const Scalar tol = double(clip_on_line_tolerance) * (abs(ex) + abs(ey)) * L;
    Scalar(*in)[2] = buf[cur];
    Scalar(*out)[2] = buf[1 - cur];
    int m = 0;
    auto side = [&](const Scalar* v) -> Scalar { return ex * (v[1] - a[1]) - ey * (v[0] - a[0]); };
    for (int i = 0; i < n; ++i) {
      const Scalar* p = in[i == 0 ? n - 1 : i - 1];  // previous vertex
      const Scalar* q = in[i];                       // current vertex
      const Scalar sp = side(p), sq = side(q);
      if ((sp < -tol && sq > tol) || (sp > tol && sq < -tol)) {  // edge p→q crosses the line
        if (m >= cap) return MortarStatus::capacity_exceeded;
        const Scalar t = sp / (sp - sq);
        out[m][0] = p[0] + t * (q[0] - p[0]);
        out[m][1] = p[1] + t * (q[1] - p[1]);
        ++m;
      }
      if (sq >= -tol) {  // q kept
        if (m >= cap) return MortarStatus::capacity_exceeded;
        out[m][0] = q[0], out[m][1] = q[1];
        if (!(sq > tol)) {
          // q on the line while the polygon crosses it at q (neighbours strictly on opposite
          // sides): take q as the intersection of the edge from the inside neighbour with the
          // line. Same value up to τ, but its derivatives are those of a crossing (those of
          // the neighbouring topology), not of an unclipped vertex.
          const Scalar* r = in[i + 1 == n ? 0 : i + 1];
          const Scalar sr = side(r);
          const Scalar* o = sp > tol && sr < -tol ? p : (sp < -tol && sr > tol ? r : nullptr);
          if (o) {
            const Scalar so = o == p ? sp : sr;
            const Scalar t = so / (so - sq);
            out[m][0] = o[0] + t * (q[0] - o[0]);
            out[m][1] = o[1] + t * (q[1] - o[1]);
          }
        }
        ++m;
      }
    }
    n = m;
    cur = 1 - cur;
  }

  // merge consecutive duplicates (also last/first)
  const Scalar merge2 = clip_merge_tolerance * clip_merge_tolerance * L * L;
  int k = 0;
  for (int i = 0; i < n; ++i) {
    const Scalar* q = buf[cur][i];
    if (k > 0) {
      const Scalar dx = q[0] - result[k - 1][0], dy = q[1] - result[k - 1][1];
      if (dx * dx + dy * dy <= merge2) continue;
    }
    if (k >= max_clip_vertices) return MortarStatus::capacity_exceeded;
    result[k][0] = q[0], result[k][1] = q[1];
    ++k;
  }
  while (k > 1) {
    const Scalar dx = result[k - 1][0] - result[0][0], dy = result[k - 1][1] - result[0][1];
    if (dx * dx + dy * dy > merge2) break;
    --k;
  }
  if (k < 3) return MortarStatus::no_overlap;
  const Scalar area = polygon_signed_area(k, result);
  const Scalar min_area = abs_s < abs_c ? abs_s : abs_c;
  if (!(area > rel_area_tol * min_area)) return MortarStatus::no_overlap;
  n_result = k;
  return MortarStatus::ok;
}

}  // namespace grout
