// Uses only the header-only kernels of an installed Grout.
#include <cstdio>

#include "kernels/linear_elastic.hpp"

int main() {
  const auto c = grout::elastic_constants(210e9, 0.3, 3, false);
  std::printf("consumer_kernels: lambda = %g, mu = %g\n", c.lambda, c.mu);
  return c.mu > 0.0 ? 0 : 1;
}
