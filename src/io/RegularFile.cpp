#include "io/RegularFile.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <stdexcept>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace io {

namespace {

std::string kindOf(mode_t mode)
{
    if (S_ISDIR(mode))
        return "a folder";
    if (S_ISCHR(mode))
        return "a character device";
    if (S_ISBLK(mode))
        return "a block device";
    if (S_ISFIFO(mode))
        return "a FIFO";
    if (S_ISSOCK(mode))
        return "a socket";
    return "not a regular file";
}

[[noreturn]] void refuse(const std::filesystem::path& path, const std::string& reason)
{
    throw std::runtime_error("cannot read " + path.string() + ": " + reason);
}

}  // namespace

RegularFile::RegularFile(const std::filesystem::path& path)
{
    struct stat named {};
    if (::stat(path.c_str(), &named) != 0)
        refuse(path, std::strerror(errno));
    if (!S_ISREG(named.st_mode))
        refuse(path, "it is " + kindOf(named.st_mode) + ", not a regular file");
    const int descriptor = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (descriptor < 0)
        refuse(path, std::strerror(errno));
    struct stat opened {};
    if (::fstat(descriptor, &opened) != 0 || !S_ISREG(opened.st_mode) ||
        opened.st_dev != named.st_dev || opened.st_ino != named.st_ino) {
        ::close(descriptor);
        refuse(path, "it changed while it was opened (it is not the regular file it was)");
    }
    // Reads from a regular file never block; the flag only kept the open from waiting.
    ::fcntl(descriptor, F_SETFL, ::fcntl(descriptor, F_GETFL) & ~O_NONBLOCK);
    stream_ = ::fdopen(descriptor, "rb");
    if (stream_ == nullptr) {
        const int error = errno;
        ::close(descriptor);
        refuse(path, std::strerror(error));
    }
    size_ = static_cast<std::int64_t>(opened.st_size);
}

RegularFile::~RegularFile()
{
    if (stream_ != nullptr)
        std::fclose(stream_);
}

}  // namespace io
