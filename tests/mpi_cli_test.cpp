// `mpirun -np N ris simulate ... --stream` (docs/scale.md): every product the
// same bytes as a single process, for SLAR along the grid (heading 0) and
// across it (heading 90), SLAR with point targets, the incoherent and the
// coherent SAR (along the grid and off it), PPI (both shipped radars, a sector, point targets)
// and an acquisition's radar grid;
// a failing or killed rank fails the whole run and leaves no output. Skipped when ris was built
// without MPI.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "acquisition_paths.h"
#include "build_paths.h"
#include "folder_compare.h"
#include "test_util.h"

namespace ris {
namespace {

namespace fs = std::filesystem;

#define RIS_REQUIRE_MPI()                                                             \
  if (std::string(test::mpiexec()).empty()) {                                         \
    GTEST_SKIP() << "ris was built without MPI (install libopenmpi-dev openmpi-bin)"; \
  }

// mpirun as these tests run it: more ranks than cores (--oversubscribe),
// as root in a container (--allow-run-as-root), shared memory without the
// ptrace-based single copy a container may forbid, and a session directory
// of its own (the shell's pid): two mpiruns starting at once (ctest -j2)
// can race creating Open MPI's shared /tmp/ompi.<host>.<uid> ("mkdir ...
// File exists", orte_session_dir failed; seen once in 700 runs).
std::string mpirun(int ranks, const std::string& env = "") {
  return "env OMPI_MCA_orte_tmpdir_base=/tmp/ris-mpi-$$ "
         "OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_rmaps_base_oversubscribe=1 " +
         env + " " + test::mpiexec() + " --oversubscribe --allow-run-as-root -np " +
         std::to_string(ranks) + " ";
}

test::RunResult run_shell(const std::string& cmd) {
  test::TempDir tmp;
  const std::string log = (tmp / "out.txt").string();
  const int status = std::system((cmd + " > " + log + " 2>&1").c_str());
  test::RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.output = test::read_file(log);
  return r;
}

using test::expect_same_files;
using test::radar_with;

// A small noise scene (300 x 200 cells of 10 m, or `size`), run by one
// process and by 1, 2 and 3 ranks in blocks of 16 lines (13 or 19 blocks).
// extra_args: more options of `ris simulate` (--targets).
void expect_ranks_give_single_process_bytes(const std::string& radar, const std::string& tag,
                                            const std::string& extra_args = "",
                                            const std::string& size = "300x200") {
  test::TempDir dir;
  const std::string scene = (dir / "scene.tif").string();
  const auto s = test::run_ris("scene fractal --generator noise --size " + size +
                               " --cell-size 10 --relief 300 --base 50 -o " + scene);
  ASSERT_EQ(s.exit_code, 0) << s.output;
  const std::string args = " simulate --quiet --threads 1 --block-lines 16 --scene " + scene +
                           " --radar " + radar + " " + extra_args + " --out ";
  const auto one = test::run_ris(args + (dir / "one").string());
  ASSERT_EQ(one.exit_code, 0) << tag << "\n" << one.output;
  for (int ranks : {1, 2, 3}) {
    for (const char* schedule : {"dynamic", "interleaved"}) {
      if (ranks == 1 && std::string(schedule) == "interleaved") continue;
      const fs::path out = dir / ("np" + std::to_string(ranks) + schedule);
      const auto r = run_shell(mpirun(ranks, std::string("RIS_MPI_SCHEDULE=") + schedule) +
                               test::ris_exe() + args + out.string());
      const std::string t = tag + ", " + std::to_string(ranks) + " ranks, " + schedule;
      ASSERT_EQ(r.exit_code, 0) << t << "\n" << r.output;
      expect_same_files(dir / "one", out, t);
    }
  }
}

TEST(MpiCli, SlarAlongTheGridGivesSingleProcessBytes) {
  RIS_REQUIRE_MPI();
  test::TempDir dir;
  expect_ranks_give_single_process_bytes(
      radar_with(dir, "r.toml", "seed-fig4-5.toml", "heading = \"0 deg\"", "heading = \"0 deg\""),
      "SLAR heading 0");
}

TEST(MpiCli, SlarAcrossTheGridGivesSingleProcessBytes) {
  RIS_REQUIRE_MPI();
  test::TempDir dir;
  expect_ranks_give_single_process_bytes(
      radar_with(dir, "r.toml", "seed-fig4-5.toml", "heading = \"0 deg\"", "heading = \"90 deg\""),
      "SLAR heading 90");
}

TEST(MpiCli, IncoherentSarGivesSingleProcessBytes) {
  RIS_REQUIRE_MPI();
  test::TempDir dir;
  expect_ranks_give_single_process_bytes(
      radar_with(dir, "r.toml", "sar-x-band-stripmap.toml", "coherent = true", "coherent = false"),
      "incoherent SAR");
}

// A track off the grid axes (ris/sim/slar_stream.h, slar_stream_oblique.h)
// on 300 x 600 cells: 42 blocks of 16 lines, and the scene maps' pass (1m)
// in 3 blocks of 256 rows, both split over the ranks.
TEST(MpiCli, ObliqueSlarGivesSingleProcessBytes) {
  RIS_REQUIRE_MPI();
  test::TempDir dir;
  expect_ranks_give_single_process_bytes(
      radar_with(dir, "r.toml", "seed-fig4-5.toml", "heading = \"0 deg\"", "heading = \"30 deg\""),
      "SLAR heading 30", "", "300x600");
}

// A track along the grid at 2.5 cells a line (heading 90 deg, 25 m lines
// on 10 m cells: 8 blocks of 16 lines, each window 40 columns wide): each
// sample's map values spilled, the scene maps from pass 1m, over the ranks.
TEST(MpiCli, SpacedGridAxisSlarGivesSingleProcessBytes) {
  RIS_REQUIRE_MPI();
  test::TempDir dir;
  const std::string radar =
      radar_with(dir, "r0.toml", "seed-fig4-5.toml", "heading = \"0 deg\"", "heading = \"90 deg\"");
  std::string text = test::read_file(radar);
  text.insert(0, "azimuth_line_spacing = \"25 m\"\n");
  test::write_file(dir / "r.toml", text);
  expect_ranks_give_single_process_bytes((dir / "r.toml").string(), "SLAR heading 90, 25 m lines");
}

// Point targets over the 300 x 200-cell scene (3 x 2 km): in the open, near
// its first line and its far corner, one high above the terrain.
std::string write_targets(const test::TempDir& dir) {
  const fs::path p = dir / "targets.toml";
  test::write_file(p,
                   "[[target]]\nname = \"a\"\nposition = [500.0, 1000.0]\nrcs = 10000.0\n"
                   "[[target]]\nname = \"b\"\nposition = [1500.0, 300.0]\nheight = \"5 m\"\n"
                   "rcs_db = 35\n"
                   "[[target]]\nname = \"c\"\nposition = [2500.0, 1700.0]\nrcs = 5000.0\n"
                   "[[target]]\nname = \"d\"\nposition = [2900.0, 15.0]\nrcs = 5000.0\n"
                   "[[target]]\nname = \"e\"\nposition = [1200.0, 1990.0]\nheight = \"50 m\"\n"
                   "rcs = 300.0\n");
  return p.string();
}

// Point targets in a streamed SLAR run: each block finds the targets on its
// lines lit or hidden, rank 0 measures them (metadata.json): the same bytes.
TEST(MpiCli, PointTargetsGiveSingleProcessBytes) {
  RIS_REQUIRE_MPI();
  test::TempDir dir;
  expect_ranks_give_single_process_bytes(
      radar_with(dir, "r.toml", "seed-fig4-5.toml", "heading = \"0 deg\"", "heading = \"0 deg\""),
      "SLAR with point targets", "--targets " + write_targets(dir));
}

// Point targets on a track off the grid axes (heading 30 deg, the 300 x
// 600-cell scene of ObliqueSlarGivesSingleProcessBytes): each oblique block
// finds the targets on its lines lit or hidden, rank 0 measures them: the
// same bytes.
TEST(MpiCli, ObliquePointTargetsGiveSingleProcessBytes) {
  RIS_REQUIRE_MPI();
  test::TempDir dir;
  expect_ranks_give_single_process_bytes(
      radar_with(dir, "r.toml", "seed-fig4-5.toml", "heading = \"0 deg\"", "heading = \"30 deg\""),
      "SLAR heading 30 with point targets", "--targets " + write_targets(dir), "300x600");
}

// The coherent SAR (the shipped radar: 4 looks, NESZ) with point targets:
// each rank computes its blocks with their halo of lines and sends their
// intensity; rank 0 finishes them in line order: the same bytes.
TEST(MpiCli, CoherentSarGivesSingleProcessBytes) {
  RIS_REQUIRE_MPI();
  test::TempDir dir;
  expect_ranks_give_single_process_bytes(
      radar_with(dir, "r.toml", "sar-x-band-stripmap.toml", "coherent = true", "coherent = true"),
      "coherent SAR", "--targets " + write_targets(dir));
}

// The coherent SAR on a track off the grid axes (heading 30 deg, the 300 x
// 600-cell scene of ObliqueSlarGivesSingleProcessBytes) with point targets:
// each rank computes its oblique blocks with their halo of lines (the
// halo's map values and counts dropped) and sends their intensity and
// per-sample map values; rank 0 finishes them in line order and builds the
// scene maps (pass 1m): the same bytes.
TEST(MpiCli, ObliqueCoherentSarGivesSingleProcessBytes) {
  RIS_REQUIRE_MPI();
  test::TempDir dir;
  expect_ranks_give_single_process_bytes(radar_with(dir, "r.toml", "sar-x-band-stripmap.toml",
                                                    "heading = \"0 deg\"", "heading = \"30 deg\""),
                                         "coherent SAR heading 30",
                                         "--targets " + write_targets(dir), "300x600");
}

// The coherent SAR along the grid at 25 m lines on 10 m cells, with point
// targets: each rank's blocks spill their own lines' per-sample map values
// (the halo's dropped), rank 0 builds the scene maps (pass 1m): the same
// bytes.
TEST(MpiCli, SpacedGridAxisCoherentSarGivesSingleProcessBytes) {
  RIS_REQUIRE_MPI();
  test::TempDir dir;
  std::string text = test::read_file(
      radar_with(dir, "r0.toml", "sar-x-band-stripmap.toml", "coherent = true", "coherent = true"));
  text.insert(0, "azimuth_line_spacing = \"25 m\"\n");
  test::write_file(dir / "r.toml", text);
  expect_ranks_give_single_process_bytes((dir / "r.toml").string(), "coherent SAR, 25 m lines",
                                         "--targets " + write_targets(dir));
}

// A streamed PPI run (rays in blocks, ris/sim/ppi_stream.h) on a noise
// scene of 200 x 600 cells of 30 m (the shipped radars' site, 3 km east and
// 2.1 km north of its south-west corner; 3 blocks of 256 rows, so pass 0's
// rows are split over the ranks): one process, then 1, 2 and 3 ranks with
// each schedule, in blocks of 16 rays (`block_args`) or the default (at
// least 4 blocks a rank). extra_args: more options of `ris simulate`
// (--targets; the single process's files are then compared with an
// in-memory run's too).
void expect_ppi_ranks_give_single_process_bytes(const std::string& radar,
                                                const std::string& block_args,
                                                const std::string& tag,
                                                const std::string& extra_args = "") {
  test::TempDir dir;
  const std::string scene = (dir / "scene.tif").string();
  const auto s = test::run_ris(
      "scene fractal --generator noise --size 200x600 --cell-size 30 --relief 300 --base 50 "
      "--patches 1,2,3 -o " +
      scene);
  ASSERT_EQ(s.exit_code, 0) << s.output;
  const std::string args = " simulate --quiet --threads 1 --stream" + block_args + " --scene " +
                           scene + " --radar " + radar + " " + extra_args + " --out ";
  const auto one = test::run_ris(args + (dir / "one").string());
  ASSERT_EQ(one.exit_code, 0) << tag << "\n" << one.output;
  if (!extra_args.empty()) {  // with targets: the in-memory run's bytes too
    const auto mem = test::run_ris(" simulate --quiet --threads 1 --scene " + scene + " --radar " +
                                   radar + " " + extra_args + " --out " + (dir / "mem").string());
    ASSERT_EQ(mem.exit_code, 0) << tag << "\n" << mem.output;
    expect_same_files(dir / "mem", dir / "one", tag + ", in memory", 8);
  }
  for (int ranks : {1, 2, 3}) {
    for (const char* schedule : {"dynamic", "interleaved"}) {
      if (ranks == 1 && std::string(schedule) == "interleaved") continue;
      const fs::path out = dir / ("np" + std::to_string(ranks) + schedule);
      const auto r = run_shell(mpirun(ranks, std::string("RIS_MPI_SCHEDULE=") + schedule) +
                               test::ris_exe() + args + out.string());
      const std::string t = tag + ", " + std::to_string(ranks) + " ranks, " + schedule;
      ASSERT_EQ(r.exit_code, 0) << t << "\n" << r.output;
      expect_same_files(dir / "one", out, t, 8);  // 7 products and metadata.json
    }
  }
}

TEST(MpiCli, PpiGroundRadarGivesSingleProcessBytes) {
  RIS_REQUIRE_MPI();
  const std::string radar = std::string(test::data_dir()) + "/radars/ppi-ground-mast-30m.toml";
  expect_ppi_ranks_give_single_process_bytes(radar, " --block-lines 16", "PPI ground, 16 rays");
  expect_ppi_ranks_give_single_process_bytes(radar, "", "PPI ground, default blocks");
}

TEST(MpiCli, PpiAirborneRadarGivesSingleProcessBytes) {
  RIS_REQUIRE_MPI();
  expect_ppi_ranks_give_single_process_bytes(
      std::string(test::data_dir()) + "/radars/ppi-airborne-nav-10000ft.toml", " --block-lines 16",
      "PPI airborne");
}

TEST(MpiCli, PpiSectorGivesSingleProcessBytes) {
  RIS_REQUIRE_MPI();
  test::TempDir dir;
  expect_ppi_ranks_give_single_process_bytes(
      radar_with(dir, "r.toml", "ppi-ground-mast-30m.toml", "[scan]\n",
                 "[scan]\nstart = \"30 deg\"\nwidth = \"100 deg\"\n"),
      " --block-lines 7", "PPI sector");
}

// Point targets around the PPI site (3 km east, 2.1 km north): in the open
// within the 3 km range, one high above the terrain, one beyond the range.
std::string write_ppi_targets(const test::TempDir& dir) {
  const fs::path p = dir / "ppi-targets.toml";
  test::write_file(p,
                   "[[target]]\nname = \"a\"\nposition = [3800.0, 2600.0]\nrcs = 10000.0\n"
                   "[[target]]\nname = \"b\"\nposition = [2000.0, 3900.0]\nheight = \"5 m\"\n"
                   "rcs_db = 35\n"
                   "[[target]]\nname = \"c\"\nposition = [4500.0, 900.0]\nrcs = 5000.0\n"
                   "[[target]]\nname = \"d\"\nposition = [1500.0, 1200.0]\nheight = \"60 m\"\n"
                   "rcs = 300.0\n"
                   "[[target]]\nname = \"e\"\nposition = [3100.0, 9000.0]\nrcs = 300.0\n");
  return p.string();
}

// Point targets in a streamed PPI run: each block of rays finds the targets
// on its rays lit or hidden, rank 0 folds them in ray order (seen and
// hidden in metadata.json): the same bytes as one process, blocks of 16
// rays and the default, full circle and a sector.
TEST(MpiCli, PpiPointTargetsGiveSingleProcessBytes) {
  RIS_REQUIRE_MPI();
  test::TempDir dir;
  const std::string targets = "--targets " + write_ppi_targets(dir);
  const std::string radar = std::string(test::data_dir()) + "/radars/ppi-ground-mast-30m.toml";
  expect_ppi_ranks_give_single_process_bytes(radar, " --block-lines 16", "PPI targets, 16 rays",
                                             targets);
  expect_ppi_ranks_give_single_process_bytes(
      radar_with(dir, "r.toml", "ppi-ground-mast-30m.toml", "[scan]\n",
                 "[scan]\nstart = \"30 deg\"\nwidth = \"100 deg\"\n"),
      "", "PPI targets, sector, default blocks", targets);
}

// No folder beside `out` but the inputs: neither the output nor a staging
// folder left behind.
void expect_nothing_written(const test::TempDir& dir, const std::string& tag) {
  for (const auto& e : fs::directory_iterator(dir.path())) {
    const std::string name = e.path().filename().string();
    EXPECT_TRUE(name == "scene.tif" || name == "tall.tif" || name.ends_with(".toml"))
        << tag << ": left " << name;
  }
}

// A rank killed from outside (the OOM killer, scancel): RIS_KILL_BLOCK=b
// makes the worker given block b raise SIGKILL on itself. mpirun ends the
// other ranks (SIGTERM); rank 0 removes its staging folder on it
// (apps/ris/mpi/mpi_process_group.cpp). The run must fail, not hang (the
// test's `timeout` gives up after 120 s with status 124), name the failure
// and leave no output and no staging folder; for a SLAR and a PPI run (and a
// PPI block that throws).
TEST(MpiCli, AKilledRankFailsTheRunWithoutOutput) {
  RIS_REQUIRE_MPI();
  test::TempDir dir;
  const std::string scene = (dir / "scene.tif").string();
  ASSERT_EQ(test::run_ris("scene fractal --generator noise --size 200x140 --cell-size 30 "
                          "--relief 300 --base 50 -o " +
                          scene)
                .exit_code,
            0);
  const std::string common = std::string(test::ris_exe()) +
                             " simulate --quiet --threads 1 --stream --block-lines 16 --scene " +
                             scene + " --out " + (dir / "out").string();
  for (const std::string radar : {"seed-fig4-5.toml", "ppi-ground-mast-30m.toml"}) {
    // Block 3 is rank 1's (interleaved: block b on rank b mod 2), after rank
    // 0 has staged its output folder and written blocks 0 to 2.
    const auto r =
        run_shell("timeout 120 " + mpirun(2, "RIS_MPI_SCHEDULE=interleaved RIS_KILL_BLOCK=3") +
                  common + " --radar " + test::data_dir() + "/radars/" + radar);
    EXPECT_NE(r.exit_code, 0) << radar << "\n" << r.output;
    EXPECT_NE(r.exit_code, 124) << radar << ": the run hung\n" << r.output;
    // mpirun's message names the killed rank; rank 0's says why it stopped.
    EXPECT_NE(r.output.find("signal 9"), std::string::npos) << radar << "\n" << r.output;
    EXPECT_NE(r.output.find("stopped by signal"), std::string::npos) << radar << "\n" << r.output;
    expect_nothing_written(dir, radar + ": a killed rank");
  }
  // A PPI block that throws on rank 1 fails the run as a SLAR block does
  // (AFailingRankFailsTheRunWithoutOutput).
  const auto r = run_shell(mpirun(2, "RIS_MPI_SCHEDULE=interleaved RIS_FAIL_BLOCK=3") + common +
                           " --radar " + test::data_dir() + "/radars/ppi-ground-mast-30m.toml");
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("rank 1 of 2 failed"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("RIS_FAIL_BLOCK"), std::string::npos) << r.output;
  expect_nothing_written(dir, "a PPI worker's block");
}

TEST(MpiCli, AFailingRankFailsTheRunWithoutOutput) {
  RIS_REQUIRE_MPI();
  test::TempDir dir;
  const std::string scene = (dir / "scene.tif").string();
  ASSERT_EQ(test::run_ris("scene fractal --generator noise --size 300x200 --cell-size 10 "
                          "--relief 300 --base 50 -o " +
                          scene)
                .exit_code,
            0);
  const std::string args = std::string(test::ris_exe()) +
                           " simulate --quiet --threads 1 --block-lines 16 --scene " + scene +
                           " --out " + (dir / "out").string();
  // Block 1 fails on rank 1 (interleaved: block b on rank b mod 2), in pass
  // 1, after rank 0 has staged its output folder.
  auto r = run_shell(mpirun(2, "RIS_MPI_SCHEDULE=interleaved RIS_FAIL_BLOCK=1") + args);
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("rank 1 of 2 failed"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("RIS_FAIL_BLOCK"), std::string::npos) << r.output;
  expect_nothing_written(dir, "a worker's block");
  // A block of the geocoding pass (2b) on rank 1, after rank 0 has written
  // pass 1's products into its staging folder (a scene of 600 rows: 3
  // geocoding blocks of 256 rows).
  const std::string tall = (dir / "tall.tif").string();
  ASSERT_EQ(test::run_ris("scene fractal --generator noise --size 100x600 --cell-size 10 "
                          "--relief 300 --base 50 -o " +
                          tall)
                .exit_code,
            0);
  r = run_shell(mpirun(2, "RIS_MPI_SCHEDULE=interleaved RIS_FAIL_GEO_BLOCK=1") + test::ris_exe() +
                " simulate --quiet --threads 1 --block-lines 64 --scene " + tall + " --out " +
                (dir / "out").string());
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("rank 1 of 2 failed"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("RIS_FAIL_GEO_BLOCK"), std::string::npos) << r.output;
  expect_nothing_written(dir, "a worker's geocoding block");
  // A block of an oblique track's scene maps (pass 1m) on rank 1, after
  // rank 0 has spilled the samples' map values into its staging folder.
  const std::string oblique = radar_with(dir, "r30.toml", "seed-fig4-5.toml", "heading = \"0 deg\"",
                                         "heading = \"30 deg\"");
  r = run_shell(mpirun(2, "RIS_MPI_SCHEDULE=interleaved RIS_FAIL_MAPS_BLOCK=1") + test::ris_exe() +
                " simulate --quiet --threads 1 --block-lines 64 --scene " + tall + " --radar " +
                oblique + " --out " + (dir / "out").string());
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("rank 1 of 2 failed"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("RIS_FAIL_MAPS_BLOCK"), std::string::npos) << r.output;
  expect_nothing_written(dir, "a worker's scene maps block");
  // The same block on rank 0 (dynamic; 1 rank).
  r = run_shell(mpirun(1, "RIS_FAIL_BLOCK=1") + args);
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("RIS_FAIL_BLOCK"), std::string::npos) << r.output;
  expect_nothing_written(dir, "rank 0's block");
  // A bad input only rank 1 reads in pass 0: a backscatter table without
  // the scene's categories fails on every rank that meets one.
  test::write_file(dir / "bs.toml", "");
  r = run_shell(mpirun(2) + args + " --backscatter " + (dir / "bs.toml").string());
  EXPECT_NE(r.exit_code, 0) << r.output;
  expect_nothing_written(dir, "bad backscatter");
  // A run over several ranks without --stream is refused (each rank would
  // write the whole output).
  r = run_shell(mpirun(2) + test::ris_exe() + " simulate --quiet --scene " + scene + " --out " +
                (dir / "out").string());
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("--stream"), std::string::npos) << r.output;
  expect_nothing_written(dir, "no --stream");
}

