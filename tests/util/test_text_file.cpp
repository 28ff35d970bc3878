// Whole-file reads, of regular files only (util/text_file.h).
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <sys/stat.h>

#include "util/error.h"
#include "util/text_file.h"
#include "test_support.h"

using namespace strata;

TEST_CASE("text file: regular files are read whole, and a FIFO, a device or a folder is not opened nor waited on") {
    const test::ScratchDir dir = test::scratchDir("text-file");
    std::ofstream(dir / "a.txt", std::ios::binary) << std::string("x\0y", 3);
    std::string bytes;
    CHECK(readRegularFile(dir / "a.txt", bytes) == FileKind::Regular);
    CHECK(bytes == std::string("x\0y", 3));
    CHECK(readRegularFile(dir / "absent", bytes) == FileKind::Missing);
    CHECK(readRegularFile(dir / "a.txt/under", bytes) == FileKind::Missing);
    CHECK(readRegularFile(dir, bytes) == FileKind::NotRegular);
    CHECK(readRegularFile("/dev/zero", bytes) == FileKind::NotRegular);
    // A FIFO without a writer would block an ordinary open forever.
    REQUIRE(::mkfifo((dir / "fifo").c_str(), 0600) == 0);
    CHECK(readRegularFile(dir / "fifo", bytes) == FileKind::NotRegular);
    CHECK_THROWS_WITH_AS(readTextFile(dir / "fifo", "scene"),
                         ((dir / "fifo").string() + ": scene is not a regular file").c_str(), Error);
    CHECK_THROWS_WITH_AS(readTextFile(dir / "absent", "scene"),
                         ((dir / "absent").string() + ": cannot open scene").c_str(), Error);
    // Another file than the one expected (put in its place since) is not read.
    FileIdentity identity;
    REQUIRE(fileKindOf(dir / "a.txt", &identity) == FileKind::Regular);
    std::filesystem::rename(dir / "a.txt", dir / "b.txt");
    std::ofstream(dir / "a.txt") << "replaced";
    CHECK(readRegularFile(dir / "a.txt", bytes, &identity) == FileKind::NotRegular);
    CHECK(readRegularFile(dir / "b.txt", bytes, &identity) == FileKind::Regular);
}
