// `ris bench` (the default bench): the quad-pol coherent SAR against the
// single-pol coherent SAR of the same scene (issue 33's goal: at most 3 x).
#pragma once

#include <string>

namespace ris::app {

// The shipped town with its quad-pol radar, the simulation only (no
// products): median seconds of each over `repeats` runs on 2 threads, and
// their ratio.
void run_quad_pol_bench(const std::string& data_dir, int repeats);

}  // namespace ris::app
