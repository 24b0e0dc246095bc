// A run stopped from outside leaves no unfinished output behind.
//
// On SIGINT (Ctrl-C), SIGTERM and SIGHUP the process removes every staging
// folder and temporary file it is writing (ris/io/atomic_file.h), prints one
// line saying what it removed, and exits with 128 + the signal (130, 143,
// 129), as a shell reports a process killed by it. The signal handler only
// writes the signal's number into a pipe (async-signal-safe); a thread
// waiting on the pipe does the removal, which is not. Signal masks are left
// alone, so programs ris starts (a browser) get the usual signals.
//
// SIGXFSZ (a file past `ulimit -f`) is ignored instead of killing the
// process without a word: the write then fails with EFBIG, which the
// writer reports as an error naming the output, and the usual unwinding
// removes the staging.
//
// SIGKILL cannot be caught: what such a run leaves is removed by the next
// run writing the same output (ris/io/staging_names.h).
//
// For the command-line tool (one process, one run); an MPI rank has its own
// (apps/ris/mpi/mpi_process_group.cpp). Library users (Python) keep theirs.
#pragma once

namespace ris {

// Installs the handlers and starts the waiting thread; once per process.
void remove_outputs_on_interrupt();

}  // namespace ris