// An acquisition run streamed (ris/sim/acquisition_stream.h): over 1, 2 and
// 3 ranks, both schedules, the single process's bytes; a block failing on
// rank 1 fails the run; over 2 ranks without --stream it is refused naming
// --stream. Neither writes anything.
TEST(MpiCli, AcquisitionRunGivesSingleProcessBytes) {
  RIS_REQUIRE_MPI();
  test::TempDir dir;
  const std::string args = " simulate --quiet --threads 1 --block-lines 16 -a " +
                           test::winnipeg_h5() + " --dem " + test::test_dem("winnipeg_dem.tif");
  const auto one = test::run_ris(args + " --out " + (dir / "one").string());
  ASSERT_EQ(one.exit_code, 0) << one.output;
  for (int ranks : {1, 2, 3}) {
    for (const char* schedule : {"dynamic", "interleaved"}) {
      if (ranks == 1 && std::string(schedule) == "interleaved") continue;
      const fs::path out = dir / ("np" + std::to_string(ranks) + schedule);
      const auto r = run_shell(mpirun(ranks, std::string("RIS_MPI_SCHEDULE=") + schedule) +
                               test::ris_exe() + args + " --out " + out.string());
      const std::string t = "acquisition, " + std::to_string(ranks) + " ranks, " + schedule;
      ASSERT_EQ(r.exit_code, 0) << t << "\n" << r.output;
      expect_same_files(dir / "one", out, t, 8);
    }
  }
  // A block failing on rank 1 (interleaved: odd blocks are rank 1's) fails
  // the whole run, naming it, and leaves no output.
  test::TempDir failed;
  const auto f = run_shell(mpirun(2, "RIS_MPI_SCHEDULE=interleaved RIS_FAIL_BLOCK=3") +
                           test::ris_exe() + args + " --out " + (failed / "out").string());
  EXPECT_NE(f.exit_code, 0) << f.output;
  EXPECT_NE(f.output.find("RIS_FAIL_BLOCK"), std::string::npos) << f.output;
  expect_nothing_written(failed, "an acquisition with a failing block");
  test::TempDir none;
  const auto r = run_shell(mpirun(2) + test::ris_exe() + " simulate --quiet -a " +
                           test::winnipeg_h5() + " --dem " + test::test_dem("winnipeg_dem.tif") +
                           " --out " + (none / "out").string());
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("--stream"), std::string::npos) << r.output;
  expect_nothing_written(none, "an acquisition over ranks without --stream");
}

}  // namespace
}  // namespace ris
