// Fuzz harness: the scene description parser and builder
// (ris/scene/scene_builder.h) on arbitrary TOML. Scenes over a million cells
// are parsed but not built: building one is legitimate work whose cost the
// fuzzer's time budget cannot pay (the size guard itself is tested in
// tests/, and huge grids are the resource guard's job).
#include "fuzz_input.h"
#include "ris/scene/scene_builder.h"
#include "ris/util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ris::fuzz::quiet_logs();
  toml::table doc;
  if (!ris::fuzz::parse_toml(ris::fuzz::as_text(data, size), doc)) return 0;
  try {
    const ris::SceneDescription d = ris::parse_scene_description(doc, "fuzz.toml");
    const double cells = static_cast<double>(d.grid.rows) * static_cast<double>(d.grid.cols);
    if (cells <= 1e6) (void)ris::build_scene(d);
  } catch (const ris::InputError&) {
  }
  return 0;
}
