#include "io/OutputFiles.h"

#include "io/ImageFormats.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <fcntl.h>
#include <optional>
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

// This machine's name as it appears in temporary names: another machine sharing the folder
// (over the network) has processes of its own with the same numbers.
std::string hostNameForFiles()
{
    char name[256] = {};
    if (::gethostname(name, sizeof name - 1) != 0 || name[0] == '\0')
        return "localhost";
    std::string host = name;
    for (char& c : host)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_')
            c = '_';
    return host;
}

std::string temporaryPrefix(const fs::path& destination)
{
    return "." + destination.stem().string() + ".partial-";
}

bool allDigits(const std::string& text)
{
    return !text.empty() && text.size() <= 9 &&
           std::all_of(text.begin(), text.end(),
                       [](unsigned char c) { return std::isdigit(c) != 0; });
}

// The machine and process a temporary of `destination` named `name` belongs to: "HOST-PID-N"
// (or "PID-N", the names of earlier versions, of this machine) between the prefix and the
// extension. Nothing for any other name.
struct TemporaryOwner {
    std::string host;
    long processId = 0;
};
std::optional<TemporaryOwner> ownerOfTemporary(const std::string& name, const fs::path& destination)
{
    const std::string prefix = temporaryPrefix(destination);
    const std::string extension = destination.extension().string();
    if (name.size() <= prefix.size() + extension.size() ||
        name.compare(0, prefix.size(), prefix) != 0 ||
        name.compare(name.size() - extension.size(), extension.size(), extension) != 0)
        return std::nullopt;
    const std::string middle =
        name.substr(prefix.size(), name.size() - prefix.size() - extension.size());
    const std::size_t lastDash = middle.rfind('-');
    if (lastDash == std::string::npos || !allDigits(middle.substr(lastDash + 1)))
        return std::nullopt;
    const std::string rest = middle.substr(0, lastDash);
    const std::size_t dash = rest.rfind('-');
    TemporaryOwner owner;
    const std::string processId = dash == std::string::npos ? rest : rest.substr(dash + 1);
    if (!allDigits(processId))
        return std::nullopt;
    owner.processId = std::stol(processId);
    owner.host = dash == std::string::npos ? hostNameForFiles() : rest.substr(0, dash);
    return owner;
}

bool processRuns(long processId)
{
    // EPERM: it runs, as another user.
    return ::kill(static_cast<pid_t>(processId), 0) == 0 || errno == EPERM;
}

[[noreturn]] void failedWrite(const fs::path& destination, int error)
{
    refuse(destination, std::strerror(error));
}

// Writes `bytes` into a new `file` and checks each step: every write (short writes go on,
// EINTR retries), the synchronisation to the disk (where a delayed allocation reports a full
// disk), the size the file has on disk, and the close.
void writeBytes(const fs::path& file, const fs::path& destination,
                const std::vector<unsigned char>& bytes)
{
    // A file of this very name is a leftover of an earlier process with this number.
    ::unlink(file.c_str());
    const int descriptor =
        ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (descriptor < 0)
        failedWrite(destination, errno);
    auto fail = [&](int error) {
        ::close(descriptor);
        failedWrite(destination, error);
    };
    const unsigned char* next = bytes.data();
    std::size_t left = bytes.size();
    while (left > 0) {
        const ssize_t written = ::write(descriptor, next, left);
        if (written < 0 && errno == EINTR)
            continue;
        if (written < 0)
            fail(errno);
        if (written == 0)
            fail(EIO);
        next += written;
        left -= static_cast<std::size_t>(written);
    }
    if (::fsync(descriptor) != 0)
        fail(errno);
    struct stat onDisk {};
    if (::fstat(descriptor, &onDisk) != 0)
        fail(errno);
    if (static_cast<std::uint64_t>(onDisk.st_size) != bytes.size()) {
        ::close(descriptor);
        refuse(destination, "the file holds " + std::to_string(onDisk.st_size) + " of the " +
                                std::to_string(bytes.size()) + " bytes written");
    }
    if (::close(descriptor) != 0)
        failedWrite(destination, errno);
}

