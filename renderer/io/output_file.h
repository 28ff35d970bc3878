#pragma once
// Every file the program writes (images, the bench's tables and logs) goes through here. The bytes
// go to a temporary file beside the target, created exclusively (O_CREAT | O_EXCL | O_NOFOLLOW):
// whatever already has the temporary's name, a planted symlink above all, is never opened or
// written through; the next free name is taken instead. Only when the file is complete and on
// disk is it renamed over the target, so a failed or interrupted write leaves the target as it
// was and no temporary behind. The target itself is replaced, never written into: a symlink at
// the target's name is replaced by the file, its own target left alone.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string_view>

namespace strata {

class OutputFile {
public:
    // Creates the temporary TARGET.tmp-PID-N, N the first number no file has. Throws strata::Error
    // "TARGET: cannot write: WHY" when the target is a folder or its folder is missing or takes
    // no new file.
    explicit OutputFile(std::filesystem::path target);
    ~OutputFile();  // removes the temporary unless committed
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    const std::filesystem::path& target() const { return target_; }
    // The open temporary, e.g. for a child process's output.
    int descriptor() const { return descriptor_; }

    // Writes at the current position (all of it, or throws strata::Error naming the target).
    void write(const void* data, size_t size);
    void write(std::string_view bytes) { write(bytes.data(), bytes.size()); }
    uint64_t position() const;
    void seek(uint64_t position);

    // Flushes the temporary to disk and renames it over the target; throws strata::Error naming
    // the target (the temporary is then removed).
    void commit();

private:
    [[noreturn]] void fail(const char* step, int error) const;

    std::filesystem::path target_;
    std::filesystem::path temporary_;
    int descriptor_ = -1;
};

// Checks, before any long work, that `target` can be written: it is not a folder, and its folder
// exists and takes a new file (a temporary is created and removed, which proves it where
// permissions alone cannot: for root, or on a read-only mount). Throws strata::Error
// "TARGET: cannot write: WHY".
void requireWritable(const std::filesystem::path& target);

// Writes `bytes` as the whole of `target` through an OutputFile.
void writeFile(const std::filesystem::path& target, std::string_view bytes);

}  // namespace strata
