#pragma once
// Host side of the kernel probes: runs every probe of GROUT_KERNEL_PROBES on the host and
// writes the results, one line per probe:
//   <name> <number of values> <failed statuses> <value> <value> ...   (values as %.17g)
// Included by both host programs (kernel_probes_host.cpp with g++ and Kokkos,
// kernel_probes.cu's main with nvcc and no Kokkos), so that they print the same format.

#include <cstdio>
#include <string>
#include <vector>

#include "kernel_probes.hpp"

namespace grout {
namespace probes {

struct ProbeResult {
  std::string name;
  std::vector<double> values;
  int failures = 0;
};

/// Runs probe `f` on the host.
template <class Probe>
ProbeResult run_probe(const char* name, Probe f) {
  ProbeResult r;
  r.name = name;
  r.values.assign(max_probe_values, 0.0);
  ProbeOutput out{r.values.data()};
  f(out);
  r.values.resize(out.n < max_probe_values ? out.n : max_probe_values);
  r.failures = out.failures + (out.n > max_probe_values ? 1 : 0);
  return r;
}

/// All probes, in the order of GROUT_KERNEL_PROBES.
inline std::vector<ProbeResult> run_probes() {
  std::vector<ProbeResult> results;
#define GROUT_RUN_PROBE(name) results.push_back(run_probe(#name, probe_##name));
  GROUT_KERNEL_PROBES(GROUT_RUN_PROBE)
#undef GROUT_RUN_PROBE
  return results;
}

inline void write_probe_results(std::FILE* f, const std::vector<ProbeResult>& results) {
  for (const ProbeResult& r : results) {
    std::fprintf(f, "%s %zu %d", r.name.c_str(), r.values.size(), r.failures);
    for (double v : r.values) std::fprintf(f, " %.17g", v);
    std::fprintf(f, "\n");
  }
}

}  // namespace probes
}  // namespace grout
