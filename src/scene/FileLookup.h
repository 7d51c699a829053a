#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace scene {

// Where a scene's auxiliary files are found. Texture and user-SDF files are looked up next
// to the scene file first, then in the project's data folder (textures/, scenes/sdf/).
class FileLookup {
public:
    FileLookup(std::filesystem::path sceneDirectory, std::filesystem::path dataDirectory);

    // For the scene file at `scenePath`, with the data folder from dataDirectory().
    static FileLookup forScene(const std::filesystem::path& scenePath);

    // The project's data folder: $RAYTRACER_DATA_DIR if set, else the one the build knows.
    static std::filesystem::path dataDirectory();

    std::optional<std::filesystem::path> findTexture(const std::string& name) const;
    std::optional<std::filesystem::path> findUserSdf(const std::string& name) const;

    // The folders searched, in order, for messages.
    std::vector<std::filesystem::path> textureFolders() const;
    std::vector<std::filesystem::path> shaderFolders() const;

private:
    std::filesystem::path sceneDirectory_;
    std::filesystem::path dataDirectory_;
};

// "a, b, c": folders as a message names them.
std::string joinFolders(const std::vector<std::filesystem::path>& folders);

}  // namespace scene
