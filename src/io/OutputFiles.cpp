#include "io/OutputFiles.h"

#include "io/ImageFormats.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>

namespace io {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void refuse(const fs::path& path, const std::string& reason)
{
    throw std::runtime_error("cannot write " + path.string() + ": " + reason);
}

fs::path folderOf(const fs::path& path)
{
    return path.has_parent_path() ? path.parent_path() : fs::path(".");
}

void checkOutputCanBeWritten(const OutputRequest& output)
{
    const fs::path& path = output.path;
    struct stat status {};
    if (::stat(path.c_str(), &status) == 0 && S_ISDIR(status.st_mode))
        refuse(path, std::strerror(EISDIR));
    const fs::path folder = folderOf(path);
    if (::stat(folder.c_str(), &status) != 0)
        refuse(path, "folder " + folder.string() + ": " + std::strerror(errno));
    if (!S_ISDIR(status.st_mode))
        refuse(path, folder.string() + ": " + std::strerror(ENOTDIR));
    // Write to add the file, search to reach it; EROFS for a read-only file system.
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        refuse(path, "folder " + folder.string() + ": " + std::strerror(errno));

    std::vector<const ImageFormat*> allowed;
    for (const ImageFormat& format : outputFormats())
        if (output.kind == OutputKind::Image || format.float32)
            allowed.push_back(&format);
    const ImageFormat* format = outputFormatOf(path);
    if (format == nullptr || std::find(allowed.begin(), allowed.end(), format) == allowed.end())
        refuse(path, std::string(output.kind == OutputKind::Statistics
                                     ? "per-pixel statistics need a 32-bit float format"
                                     : "unknown image format") +
                         " (use " + listExtensions(allowed) + ")");
}

// Beside the destination, hidden, unique to this process and this output, with the
// destination's extension (OpenImageIO's writers check it).
fs::path temporaryNameFor(const fs::path& destination, std::size_t index)
{
    return folderOf(destination) /
           ("." + destination.stem().string() + ".partial-" + std::to_string(::getpid()) + "-" +
            std::to_string(index) + destination.extension().string());
}

}  // namespace

void checkOutputsCanBeWritten(const std::vector<OutputRequest>& outputs)
{
    for (const OutputRequest& output : outputs)
        checkOutputCanBeWritten(output);
}

bool resolveToSameFile(const fs::path& a, const fs::path& b)
{
    std::error_code error;
    if (fs::exists(a, error) && fs::exists(b, error) && fs::equivalent(a, b, error))
        return true;
    const fs::path first = fs::weakly_canonical(fs::absolute(a), error);
    if (error)
        return fs::absolute(a).lexically_normal() == fs::absolute(b).lexically_normal();
    const fs::path second = fs::weakly_canonical(fs::absolute(b), error);
    return !error && first == second;
}

void writeAllOrNothing(const std::vector<OutputImage>& images)
{
    std::vector<fs::path> temporaries;
    auto removeTemporaries = [&] {
        std::error_code ignored;
        for (const fs::path& temporary : temporaries)
            fs::remove(temporary, ignored);
    };
    try {
        for (std::size_t i = 0; i < images.size(); ++i) {
            temporaries.push_back(temporaryNameFor(images[i].path, i));
            writeImageFile(temporaries.back(), images[i].path, images[i].image,
                           images[i].attributes, images[i].channelNames);
        }
    } catch (...) {
        removeTemporaries();
        throw;
    }
    for (std::size_t i = 0; i < images.size(); ++i) {
        std::error_code error;
        fs::rename(temporaries[i], images[i].path, error);
        if (error) {
            temporaries.erase(temporaries.begin(), temporaries.begin() + i);
            removeTemporaries();
            refuse(images[i].path, error.message());
        }
    }
}

}  // namespace io
