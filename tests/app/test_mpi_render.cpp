// `mpirun -np 2 strata render` on this machine (loopback and shared memory only), against the
// single-process render. Built only with STRATA_WITH_MPI.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "io/image_io.h"
#include "test_support.h"

using namespace strata;

namespace {

// Shared memory between the ranks (no TCP transport) and no single-copy (CMA needs ptrace rights
// that containers often lack); root and more ranks than cores are fine in CI. `timeout` turns a
// hang into a failure.
std::string mpirun() {
    return "OMPI_MCA_btl=self,vader OMPI_MCA_btl_vader_single_copy_mechanism=none timeout 300 " +
           std::string(STRATA_MPIEXEC) + " --allow-run-as-root --oversubscribe --bind-to none";
}

std::string strataBinary() { return STRATA_BINARY; }

size_t occurrences(const std::string& text, const std::string& part) {
    size_t count = 0;
    for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) {
        ++count;
    }
    return count;
}

// The last line of `text` that starts with `prefix`, "" when there is none.
std::string lastLineStartingWith(const std::string& text, const std::string& prefix) {
    std::istringstream lines(text);
    std::string last;
    for (std::string line; std::getline(lines, line);) {
        if (line.starts_with(prefix)) last = line;
    }
    return last;
}

}  // namespace

// Why not bit-identical, and this bound: app/render_job.cpp, RenderJob::reduce. Each double sum
// differs from the single process's by at most 2*gamma_{n-1} (5.3e-14 relative at 120 spp), so
// each float pixel channel is the same float or the next one up or down.
TEST_CASE("mpi render: 2 ranks give the single-process image and the job's progress") {
    const auto dir = test::scratchDir("mpi-equal");
    // 5 passes: rank 0 renders 3, rank 1 renders 2.
    const std::string arguments = "render " + test::cornellScene().string() +
                                  " --width 24 --height 20 --spp 120 --seed 11 --threads 1 --json";
    const auto single = test::runStrata(arguments + " --out " + (dir / "single.exr").string());
    REQUIRE_MESSAGE(single.exitCode == 0, single.err);
    const auto distributed = test::runCommand(mpirun() + " -np 2 " + strataBinary() + " " +
                                              arguments + " --out " + (dir / "mpi.exr").string());
    REQUIRE_MESSAGE(distributed.exitCode == 0, distributed.err);
    CHECK(distributed.out.find("\"ranks\":2") != std::string::npos);
    CHECK(occurrences(distributed.out, "\"paths\":") == 1);  // one report, from rank 0
    CHECK(distributed.out.find("\"paths\":57600,") != std::string::npos);  // 24*20*120: all ranks
    CHECK(occurrences(distributed.err, "wrote ") == 1);
    // Rank 0's progress counts every rank's passes: its own 3 alone would end at pass 3/3.
    CHECK(lastLineStartingWith(distributed.err, "render: pass ")
              .starts_with("render: pass 5/5, 120 spp,"));

    const Image a = readExr(dir / "single.exr");
    const Image b = readExr(dir / "mpi.exr");
    REQUIRE(a.width == b.width);
    REQUIRE(a.height == b.height);
    size_t identical = 0;
    size_t lit = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            const float x = a.pixels[i][c];
            const float y = b.pixels[i][c];
            CHECK((y == x || y == std::nextafter(x, INFINITY) ||
                   y == std::nextafter(x, -INFINITY)));
            identical += x == y;
            lit += x > 0.0f;
        }
    }
    CHECK(lit > a.pixels.size());  // a lit image, not a comparison of zeros
    MESSAGE(identical << " of " << 3 * a.pixels.size() << " channels bit-identical");
}

TEST_CASE("mpi render: a failing rank ends the job with one clear error and no output") {
    const auto dir = test::scratchDir("mpi-fail");
    const auto out = dir / "out.exr";
    const std::string arguments = "render " + test::cornellScene().string() + " --width 8 --height 8 --spp 48 --out " +
                                  out.string();

    // Rank 1 alone fails (its own options differ: Open MPI's MPMD form A : B).
    const auto oneRank =
        test::runCommand(mpirun() + " -np 1 " + strataBinary() + " " + arguments + " : -np 1 " +
                         strataBinary() + " " + arguments + " --tonemap bogus");
    CHECK(oneRank.exitCode == 2);  // bad usage, on every rank: the status rank 0 gives
    CHECK(occurrences(oneRank.err, "strata: rank 1 of 2: --tonemap: unknown tonemap 'bogus'") == 1);
    CHECK(!std::filesystem::exists(out));

    // A bad scene fails on every rank: reported once.
    std::ofstream(dir / "bad.obj") << "v 0 0 0\nv 1 0 x\nv 0 1 0\nf 1 2 3\n";
    const auto badScene = test::runCommand(mpirun() + " -np 2 " + strataBinary() + " render " +
                                           (dir / "bad.obj").string() + " --out " + out.string());
    CHECK(badScene.exitCode == 1);  // bad input
    CHECK(occurrences(badScene.err, "bad.obj:2: 'x' is not a number") == 1);
    CHECK(!std::filesystem::exists(out));
}

