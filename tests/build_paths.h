// Paths of the checkout and build the tests run from.
#pragma once

namespace ris::test {

// Functions, not compile definitions on every test file: an absolute path on
// each compile line would make every checkout's objects differ and defeat the
// compiler cache shared between checkouts. Each returns a string literal.
const char* ris_exe();        // the built `ris` tool
const char* source_dir();     // the source tree's root
const char* data_dir();       // <source>/data (radars, scenes, libraries)
const char* test_data_dir();  // <source>/tests/data
// The MPI launcher `ris` was built for (mpirun), or "" when built without MPI.
const char* mpiexec();

}  // namespace ris::test
