#pragma once
// Whole-file reads for every file Strata reads (scene files, the files they refer to, EXR images),
// with the one error message every loader uses. Only regular files are read: a FIFO would block
// the read forever and a device such as /dev/zero never ends, and no scene or image file is one.
#include <cstdint>
#include <filesystem>
#include <string>

namespace strata {

// What is at a path, following symlinks.
enum class FileKind { Regular, Missing, NotRegular, Unreadable };

// The device and inode of a file: the same file under another path, or another file put in place
// of the one seen before.
struct FileIdentity {
    uint64_t device = 0;
    uint64_t inode = 0;
    bool operator==(const FileIdentity&) const = default;
};

// What `path` is; `identity` receives a regular file's.
FileKind fileKindOf(const std::filesystem::path& path, FileIdentity* identity = nullptr);

// Reads the regular file `path` into `bytes`: Regular when read. Anything else is not opened, and
// what is opened is opened without blocking and checked to be the regular file seen before (a
// FIFO put in its place meanwhile cannot hang the read), and `expected` when given: NotRegular
// when it is another file.
FileKind readRegularFile(const std::filesystem::path& path, std::string& bytes,
                         const FileIdentity* expected = nullptr);

// The file's bytes; throws strata::Error "PATH: cannot open WHAT" when it cannot be read and
// "PATH: WHAT is not a regular file" for a directory, FIFO, device or socket.
std::string readTextFile(const std::filesystem::path& path, const std::string& what);

}  // namespace strata
