#pragma once
// Element topologies and the Exodus II side numbering.
//
// Side (face/edge) local node lists follow the Exodus II convention
// (Sjaardema et al., "Exodus II: A Finite Element Data Model", SAND92-2137, fig. 4):
//   QUAD4 sides 1-4 = (1,2),(2,3),(3,4),(4,1);  TRI3 sides 1-3 = (1,2),(2,3),(3,1);
//   HEX8  sides 1-6 = (1,2,6,5),(2,3,7,6),(3,4,8,7),(1,5,8,4),(1,4,3,2),(5,6,7,8);
//   TET4  sides 1-4 = (1,2,4),(2,3,4),(1,4,3),(1,3,2).
// Node numbers above are 1-based; the tables below are 0-based. Every side is listed so
// that its normal (right-hand rule in 3D, (dx,dy) -> (dy,-dx) in 2D) points out of the
// element.

#include "kernels/kernel_macros.hpp"

namespace grout {

enum class Topology : int { line2 = 0, tri3 = 1, quad4 = 2, tet4 = 3, hex8 = 4 };

constexpr int max_element_nodes = 8;
constexpr int max_side_nodes = 4;

GROUT_INLINE_FUNCTION constexpr int topology_dimension(Topology t) {
  return t == Topology::line2 ? 1 : (t == Topology::tri3 || t == Topology::quad4) ? 2 : 3;
}

GROUT_INLINE_FUNCTION constexpr int topology_num_nodes(Topology t) {
  switch (t) {
    case Topology::line2:
      return 2;
    case Topology::tri3:
      return 3;
    case Topology::quad4:
      return 4;
    case Topology::tet4:
      return 4;
    case Topology::hex8:
      return 8;
  }
  return 0;
}

GROUT_INLINE_FUNCTION constexpr int topology_num_sides(Topology t) {
  switch (t) {
    case Topology::line2:
      return 2;
    case Topology::tri3:
      return 3;
    case Topology::quad4:
      return 4;
    case Topology::tet4:
      return 4;
    case Topology::hex8:
      return 6;
  }
  return 0;
}

/// Topology of a side of an element of topology t (tet4 -> tri3, hex8 -> quad4, 2D -> line2).
GROUT_INLINE_FUNCTION constexpr Topology side_topology(Topology t) {
  return t == Topology::tet4   ? Topology::tri3
         : t == Topology::hex8 ? Topology::quad4
                               : Topology::line2;
}

/// \brief 0-based local nodes of Exodus side `side` (1-based) of topology t.
/// \return number of side nodes, 0 if the side number is out of range.
GROUT_INLINE_FUNCTION int side_local_nodes(Topology t, int side, int nodes[max_side_nodes]) {
  constexpr int tri3[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  constexpr int quad4[4][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  constexpr int tet4[4][3] = {{0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {0, 2, 1}};
  constexpr int hex8[6][4] = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6},
                              {0, 4, 7, 3}, {0, 3, 2, 1}, {4, 5, 6, 7}};
  if (side < 1 || side > topology_num_sides(t)) return 0;
  const int s = side - 1;
  switch (t) {
    case Topology::line2:
      nodes[0] = s;
      return 1;
    case Topology::tri3:
      nodes[0] = tri3[s][0];
      nodes[1] = tri3[s][1];
      return 2;
    case Topology::quad4:
      nodes[0] = quad4[s][0];
      nodes[1] = quad4[s][1];
      return 2;
    case Topology::tet4:
      for (int i = 0; i < 3; ++i) nodes[i] = tet4[s][i];
      return 3;
    case Topology::hex8:
      for (int i = 0; i < 4; ++i) nodes[i] = hex8[s][i];
      return 4;
  }
  return 0;
}

}  // namespace grout
