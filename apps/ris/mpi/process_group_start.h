// How the tool joins the processes of a run (ris/util/process_group.h): an
// MPI job when built with MPI (mpi_process_group.cpp) and started by a
// launcher (mpirun, srun), else the single process (single_process_group.cpp).
#pragma once

#include <memory>

#include "ris/util/process_group.h"

namespace ris::app {

// The MPI job this process belongs to, or nullptr (no MPI in this build, or
// not started by an MPI launcher). Its destructor ends MPI's part of the run.
std::unique_ptr<ProcessGroup> join_process_group(int& argc, char**& argv);

}  // namespace ris::app
