#include "interaction/FileWatcher.h"

#include "io/Sha256.h"

#include <fstream>
#include <system_error>

namespace interaction {

namespace fs = std::filesystem;

bool FileWatcher::FileState::sameTimeAndSize(const FileState& other) const
{
    return exists == other.exists && modified == other.modified && size == other.size;
}

FileWatcher::FileState FileWatcher::timeAndSizeOf(const fs::path& file)
{
    FileState state;
    std::error_code error;
    const fs::file_time_type modified = fs::last_write_time(file, error);
    if (error)
        return state;
    const std::uintmax_t size = fs::file_size(file, error);
    if (error)
        return state;
    state.exists = true;
    state.modified = modified;
    state.size = size;
    return state;
}

std::string FileWatcher::contentDigestOf(const fs::path& file)
{
    std::ifstream in(file, std::ios::binary);
    if (!in)
        return "";
    io::Sha256 digest;
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0)
        digest.add(buffer, static_cast<std::size_t>(in.gcount()));
    if (in.bad())
        return "";
    return digest.hexDigest();
}

void FileWatcher::watch(const std::vector<fs::path>& files)
{
    std::vector<FileState> states;
    for (const fs::path& file : files) {
        // A file watched already keeps the state last seen, so that an edit made while the
        // scene was being reloaded is still reported.
        std::size_t known = 0;
        while (known < paths_.size() && paths_[known] != file)
            ++known;
        if (known < paths_.size()) {
            states.push_back(states_[known]);
        } else {
            FileState state = timeAndSizeOf(file);
            if (state.exists)
                state.contentDigest = contentDigestOf(file);
            states.push_back(std::move(state));
        }
    }
    paths_ = files;
    states_ = std::move(states);
}

std::vector<fs::path> FileWatcher::changedFiles()
{
    std::vector<fs::path> changed;
    for (std::size_t i = 0; i < paths_.size(); ++i) {
        FileState now = timeAndSizeOf(paths_[i]);
        if (now.sameTimeAndSize(states_[i]))
            continue;
        // Hashed only when the time or size moved: a few times per save, never per poll.
        if (now.exists)
            now.contentDigest = contentDigestOf(paths_[i]);
        const bool bytesChanged = now.exists != states_[i].exists ||
                                  now.contentDigest != states_[i].contentDigest ||
                                  now.contentDigest.empty();
        states_[i] = std::move(now);
        if (bytesChanged)
            changed.push_back(paths_[i]);
    }
    return changed;
}

}  // namespace interaction
