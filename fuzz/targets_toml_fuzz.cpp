// Fuzz harness: the point-target list parser (ris/sim/point_target.h).
#include "fuzz_input.h"
#include "ris/sim/point_target.h"
#include "ris/util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ris::fuzz::quiet_logs();
  toml::table doc;
  if (!ris::fuzz::parse_toml(ris::fuzz::as_text(data, size), doc)) return 0;
  try {
    (void)ris::point_targets_from_toml(doc, "fuzz.toml");
  } catch (const ris::InputError&) {
  }
  return 0;
}
