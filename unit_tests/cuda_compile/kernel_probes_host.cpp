// The kernel probes built by the host compiler with Kokkos (the normal build): the reference
// for the nvcc build of the same probes (kernel_probes.cu).
//
//   kernel_probes_host                  run the probes, print the results; exit 1 if a kernel
//                                       returned a status other than ok or a value is not finite
//   kernel_probes_host --list           print the probe names, one per line
//   kernel_probes_host --compare FILE   compare FILE (the nvcc build's output) with this build:
//                                       same probes, same counts and statuses, and every value
//                                       |a − b| ≤ 1e-14 max(|a|, |b|) + 1e-16 s (s: the largest
//                                       |value| of the probe); exit 1 otherwise
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "probe_results.hpp"

namespace {

using grout::probes::ProbeResult;

constexpr double rel_tol = 1e-14;
constexpr double scale_tol = 1e-16;

int check_probes(const std::vector<ProbeResult>& results) {
  int bad = 0;
  for (const ProbeResult& r : results) {
    const bool finite =
        std::all_of(r.values.begin(), r.values.end(), [](double v) { return std::isfinite(v); });
    if (r.failures != 0 || !finite || r.values.empty()) {
      std::fprintf(stderr, "probe %s: %d failed statuses, %s values\n", r.name.c_str(), r.failures,
                   finite ? "finite" : "non-finite");
      ++bad;
    }
  }
  return bad;
}

bool read_results(const char* path, std::vector<ProbeResult>& results) {
  std::ifstream in(path);
  if (!in) return false;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    ProbeResult r;
    std::size_t n = 0;
    if (!(s >> r.name >> n >> r.failures)) continue;
    r.values.resize(n);
    for (double& v : r.values)
      if (!(s >> v)) return false;
    results.push_back(r);
  }
  return true;
}

/// Compares `other` (nvcc build) with `ref` (this build); prints one line per probe.
int compare(const std::vector<ProbeResult>& ref, const std::vector<ProbeResult>& other) {
  int bad = 0;
  if (other.size() != ref.size()) {
    std::printf("probe count differs: %zu here, %zu in the file\n", ref.size(), other.size());
    ++bad;
  }
  for (const ProbeResult& a : ref) {
    auto it = std::find_if(other.begin(), other.end(),
                           [&](const ProbeResult& b) { return b.name == a.name; });
    if (it == other.end()) {
      std::printf("%-20s missing from the file\n", a.name.c_str());
      ++bad;
      continue;
    }
    const ProbeResult& b = *it;
    if (b.values.size() != a.values.size() || b.failures != a.failures) {
      std::printf("%-20s %zu values/%d failures here, %zu/%d in the file\n", a.name.c_str(),
                  a.values.size(), a.failures, b.values.size(), b.failures);
      ++bad;
      continue;
    }
    double s = 0.0;
    for (double v : a.values) s = std::max(s, std::abs(v));
    double worst = 0.0;  // largest |a − b| / (tolerance of that value)
    std::size_t worst_at = 0;
    for (std::size_t k = 0; k < a.values.size(); ++k) {
      const double x = a.values[k], y = b.values[k];
      const double tol = rel_tol * std::max(std::abs(x), std::abs(y)) + scale_tol * s;
      const double ratio = std::isfinite(y) ? std::abs(x - y) / (tol > 0.0 ? tol : 1e-300) : 1e300;
      if (ratio > worst) worst = ratio, worst_at = k;
    }
    const bool ok = worst <= 1.0;
    std::printf("%-20s %4zu values  worst |diff|/tol = %.3g%s\n", a.name.c_str(), a.values.size(),
                worst, ok ? "" : "  MISMATCH");
    if (!ok) {
      std::printf("  value %zu: %.17g here, %.17g in the file\n", worst_at, a.values[worst_at],
                  b.values[worst_at]);
      ++bad;
    }
  }
  return bad;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<ProbeResult> results = grout::probes::run_probes();
  if (argc == 2 && std::strcmp(argv[1], "--list") == 0) {
    for (const ProbeResult& r : results) std::printf("%s\n", r.name.c_str());
    return 0;
  }
  if (argc == 3 && std::strcmp(argv[1], "--compare") == 0) {
    std::vector<ProbeResult> other;
    if (!read_results(argv[2], other)) {
      std::fprintf(stderr, "cannot read probe results from %s\n", argv[2]);
      return 1;
    }
    const int bad = compare(results, other);
    std::printf("%s\n", bad == 0 ? "nvcc build agrees with the host build" : "MISMATCH");
    return bad == 0 ? 0 : 1;
  }
  if (argc != 1) {
    std::fprintf(stderr, "usage: %s [--list | --compare FILE]\n", argv[0]);
    return 2;
  }
  grout::probes::write_probe_results(stdout, results);
  return check_probes(results) == 0 ? 0 : 1;
}
