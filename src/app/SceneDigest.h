#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace app {

// SHA-256 over the files a scene is made of (app/SceneLoading.h, filesOfScene: the scene
// file, then its user SDF files, then its textures), each as its length in bytes (8 bytes,
// little-endian) followed by its bytes, so that no two lists of files give one stream. The
// contents count, not the paths: shards rendered on machines that keep the files in
// different folders agree. Throws std::runtime_error naming a file that cannot be read.
std::string sceneSha256(const std::vector<std::filesystem::path>& files);

}  // namespace app
