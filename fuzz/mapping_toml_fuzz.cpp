// Fuzz harness: the land-cover mapping reader (ris/scene/landcover.h) that
// turns a classification raster's codes into library categories.
#include "fuzz_input.h"
#include "ris/scene/landcover.h"
#include "ris/util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ris::fuzz::quiet_logs();
  const std::string path = ris::fuzz::write_input(ris::fuzz::as_text(data, size), ".toml");
  try {
    (void)ris::read_landcover_mapping(path);
  } catch (const ris::InputError&) {
  }
  return 0;
}
