// Uses the io library and a kernel of an installed Grout.
#include <cstdio>

#include "io/errors.hpp"
#include "io/exodus.hpp"
#include "kernels/topology.hpp"

int main() {
  try {
    grout::read_exodus("no-such-file.exo");
  } catch (const grout::InputError& e) {
    int nodes[grout::max_side_nodes];
    const int n = grout::side_local_nodes(grout::Topology::hex8, 6, nodes);
    std::printf("consumer: caught '%s'; hex8 side 6 has %d nodes\n", e.what(), n);
    return n == 4 ? 0 : 1;
  }
  return 1;
}
