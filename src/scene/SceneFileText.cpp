#include "scene/SceneFileText.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>

namespace scene {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void failToRead(const fs::path& path, int error)
{
    throw std::runtime_error(path.string() +
                             ": cannot read the scene file: " + std::strerror(error));
}

}  // namespace

std::string readSceneFileText(const fs::path& path)
{
    const int descriptor = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (descriptor < 0)
        failToRead(path, errno);
    struct Closer {
        int descriptor;
        ~Closer() { ::close(descriptor); }
    } closer{descriptor};
    struct stat status {};
    if (::fstat(descriptor, &status) != 0)
        failToRead(path, errno);
    if (S_ISDIR(status.st_mode))
        failToRead(path, EISDIR);
    const auto tooLarge = [&] {
        throw std::runtime_error(path.string() + ": the scene file is larger than " +
                                 std::to_string(kMaxSceneFileBytes >> 20) +
                                 " MiB, the most a scene file may hold");
    };
    if (S_ISREG(status.st_mode) && static_cast<std::size_t>(status.st_size) > kMaxSceneFileBytes)
        tooLarge();
    std::string text;
    char buffer[1 << 16];
    for (;;) {
        const ssize_t count = ::read(descriptor, buffer, sizeof buffer);
        if (count < 0 && errno == EINTR)
            continue;
        if (count < 0)
            failToRead(path, errno);
        if (count == 0)
            break;
        text.append(buffer, static_cast<std::size_t>(count));
        if (text.size() > kMaxSceneFileBytes)
            tooLarge();
    }
    return text;
}

}  // namespace scene
