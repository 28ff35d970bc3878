// RenderJob outside MPI proper: what a build without MPI does when an MPI launcher starts it.
#include <doctest/doctest.h>

#include <string>

#include "test_support.h"

using namespace strata;

// Only a build without MPI can run this: one with MPI reads the same variable as its cue to join
// a job (MPI_Init), which without a real mpirun around it fails. STRATA_MPIEXEC is defined for
// the tests exactly when strata is built with MPI.
#ifndef STRATA_MPIEXEC
TEST_CASE("render job: a build without MPI started by mpirun stops at once") {
    const auto dir = test::scratchDir("no-mpi");
    const std::string render = std::string(STRATA_BINARY) + " render " +
                               test::cornellScene().string() +
                               " --width 8 --height 8 --spp 24 --out " + (dir / "out.exr").string();

    // What Open MPI's mpirun -np 2 gives its processes; rank 0 says why, once.
    const auto first = test::runCommand("OMPI_COMM_WORLD_SIZE=2 OMPI_COMM_WORLD_RANK=0 " + render);
    CHECK(first.exitCode != 0);
    CHECK(first.err ==
          "strata: this strata was built without MPI (STRATA_WITH_MPI=OFF) but was started by "
          "mpirun with 2 processes; rebuild with libopenmpi-dev installed, or run it without "
          "mpirun\n");
    // The others stop too, silently.
    const auto second = test::runCommand("OMPI_COMM_WORLD_SIZE=2 OMPI_COMM_WORLD_RANK=1 " + render);
    CHECK(second.exitCode != 0);
    CHECK(second.err.empty());
    CHECK(!std::filesystem::exists(dir / "out.exr"));

    // mpirun -np 1 is one process like any other.
    const auto alone = test::runCommand("OMPI_COMM_WORLD_SIZE=1 OMPI_COMM_WORLD_RANK=0 " + render);
    CHECK_MESSAGE(alone.exitCode == 0, alone.err);
    CHECK(std::filesystem::exists(dir / "out.exr"));
}
#endif
