// `ris bench --objects`: rays per second of the SBR tracer (src/objects/sbr.cpp)
// on 2 threads over a mesh of a few thousand triangles.
#pragma once

#include <string>

namespace ris::app {

void run_objects_bench(int repeats);
// The shipped town's objects as a run traces them (seconds, rays/s).
void run_town_bench(const std::string& data_dir);

}  // namespace ris::app
