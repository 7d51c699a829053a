#pragma once
#include <cstdint>
#include <filesystem>
#include <utility>
#include <vector>

namespace app {

// Tells which of a few files changed on disk, by polling their modification time and size
// (no inotify: a handful of stat calls a few times a second costs nothing, and works on
// every file system). A file that appears or disappears has changed too.
class FileWatcher {
public:
    // Watches `files` from now on. Changes are judged against the state last seen of a file
    // watched already, and against its present state for a new one.
    void watch(const std::vector<std::filesystem::path>& files);

    // The watched files whose state differs from the one last seen; that state becomes the
    // one seen, so each change is reported once.
    std::vector<std::filesystem::path> changedFiles();

    const std::vector<std::filesystem::path>& files() const { return paths_; }

private:
    struct FileState {
        bool exists = false;
        std::filesystem::file_time_type modified{};
        std::uintmax_t size = 0;
        bool operator==(const FileState& other) const;
    };
    static FileState stateOf(const std::filesystem::path& file);

    std::vector<std::filesystem::path> paths_;
    std::vector<FileState> states_;
};

}  // namespace app
