// Fuzz harness: the backscatter library loader (ris/backscatter/library.h):
// categories, models and their parameters, dielectric tables; each source
// that loads is evaluated once per category so that the models' own checks
// run too.
#include "fuzz_input.h"
#include "ris/backscatter/library.h"
#include "ris/util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ris::fuzz::quiet_logs();
  const std::string path = ris::fuzz::write_input(ris::fuzz::as_text(data, size), ".toml");
  try {
    (void)ris::load_sigma0_source(path);
  } catch (const ris::InputError&) {
  }
  return 0;
}
