#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace interaction {

// Tells which of a few files changed on disk, by polling their modification time and size
// (no inotify: a handful of stat calls a few times a second costs nothing, and works on
// every file system). A file that appears or disappears has changed too. A new time or size
// is only a hint: the file has changed when its bytes have (SHA-256), so that touching a
// file, or saving it unchanged, is no change and restarts nothing.
class FileWatcher {
public:
    // Watches `files` from now on. Changes are judged against the state last seen of a file
    // watched already, and against its present state for a new one.
    void watch(const std::vector<std::filesystem::path>& files);

    // The watched files whose bytes (or existence) differ from the ones last seen; that
    // state becomes the one seen, so each change is reported once.
    std::vector<std::filesystem::path> changedFiles();

    const std::vector<std::filesystem::path>& files() const { return paths_; }

private:
    struct FileState {
        bool exists = false;
        std::filesystem::file_time_type modified{};
        std::uintmax_t size = 0;
        // SHA-256 of the bytes, taken when the time or size moved; empty if unreadable.
        std::string contentDigest;
        bool sameTimeAndSize(const FileState& other) const;
    };
    // The file's time and size, without its digest.
    static FileState timeAndSizeOf(const std::filesystem::path& file);
    static std::string contentDigestOf(const std::filesystem::path& file);

    std::vector<std::filesystem::path> paths_;
    std::vector<FileState> states_;
};

}  // namespace interaction
