// Fuzz harness: the measured sigma0 table reader (CSV,
// ris/backscatter/sigma0_table.h), through the same loader as a library path.
#include "fuzz_input.h"
#include "ris/backscatter/library.h"
#include "ris/util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ris::fuzz::quiet_logs();
  const std::string path = ris::fuzz::write_input(ris::fuzz::as_text(data, size), ".csv");
  try {
    (void)ris::load_sigma0_source(path);
  } catch (const ris::InputError&) {
  }
  return 0;
}
