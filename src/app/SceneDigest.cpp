#include "app/SceneDigest.h"

#include "io/Sha256.h"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace app {

namespace {

std::string contentsOf(const std::filesystem::path& file)
{
    std::ifstream in(file, std::ios::binary);
    std::ostringstream bytes;
    if (in)
        bytes << in.rdbuf();
    if (!in || in.bad())
        throw std::runtime_error("cannot read " + file.string() + ": " + std::strerror(errno));
    return bytes.str();
}

}  // namespace

std::string sceneSha256(const std::vector<std::filesystem::path>& files)
{
    io::Sha256 digest;
    for (const std::filesystem::path& file : files) {
        // Read whole, so that the length and the bytes hashed are of one version of the file.
        const std::string bytes = contentsOf(file);
        unsigned char length[8];
        for (int i = 0; i < 8; ++i)
            length[i] =
                static_cast<unsigned char>(static_cast<std::uint64_t>(bytes.size()) >> (8 * i));
        digest.add(length, sizeof length);
        digest.add(bytes);
    }
    return digest.hexDigest();
}

}  // namespace app
