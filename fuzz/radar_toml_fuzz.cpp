// Fuzz harness: the radar description parser (ris/sensor/radar_config.h),
// including the derived quantities `ris radar info` prints.
#include "fuzz_input.h"
#include "ris/sensor/radar_config.h"
#include "ris/util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ris::fuzz::quiet_logs();
  toml::table doc;
  if (!ris::fuzz::parse_toml(ris::fuzz::as_text(data, size), doc)) return 0;
  try {
    (void)ris::radar_from_toml(doc, "fuzz.toml");
  } catch (const ris::InputError&) {
  }
  return 0;
}
