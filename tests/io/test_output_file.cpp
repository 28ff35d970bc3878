#include <doctest/doctest.h>

#include <fstream>
#include <set>
#include <string>
#include <unistd.h>

#include "io/output_file.h"
#include "util/error.h"
#include "test_support.h"

using namespace strata;

namespace fs = std::filesystem;

namespace {

// What an attacker would plant for a writer of `target` in this process: a symlink at every
// temporary name it could choose, the older TARGET.tmp-PID and TARGET.tmpPID among them, each to
// `victim`. Returns their names.
std::set<std::string> plantSymlinks(const fs::path& target, const fs::path& victim, int numbered) {
    const std::string stem = target.filename().string();
    const std::string pid = std::to_string(getpid());
    std::set<std::string> names = {stem + ".tmp-" + pid, stem + ".tmp" + pid};
    for (int n = 0; n < numbered; ++n) names.insert(stem + ".tmp-" + pid + "-" + std::to_string(n));
    for (const auto& name : names) fs::create_symlink(victim, target.parent_path() / name);
    return names;
}

}  // namespace

TEST_CASE("output file: symlinks planted at its temporary names are never written through") {
    const auto dir = test::scratchDir("output-symlinks");
    const auto victim = dir / "victim";
    std::ofstream(victim) << "precious";
    // A dangling symlink too: a plain O_CREAT would create the file it names.
    const auto target = dir / "out.png";
    const std::set<std::string> planted = plantSymlinks(target, victim, 10);
    fs::create_symlink(dir / "created-through-a-link", dir / ("out.png.tmp-" + std::to_string(getpid()) + "-10"));

    writeFile(target, "new image");
    CHECK(test::fileBytes(target) == "new image");
    CHECK(test::fileBytes(victim) == "precious");
    CHECK(!fs::exists(dir / "created-through-a-link"));
    for (const auto& name : planted) CHECK(fs::is_symlink(dir / name));
    // Only the target is new: the temporary became it.
    std::set<std::string> expected = planted;
    expected.insert({"victim", "out.png", "out.png.tmp-" + std::to_string(getpid()) + "-10"});
    CHECK(test::folderEntries(dir) == expected);
}

TEST_CASE("output file: when every temporary name is taken it fails and leaves the target alone") {
    const auto dir = test::scratchDir("output-taken");
    const auto victim = dir / "victim";
    std::ofstream(victim) << "precious";
    const auto target = dir / "out.exr";
    std::ofstream(target) << "an earlier render";
    plantSymlinks(target, victim, 100);
    CHECK_THROWS_WITH_AS(writeFile(target, "new"), doctest::Contains("out.exr: cannot write: the temporary names"),
                         Error);
    CHECK(test::fileBytes(target) == "an earlier render");
    CHECK(test::fileBytes(victim) == "precious");
}

TEST_CASE("output file: the target is replaced only on commit, and a symlink at the target is replaced, not followed") {
    const auto dir = test::scratchDir("output-commit");
    const auto target = dir / "out.pfm";
    std::ofstream(target) << "an earlier render";
    {
        OutputFile file(target);
        file.write("half of it");
        CHECK(test::fileBytes(target) == "an earlier render");
    }  // never committed: a failure midway
    CHECK(test::fileBytes(target) == "an earlier render");
    CHECK(test::folderEntries(dir) == std::set<std::string>{"out.pfm"});

    OutputFile file(target);
    file.write("0123456789");
    file.seek(2);
    file.write("ab");
    CHECK(file.position() == 4);
    file.commit();
    CHECK(test::fileBytes(target) == "01ab456789");
    CHECK(test::folderEntries(dir) == std::set<std::string>{"out.pfm"});

    const auto victim = dir / "victim";
    std::ofstream(victim) << "precious";
    fs::create_symlink(victim, dir / "link.png");
    writeFile(dir / "link.png", "image");
    CHECK(!fs::is_symlink(dir / "link.png"));
    CHECK(test::fileBytes(dir / "link.png") == "image");
    CHECK(test::fileBytes(victim) == "precious");
}

TEST_CASE("output file: a missing, unwritable or wrong folder and a target that is no file are named before writing") {
    const auto dir = test::scratchDir("output-checks");
    std::ofstream(dir / "file") << "x";
    fs::create_directory(dir / "folder.png");
    const struct {
        fs::path target;
        std::string expected;
    } cases[] = {
        {dir / "no" / "such" / "out.png", (dir / "no" / "such" / "out.png").string() +
                                              ": cannot write: no such folder " + (dir / "no" / "such").string()},
        {dir / "file" / "out.png", (dir / "file" / "out.png").string() + ": cannot write: " +
                                       (dir / "file").string() + " is not a folder"},
        {dir / "folder.png", (dir / "folder.png").string() + ": cannot write: it is a folder"},
        {dir / "folder.png" / "", (dir / "folder.png" / "").string() + ": cannot write: it is a folder"},
        {"/dev/null", "/dev/null: cannot write: it is not a regular file"},
        // sysfs takes no new file, even from root.
        {"/sys/strata-test.png", "/sys/strata-test.png: cannot write: folder /sys: "},
    };
    for (const auto& c : cases) {
        CAPTURE(c.target);
        CHECK_THROWS_WITH_AS(requireWritable(c.target), doctest::Contains(c.expected.c_str()), Error);
    }
    CHECK_NOTHROW(requireWritable(dir / "out.png"));
    CHECK(!fs::exists(dir / "out.png"));  // the check leaves nothing behind
    CHECK(test::folderEntries(dir) == std::set<std::string>{"file", "folder.png"});
}
