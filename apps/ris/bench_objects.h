// `ris bench --objects`: rays per second of the SBR tracer (src/objects/sbr.cpp)
// on 2 threads over a mesh of a few thousand triangles.
#pragma once

namespace ris::app {

void run_objects_bench(int repeats);

}  // namespace ris::app
