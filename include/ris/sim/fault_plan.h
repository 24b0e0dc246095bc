// Failures a run injects on purpose, so that tests can reach its failure
// paths (a block that throws on the rank computing it, an MPI worker killed
// from outside) and check that the run fails naming the block and leaves no
// output (tests/mpi_cli_test.cpp, tests/stream_acquisition_cli_test.cpp,
// docs/scale.md "Failures").
//
// One plan in the run's options (RunRequest::faults, and the streamed
// runs' SlarStreamOptions / PpiStreamOptions::faults), read from the
// environment once, at the edge: `ris simulate` calls
// fault_plan_from_environment(); the library, the server and Python never
// read these variables.
//
// Example:
//   ris::SlarStreamOptions o;
//   o.faults.line_block = 3;  // pass 1's block 3 throws
#pragma once

namespace ris {

struct FaultPlan {
  // Block b (0-based) of a pass throws on the rank computing it; -1: none.
  int line_block = -1;       // RIS_FAIL_BLOCK: the lines pass (every streamed mode)
  int geocoding_block = -1;  // RIS_FAIL_GEO_BLOCK: the geocoding pass (SLAR / SAR)
  int maps_block = -1;       // RIS_FAIL_MAPS_BLOCK: the scene-maps pass (oblique tracks)
  // RIS_KILL_BLOCK: the MPI worker handed block b of any pass dies of
  // SIGKILL before computing it (rank 0 is never killed); -1: none.
  int kill_block = -1;

  bool any() const {
    return line_block >= 0 || geocoding_block >= 0 || maps_block >= 0 || kill_block >= 0;
  }
};

// The plan the environment asks for: RIS_FAIL_BLOCK, RIS_FAIL_GEO_BLOCK,
// RIS_FAIL_MAPS_BLOCK and RIS_KILL_BLOCK, each a block index (unset or
// empty: none). Throws InputError naming the variable for a value that is
// not a non-negative integer (the earlier atoi read "x" as block 0).
FaultPlan fault_plan_from_environment();

}  // namespace ris
