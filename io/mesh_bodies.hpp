#pragma once
// The bodies of a mesh: the connected components of its elements, two elements being
// connected when they share a node (blocks that share nodes form one body; bodies that only
// touch through a contact or tied interface are separate).

#include <vector>

#include "io/mesh.hpp"

namespace grout {

/// Body index of every node, 0 .. number of bodies − 1, numbered in the order of their
/// lowest node; a node of no element is a body of its own.
std::vector<int> node_bodies(const Mesh& mesh);

}  // namespace grout
