#include "util/text_file.h"

#include <cerrno>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "util/error.h"
#include "util/printable.h"

namespace strata {
namespace {

FileIdentity identityOf(const struct stat& status) {
    return {static_cast<uint64_t>(status.st_dev), static_cast<uint64_t>(status.st_ino)};
}

// Closes the descriptor on every way out.
struct FileDescriptor {
    int fd;
    ~FileDescriptor() {
        if (fd >= 0) ::close(fd);
    }
};

}  // namespace

FileKind fileKindOf(const std::filesystem::path& path, FileIdentity* identity) {
    struct stat status {};
    if (::stat(path.c_str(), &status) != 0) {
        return errno == ENOENT || errno == ENOTDIR ? FileKind::Missing : FileKind::Unreadable;
    }
    if (!S_ISREG(status.st_mode)) return FileKind::NotRegular;
    if (identity) *identity = identityOf(status);
    return FileKind::Regular;
}

FileKind readRegularFile(const std::filesystem::path& path, std::string& bytes,
                         const FileIdentity* expected) {
    // Not opened unless it is a regular file: opening some devices does something.
    FileIdentity seen;
    const FileKind kind = fileKindOf(path, &seen);
    if (kind != FileKind::Regular) return kind;
    if (expected && seen != *expected) return FileKind::NotRegular;
    const FileDescriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
    if (file.fd < 0) return errno == ENOENT || errno == ENOTDIR ? FileKind::Missing : FileKind::Unreadable;
    struct stat status {};
    if (::fstat(file.fd, &status) != 0) return FileKind::Unreadable;
    if (!S_ISREG(status.st_mode) || identityOf(status) != seen) return FileKind::NotRegular;
    // A regular file reads alike either way; blocking reads are the ordinary ones.
    const int flags = ::fcntl(file.fd, F_GETFL);
    if (flags < 0 || ::fcntl(file.fd, F_SETFL, flags & ~O_NONBLOCK) != 0) return FileKind::Unreadable;
    bytes.clear();
    bytes.reserve(static_cast<size_t>(status.st_size));
    char buffer[1 << 16];
    for (;;) {
        const ssize_t count = ::read(file.fd, buffer, sizeof buffer);
        if (count == 0) break;
        if (count < 0) {
            if (errno == EINTR) continue;
            return FileKind::Unreadable;
        }
        bytes.append(buffer, static_cast<size_t>(count));
    }
    return FileKind::Regular;
}

std::string readTextFile(const std::filesystem::path& path, const std::string& what) {
    std::string bytes;
    switch (readRegularFile(path, bytes)) {
        case FileKind::Regular: return bytes;
        case FileKind::NotRegular:
            throw Error(printable(path.string()) + ": " + what + " is not a regular file");
        default: throw Error(printable(path.string()) + ": cannot open " + what);
    }
}

}  // namespace strata
