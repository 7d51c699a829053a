#pragma once
#include <cstdint>
#include <cstdio>
#include <filesystem>

namespace io {

// A file opened for reading only once it is known to be a regular file. Its path is checked
// with stat() before anything opens it (opening a device can act: a tape rewinds; a FIFO
// blocks until someone writes), then opened without blocking and checked again through the
// descriptor, so that the file read is the file checked even if the path changes between.
class RegularFile {
public:
    // Throws std::runtime_error "cannot read PATH: ..." with the system's reason, or what
    // the path is instead ("a character device, not a regular file").
    explicit RegularFile(const std::filesystem::path& path);
    ~RegularFile();
    RegularFile(const RegularFile&) = delete;
    RegularFile& operator=(const RegularFile&) = delete;

    std::FILE* stream() const { return stream_; }
    std::int64_t size() const { return size_; }

private:
    std::FILE* stream_ = nullptr;
    std::int64_t size_ = 0;
};

}  // namespace io
