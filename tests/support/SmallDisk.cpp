#include "support/SmallDisk.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/mount.h>
#include <unistd.h>
#include <vector>

namespace testing_support {

SmallDisk::SmallDisk(const std::filesystem::path& folder, const std::string& size) : folder_(folder)
{
    std::filesystem::create_directories(folder_);
    const std::string options = "size=" + size;
    if (::mount("tmpfs", folder_.c_str(), "tmpfs", MS_NOSUID | MS_NODEV, options.c_str()) == 0)
        mounted_ = true;
    else
        whyNotMounted_ = std::string("mounting a ") + size + " tmpfs is not allowed here (" +
                         std::strerror(errno) +
                         "): the full-disk tests need root or "
                         "CAP_SYS_ADMIN";
}

SmallDisk::~SmallDisk()
{
    if (mounted_)
        ::umount2(folder_.c_str(), MNT_DETACH);
}

bool SmallDisk::fillLeaving(std::size_t bytesLeft) const
{
    const std::filesystem::path filler = folder_ / "filler";
    const int descriptor = ::open(filler.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (descriptor < 0)
        return false;
    const std::vector<char> page(4096, 'x');
    off_t size = 0;
    for (ssize_t written; (written = ::write(descriptor, page.data(), page.size())) > 0;)
        size += written;
    const bool full = errno == ENOSPC;
    const bool freed = ::ftruncate(descriptor, size - static_cast<off_t>(bytesLeft)) == 0;
    ::close(descriptor);
    return full && freed;
}

}  // namespace testing_support
