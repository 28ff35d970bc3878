// `strata render`'s outputs: checked before anything is read or rendered, written through
// temporaries created exclusively beside them, in any letter case of their extensions.
#include <doctest/doctest.h>

#include <fstream>
#include <set>
#include <stb_image.h>
#include <sys/stat.h>

#include "io/image_io.h"
#include "test_support.h"

using namespace strata;

namespace fs = std::filesystem;

namespace {

// A small render of the bundled Cornell box.
const std::string kRender = "render --width 8 --height 8 --spp 24";

}  // namespace

TEST_CASE("render: symlinks planted at every temporary name of its outputs are left alone") {
    const auto dir = test::scratchDir("render-symlinks");
    const auto victim = dir / "victim";
    std::ofstream(victim) << "precious";
    std::string outputs;
    std::string plant;
    for (const char* name : {"out.png", "out.exr", "out.pfm"}) {
        const std::string out = (dir / name).string();
        outputs += " --out " + out;
        // The shell plants them as the process strata becomes (exec keeps its PID): the older
        // names OUT.tmp-PID and OUT.tmpPID, and OUT.tmp-PID-N for the first ten N.
        plant += "for s in .tmp-$$ .tmp$$ $(seq -f .tmp-$$-%g 0 9); do ln -s " + victim.string() + " " + out +
                 "$s; done; ";
    }
    const auto result =
        test::runCommand("sh -c '" + plant + "exec " + STRATA_BINARY + " " + kRender + outputs + "'");
    REQUIRE_MESSAGE(result.exitCode == 0, result.err);
    CHECK(test::fileBytes(victim) == "precious");
    size_t links = 0;
    for (const auto& entry : fs::directory_iterator(dir)) links += fs::is_symlink(entry.symlink_status());
    CHECK(links == 3 * 12);
    CHECK(readExr(dir / "out.exr").width == 8);
    CHECK(test::fileBytes(dir / "out.pfm").rfind("PF\n8 8\n", 0) == 0);
    int width = 0, height = 0, channels = 0;
    unsigned char* png = stbi_load((dir / "out.png").c_str(), &width, &height, &channels, 3);
    CHECK(png != nullptr);
    stbi_image_free(png);
    CHECK(width == 8);
}

TEST_CASE("render: upper-case extensions name the same formats") {
    const auto dir = test::scratchDir("render-case");
    const auto result = test::runStrata(kRender + " --out " + (dir / "a.PNG").string() + " --out " +
                                        (dir / "a.EXR").string() + " --out " + (dir / "a.Pfm").string());
    REQUIRE_MESSAGE(result.exitCode == 0, result.err);
    CHECK(test::fileBytes(dir / "a.PNG").substr(1, 3) == "PNG");
    CHECK(readExr(dir / "a.EXR").height == 8);
    CHECK(test::fileBytes(dir / "a.Pfm").rfind("PF\n", 0) == 0);
}

TEST_CASE("render: an output that cannot be written fails before rendering, one line naming --out and it") {
    const auto dir = test::scratchDir("render-unwritable");
    const std::string d = dir.string();
    fs::create_directory(dir / "folder");
    fs::create_directory(dir / "folder.exr");
    std::ofstream(dir / "file") << "not a folder";
    const std::string precious = "an earlier render\n";
    std::ofstream(dir / "keep.exr") << precious;
    const std::set<std::string> before = test::folderEntries(dir);
    const struct {
        std::string out;
        int exitStatus;
        std::string expected;
    } cases[] = {
        {d + "/no/such/x.png", 1, "--out: " + d + "/no/such/x.png: cannot write: no such folder " + d + "/no/such"},
        {d + "/file/x.png", 1, "--out: " + d + "/file/x.png: cannot write: " + d + "/file is not a folder"},
        {d + "/folder", 1, "--out: " + d + "/folder: cannot write: it is a folder"},
        {d + "/folder.exr", 1, "--out: " + d + "/folder.exr: cannot write: it is a folder"},
        {d + "/x.bmp", 2, "--out: " + d + "/x.bmp: unknown image format (use .exr, .pfm or .png)"},
        {d + "/x", 2, "--out: " + d + "/x: unknown image format (use .exr, .pfm or .png)"},
    };
    for (const auto& c : cases) {
        // Beside an output that could be written, which stays as it was too.
        const auto result = test::runStrata(kRender + " --out " + d + "/keep.exr --out " + c.out);
        CAPTURE(c.out);
        CAPTURE(result.err);
        CHECK(result.exitCode == c.exitStatus);
        // One line: nothing was read (no scene line) or rendered (no progress) before it.
        CHECK(test::lineCount(result.err) == 1);
        CHECK(result.err == "strata: " + c.expected + "\n");
        CHECK(test::fileBytes(dir / "keep.exr") == precious);
        CHECK(test::folderEntries(dir) == before);
    }
}

TEST_CASE("render: an output folder it may not write to fails before rendering") {
    const auto obeying = test::obeyingPermissions();
    if (!obeying) {
        MESSAGE("skipped: root without setpriv writes to any folder");
        return;
    }
    const auto dir = test::scratchDir("render-read-only");
    fs::create_directory(dir / "locked");
    fs::permissions(dir / "locked", fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                                        fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
    const auto result = test::runCommand(*obeying + STRATA_BINARY + " " + kRender + " --out " +
                                         (dir / "locked" / "x.png").string());
    CAPTURE(result.err);
    CHECK(result.exitCode == 1);
    CHECK(result.err == "strata: --out: " + (dir / "locked" / "x.png").string() + ": cannot write: folder " +
                            (dir / "locked").string() + ": Permission denied\n");
    CHECK(fs::is_empty(dir / "locked"));
    fs::permissions(dir / "locked", fs::perms::owner_all);
}
