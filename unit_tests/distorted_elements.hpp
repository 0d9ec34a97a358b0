#pragma once
// Distorted (non-affine where possible), positively oriented elements of each topology, shared
// by the element-kernel tests.

#include <random>
#include <vector>

#include "kernels/shape_functions.hpp"

namespace grout_test {

struct Element {
  grout::Topology t;
  int dim;
  std::vector<double> X;
  int nodes() const { return grout::topology_num_nodes(t); }
  int dofs() const { return nodes() * dim; }
};

/// tri3, quad4, tet4 and a jittered hex8 (fixed seed).
inline std::vector<Element> distorted_elements() {
  using grout::Topology;
  std::vector<Element> elements = {
      {Topology::tri3, 2, {0.1, -0.2, 2.1, 0.3, 0.4, 1.7}},
      {Topology::quad4, 2, {0.0, 0.0, 2.0, 0.2, 2.3, 1.8, -0.2, 1.5}},
      {Topology::tet4, 3, {0.0, 0.0, 0.0, 1.5, 0.1, 0.2, 0.3, 1.2, -0.1, 0.2, 0.3, 1.4}},
  };
  Element hex{Topology::hex8, 3, {}};
  const double cube[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                             {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(-0.15, 0.15);
  for (const auto& node : cube)
    for (int i = 0; i < 3; ++i) hex.X.push_back((i == 0 ? 2.0 : 1.0) * node[i] + jitter(rng));
  elements.push_back(hex);
  return elements;
}

}  // namespace grout_test
