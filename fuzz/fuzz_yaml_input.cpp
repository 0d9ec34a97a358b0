// Fuzz target: the YAML input reader (read_input_text) on arbitrary bytes. A bad input must
// end in an InputError; any other exception, a crash, a sanitizer report, a hang or a large
// allocation is a defect.

#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz/fuzz_target.hpp"
#include "io/errors.hpp"
#include "io/input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const grout::Input input = grout::read_input_text(text, "fuzz.yaml");
    (void)input;
  } catch (const grout::InputError& e) {
    grout::fuzz::expected_error(e);  // the expected outcome for bad input
  } catch (const std::exception& e) {
    grout::fuzz::unexpected_exception(e);
  }
  return 0;
}