TEST_CASE("mpi render: every rank lights the scene by the --env map rank 0 read, whatever its own folder holds") {
    // A grey square under the sky, and two different 2:1 maps of one name in two folders: each
    // rank starts in its own (Open MPI's -wdir) and is given the map by that relative name.
    const auto dir = test::scratchDir("mpi-env");
    std::ofstream(dir / "grey.obj") << "mtllib grey.mtl\nusemtl grey\nv -9 -9 0\nv 9 -9 0\nv 9 9 0\nv -9 9 0\nf 1 2 3 4\n";
    std::ofstream(dir / "grey.mtl") << "newmtl grey\nKd 0.5 0.5 0.5\n";
    std::ofstream(dir / "grey.json") << R"({"position":[0,0,5],"look_at":[0,0,0],"up":[0,1,0],"fov_y":20})";
    Image sky{8, 4, {}};
    for (int i = 0; i < 32; ++i) sky.pixels.emplace_back(0.25f * (i % 8), 0.5f, 2.0f - 0.5f * (i / 8));
    for (const char* folder : {"rank0", "other", "empty"}) std::filesystem::create_directory(dir / folder);
    writeImage(dir / "rank0" / "sky.exr", sky);
    writeImage(dir / "other" / "sky.exr", Image{8, 4, std::vector<glm::vec3>(32, glm::vec3(9.0f))});
    const std::string arguments = "render " + (dir / "grey.obj").string() +
                                  " --env sky.exr --width 16 --height 16 --spp 48 --seed 3 --threads 1";
    const auto single = test::runCommand("cd " + (dir / "rank0").string() + " && " + strataBinary() + " " +
                                         arguments + " --out " + (dir / "single.exr").string());
    REQUIRE_MESSAGE(single.exitCode == 0, single.err);
    const Image expected = readExr(dir / "single.exr");
    for (const char* otherFolder : {"empty", "other"}) {
        CAPTURE(otherFolder);
        const auto out = dir / (std::string(otherFolder) + ".exr");
        const std::string rank = strataBinary() + " " + arguments + " --out " + out.string();
        const auto distributed = test::runCommand(mpirun() + " -np 1 -wdir " + (dir / "rank0").string() + " " +
                                                  rank + " : -np 1 -wdir " + (dir / otherFolder).string() + " " + rank);
        REQUIRE_MESSAGE(distributed.exitCode == 0, distributed.err);
        const Image image = readExr(out);
        REQUIRE(image.pixels.size() == expected.pixels.size());
        size_t lit = 0;
        for (size_t i = 0; i < image.pixels.size(); ++i) {
            for (int c = 0; c < 3; ++c) {
                const float x = expected.pixels[i][c];
                const float y = image.pixels[i][c];
                CHECK((y == x || y == std::nextafter(x, INFINITY) || y == std::nextafter(x, -INFINITY)));
                lit += x > 0.0f;
            }
        }
        CHECK(lit == 3 * image.pixels.size());  // the sky lights every pixel
    }
}

TEST_CASE("mpi render: a killed rank ends the job without an output file") {
    const auto dir = test::scratchDir("mpi-kill");
    // Far more work than any machine does in the 2 s before rank 1 is killed.
    const std::string arguments = "render " + test::cornellScene().string() +
                                  " --width 128 --height 128 --spp 24000 --threads 1 --out " +
                                  (dir / "out.exr").string();
    const auto killed =
        test::runCommand(mpirun() + " -np 1 " + strataBinary() + " " + arguments +
                         " : -np 1 timeout -s KILL 2 " + strataBinary() + " " + arguments);
    CHECK(killed.exitCode != 0);
    CHECK(killed.err.find("rank 1") != std::string::npos);  // mpirun names the lost rank
    CHECK(std::filesystem::is_empty(dir));                  // no output, no temporary file
}
