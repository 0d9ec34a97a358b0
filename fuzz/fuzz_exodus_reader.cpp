// Fuzz target: the Exodus mesh reader (read_exodus) on arbitrary bytes written to a file.
// Only classic netCDF files ("CDF" magic) are fuzzed: files with the HDF5 signature are
// parsed by libhdf5, which is outside Grout and not hardened against hostile files (see
// docs/robustness.md); the replay of the corpus reads them too. A bad file must end in an
// InputError; anything else is a defect.

#include <exodusII.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "fuzz/fuzz_target.hpp"
#include "io/errors.hpp"
#include "io/exodus.hpp"

namespace {

/// A private scratch file, removed at exit.
const std::string& scratch_path() {
  static const std::string path = [] {
    const char* dir = std::getenv("TMPDIR");
    std::string p = std::string(dir && *dir ? dir : "/tmp") + "/grout_fuzz_exodus_XXXXXX";
    const int fd = mkstemp(p.data());
    if (fd < 0) std::abort();
    close(fd);
    std::atexit([] { std::remove(scratch_path().c_str()); });
    return p;
  }();
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  // libFuzzer mutates classic files only; the replay (GROUT_FUZZ_REPLAY) also reads the
  // netCDF-4 files of the corpus and regressions, for Grout's own check of what they store.
#ifdef GROUT_FUZZ_REPLAY
  const bool hdf5 = size >= 8 && std::memcmp(data, "\x89HDF\r\n\x1a\n", 8) == 0;
#else
  const bool hdf5 = false;
#endif
  const bool classic = size >= 4 && data[0] == 'C' && data[1] == 'D' && data[2] == 'F';
  if (!classic && !hdf5) return 0;
  ex_opts(0);  // no Exodus messages on stderr for every rejected input
  const std::string& path = scratch_path();
  FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) std::abort();
  const bool written = std::fwrite(data, 1, size, file) == size;
  if (std::fclose(file) != 0 || !written) std::abort();
  try {
    const grout::Mesh mesh = grout::read_exodus(path);
    (void)mesh;
  } catch (const grout::InputError& e) {
    grout::fuzz::expected_error(e);  // the expected outcome for a bad file
  } catch (const std::exception& e) {
    grout::fuzz::unexpected_exception(e);
  }
  return 0;
}
