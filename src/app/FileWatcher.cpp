#include "app/FileWatcher.h"

#include <system_error>

namespace app {

namespace fs = std::filesystem;

bool FileWatcher::FileState::operator==(const FileState& other) const
{
    return exists == other.exists && modified == other.modified && size == other.size;
}

FileWatcher::FileState FileWatcher::stateOf(const fs::path& file)
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

void FileWatcher::watch(const std::vector<fs::path>& files)
{
    std::vector<FileState> states;
    for (const fs::path& file : files) {
        // A file watched already keeps the state last seen, so that an edit made while the
        // scene was being reloaded is still reported.
        std::size_t known = 0;
        while (known < paths_.size() && paths_[known] != file)
            ++known;
        states.push_back(known < paths_.size() ? states_[known] : stateOf(file));
    }
    paths_ = files;
    states_ = std::move(states);
}

std::vector<fs::path> FileWatcher::changedFiles()
{
    std::vector<fs::path> changed;
    for (std::size_t i = 0; i < paths_.size(); ++i) {
        const FileState now = stateOf(paths_[i]);
        if (!(now == states_[i])) {
            states_[i] = now;
            changed.push_back(paths_[i]);
        }
    }
    return changed;
}

}  // namespace app