// Messages name the user's path: one about the temporary file is rewritten.
std::string aboutDestination(std::string message, const fs::path& file, const fs::path& destination)
{
    const std::string from = file.string();
    for (std::size_t at; !from.empty() && (at = message.find(from)) != std::string::npos;)
        message.replace(at, from.size(), destination.string());
    return message;
}

// The file written is read back as its format, and must hold the image's size.
void checkReadsBack(const fs::path& file, const OutputImage& output)
{
    ImageHeader header;
    try {
        header = readImageHeader(file);
    } catch (const std::runtime_error& error) {
        refuse(output.path, "the file written does not read back (" +
                                aboutDestination(error.what(), file, output.path) + ")");
    }
    if (header.width != output.image.width || header.height != output.image.height)
        refuse(output.path, "the file written reads back as " + std::to_string(header.width) + "x" +
                                std::to_string(header.height) + ", not " +
                                std::to_string(output.image.width) + "x" +
                                std::to_string(output.image.height));
}

// Makes the folder's entries (a new file, a rename) last through a crash of the machine.
void synchroniseFolder(const fs::path& folder, const fs::path& destination)
{
    const int descriptor = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (descriptor < 0)
        refuse(destination, "folder " + folder.string() + ": " + std::strerror(errno));
    // EINVAL: a file system that cannot synchronise a folder (nothing to wait for).
    if (::fsync(descriptor) != 0 && errno != EINVAL) {
        const int error = errno;
        ::close(descriptor);
        refuse(destination, "folder " + folder.string() + ": " + std::strerror(error));
    }
    ::close(descriptor);
}

std::vector<std::pair<fs::path, fs::path>> foldersOf(const std::vector<OutputImage>& images)
{
    std::vector<std::pair<fs::path, fs::path>> folders;  // folder, an output in it
    for (const OutputImage& image : images) {
        const fs::path folder = folderOf(image.path);
        if (std::none_of(folders.begin(), folders.end(),
                         [&](const auto& known) { return known.first == folder; }))
            folders.push_back({folder, image.path});
    }
    return folders;
}

}  // namespace

// Beside the destination, hidden, unique to this machine, this process and this output, with
// the destination's extension (the format's readers check it when the file is read back).
fs::path temporaryNameFor(const fs::path& destination, std::size_t index)
{
    return folderOf(destination) /
           (temporaryPrefix(destination) + hostNameForFiles() + "-" + std::to_string(::getpid()) +
            "-" + std::to_string(index) + destination.extension().string());
}

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
    const auto folders = foldersOf(images);
    try {
        for (std::size_t i = 0; i < images.size(); ++i) {
            const OutputImage& output = images[i];
            const std::vector<unsigned char> bytes =
                encodeImage(output.path, output.image, output.attributes, output.channelNames);
            temporaries.push_back(temporaryNameFor(output.path, i));
            writeBytes(temporaries.back(), output.path, bytes);
            checkReadsBack(temporaries.back(), output);
        }
        for (const auto& [folder, output] : folders)
            synchroniseFolder(folder, output);
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
    for (const auto& [folder, output] : folders)
        synchroniseFolder(folder, output);
}

std::vector<StaleTemporary> removeStaleTemporaries(const std::vector<fs::path>& destinations)
{
    const std::string host = hostNameForFiles();
    std::vector<StaleTemporary> removed;
    for (const fs::path& destination : destinations) {
        std::error_code error;
        for (fs::directory_iterator entry(folderOf(destination), error), end;
             !error && entry != end; entry.increment(error)) {
            const std::optional<TemporaryOwner> owner =
                ownerOfTemporary(entry->path().filename().string(), destination);
            std::error_code ignored;
            // Only a plain file is removed, never what a link of that name points to.
            if (!owner || owner->host != host || owner->processId == ::getpid() ||
                processRuns(owner->processId) ||
                entry->symlink_status(ignored).type() != fs::file_type::regular)
                continue;
            const bool already = std::any_of(removed.begin(), removed.end(), [&](const auto& r) {
                return r.path == entry->path();
            });
            if (!already && fs::remove(entry->path(), ignored))
                removed.push_back({entry->path(), owner->processId});
        }
    }
    return removed;
}

}  // namespace io
