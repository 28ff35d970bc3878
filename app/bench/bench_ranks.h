#pragma once
// `strata bench`, MPI: the same render as one plain process, as 1 rank and as 2 ranks under
// mpiexec on this machine (threads split so that every run uses the same cores), each timed as a
// whole process from start to exit, runs alternated. What the ranks cost on one machine: the
// scene is read once and broadcast, each rank builds its own BVH, and rank 0 reduces the buffers.
#include <filesystem>
#include <string>

namespace strata {

struct RankSettings {
    std::filesystem::path scene;
    int depth = 5;
    int width = 256;
    int height = 256;
    int spp = 240;  // 10 passes: the 2 ranks get 5 each
    int repeats = 3;
    int threads = 0;  // 0: all cores
    std::filesystem::path outDir;
};

// The markdown section for the summary, or a note why it could not run (a build without MPI,
// mpiexec failing).
std::string runRankComparison(const RankSettings& settings);

}  // namespace strata
