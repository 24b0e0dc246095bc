// The tool built without MPI: every run is one process.
#include "process_group_start.h"

namespace ris::app {

std::unique_ptr<ProcessGroup> join_process_group(int&, char**&) {
  return nullptr;
}

}  // namespace ris::app
