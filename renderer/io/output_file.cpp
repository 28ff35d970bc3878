#include "io/output_file.h"

#include <cerrno>
#include <fcntl.h>
#include <string>
#include <system_error>
#include <unistd.h>

#include "util/error.h"

namespace strata {
namespace {

namespace fs = std::filesystem;

// Names tried before giving up: far more than concurrent writers of one target ever need, few
// enough that a folder full of planted names fails at once.
constexpr int kTemporaryNames = 100;

std::string reasonOf(int error) { return std::generic_category().message(error); }

}  // namespace

OutputFile::OutputFile(fs::path target) : target_(std::move(target)) {
    const auto refuse = [&](const std::string& why) {
        throw Error(target_.string() + ": cannot write: " + why);
    };
    std::error_code ignored;
    if (fs::is_directory(target_, ignored)) refuse("it is a folder");
    if (target_.filename().empty()) refuse("the name ends in a folder separator");
    // Replacing a device or a pipe by a file (root can, in /dev) is never what was meant.
    const fs::file_status existing = fs::symlink_status(target_, ignored);
    if (fs::exists(existing) && !fs::is_regular_file(existing) && !fs::is_symlink(existing)) {
        refuse("it is not a regular file");
    }
    const fs::path folder = target_.has_parent_path() ? target_.parent_path() : fs::path(".");
    const std::string stem = target_.string() + ".tmp-" + std::to_string(static_cast<long>(getpid())) + "-";
    for (int n = 0; n < kTemporaryNames; ++n) {
        const std::string name = stem + std::to_string(n);
        // O_EXCL fails on any existing name, a symlink included, without following it.
        const int descriptor = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (descriptor >= 0) {
            descriptor_ = descriptor;
            temporary_ = name;
            return;
        }
        const int error = errno;
        if (error == EEXIST) continue;
        if (error == EINTR) {
            --n;
            continue;
        }
        if (!fs::exists(folder, ignored)) refuse("no such folder " + folder.string());
        if (!fs::is_directory(folder, ignored)) refuse(folder.string() + " is not a folder");
        refuse("folder " + folder.string() + ": " + reasonOf(error));
    }
    refuse("the temporary names " + stem + "0.." + std::to_string(kTemporaryNames - 1) +
           " are all taken");
}

OutputFile::~OutputFile() {
    if (descriptor_ >= 0) ::close(descriptor_);
    if (!temporary_.empty()) ::unlink(temporary_.c_str());
}

void OutputFile::fail(const char* step, int error) const {
    throw Error(target_.string() + ": cannot write: " + step + ": " + reasonOf(error));
}

void OutputFile::write(const void* data, size_t size) {
    const char* bytes = static_cast<const char*>(data);
    while (size > 0) {
        const ssize_t written = ::write(descriptor_, bytes, size);
        if (written < 0) {
            if (errno == EINTR) continue;
            fail("write", errno);
        }
        bytes += written;
        size -= static_cast<size_t>(written);
    }
}

uint64_t OutputFile::position() const {
    const off_t offset = ::lseek(descriptor_, 0, SEEK_CUR);
    if (offset < 0) fail("seek", errno);
    return static_cast<uint64_t>(offset);
}

void OutputFile::seek(uint64_t position) {
    if (::lseek(descriptor_, static_cast<off_t>(position), SEEK_SET) < 0) fail("seek", errno);
}

void OutputFile::commit() {
    // On disk before the rename, so that a crash leaves the old file or the whole new one.
    if (::fsync(descriptor_) != 0) fail("flush", errno);
    const int descriptor = descriptor_;
    descriptor_ = -1;
    if (::close(descriptor) != 0) fail("close", errno);
    if (::rename(temporary_.c_str(), target_.c_str()) != 0) fail("rename", errno);
    temporary_.clear();
}

void requireWritable(const fs::path& target) { OutputFile probe(target); }

void writeFile(const fs::path& target, std::string_view bytes) {
    OutputFile file(target);
    file.write(bytes);
    file.commit();
}

}  // namespace strata
