#pragma once
// The two-block contact inputs of the tests, on grout_mesh's two-block meshes (lower E = 1000,
// upper E = 3000, ν = 0.3; slave = upper bottom): two_block_bodies alone
// (test_mechanics_jacobian.cpp sets the state itself), and two_block_input for the condensation
// tests (test_condensed_solve.cpp, test_condensed_symmetric.cpp): lower bottom fixed, upper top
// pressed down (and held sideways), the x = 0 sides on rollers (so slave nodes have a
// prescribed dof).

#include <string>

#include "io/expression.hpp"
#include "io/input.hpp"

namespace grout {

/// u_component = value (an expression in t) on a node set of the input.
inline void add_dirichlet(Input& input, const std::string& set, int component,
                          const std::string& value) {
  DirichletInput d;
  d.name = set + "_" + std::to_string(component);
  d.node_set = set;
  d.component = component;
  d.value = Expression(value, "test: " + d.name);
  input.dirichlet.push_back(d);
}

/// The two bodies and their contact interface, no boundary conditions; under strain: finite
/// both are Neo-Hookean.
inline Input two_block_bodies(int dim, ContactKind type, double mu, ContactGeometry geometry,
                              StrainKind strain = StrainKind::small) {
  Input input;
  input.file = "test.yaml";
  input.model.dimension = dim;
  input.model.strain = strain;
  for (const char* block : {"lower", "upper"}) {
    MaterialInput m;
    m.name = block;
    m.block = block;
    m.youngs_modulus = std::string(block) == "lower" ? 1000.0 : 3000.0;
    m.poissons_ratio = 0.3;
    if (strain == StrainKind::finite) m.law = MaterialLaw::neo_hookean;
    input.materials.push_back(m);
  }
  ContactInput c;
  c.name = "interface";
  c.slave = "upper_bottom";
  c.master = "lower_top";
  c.geometry = geometry;
  c.type = type;
  c.friction_coefficient = mu;
  input.contact.push_back(c);
  return input;
}

inline Input two_block_input(int dim, ContactKind type, double mu, ContactGeometry geometry) {
  Input input = two_block_bodies(dim, type, mu, geometry);
  for (int c = 0; c < dim; ++c) add_dirichlet(input, "lower_bottom", c, "0");
  for (int c = 0; c < dim - 1; ++c) add_dirichlet(input, "upper_top", c, "0");
  add_dirichlet(input, "upper_top", dim - 1, "-0.01*t");
  add_dirichlet(input, dim == 2 ? "lower_left" : "lower_xmin", 0, "0");
  add_dirichlet(input, dim == 2 ? "upper_left" : "upper_xmin", 0, "0");
  return input;
}

}  // namespace grout
