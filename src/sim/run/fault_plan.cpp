#include "ris/sim/fault_plan.h"

#include <fmt/format.h>

#include <charconv>
#include <cstdlib>
#include <string_view>

#include "ris/util/error.h"

namespace ris {
namespace {

// The block index in environment variable `name`; -1 when unset or empty.
int block_from_environment(const char* name) {
  const char* v = std::getenv(name);
  if (v == nullptr || *v == '\0') return -1;
  const std::string_view text(v);
  int block = -1;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), block);
  if (ec != std::errc() || end != text.data() + text.size() || block < 0) {
    throw InputError("", name,
                     fmt::format("expected a block index (a non-negative integer), got '{}'; "
                                 "unset it for a run without injected failures",
                                 text));
  }
  return block;
}

}  // namespace

FaultPlan fault_plan_from_environment() {
  FaultPlan p;
  p.line_block = block_from_environment("RIS_FAIL_BLOCK");
  p.geocoding_block = block_from_environment("RIS_FAIL_GEO_BLOCK");
  p.maps_block = block_from_environment("RIS_FAIL_MAPS_BLOCK");
  p.kill_block = block_from_environment("RIS_KILL_BLOCK");
  return p;
}

}  // namespace ris
