#pragma once
// A disk that fills: a tmpfs of a given size mounted on a folder for one test, unmounted
// after it. Mounting needs root or CAP_SYS_ADMIN; where it is not allowed the disk says why,
// for the test to skip with.
#include <filesystem>
#include <string>

namespace testing_support {

class SmallDisk {
public:
    // Makes `folder` and mounts a tmpfs of `size` ("64k") on it.
    SmallDisk(const std::filesystem::path& folder, const std::string& size);
    ~SmallDisk();
    SmallDisk(const SmallDisk&) = delete;
    SmallDisk& operator=(const SmallDisk&) = delete;

    bool mounted() const { return mounted_; }
    // Why it is not mounted ("Operation not permitted"), for the skip message.
    const std::string& whyNotMounted() const { return whyNotMounted_; }

    // Fills the disk with a file "filler", then frees `bytesLeft` (whole pages: tmpfs
    // counts in 4 KB pages). Returns false when the disk did not fill.
    bool fillLeaving(std::size_t bytesLeft) const;

private:
    std::filesystem::path folder_;
    bool mounted_ = false;
    std::string whyNotMounted_;
};

}  // namespace testing_support
