#include "scene/FileLookup.h"

#include <cstdlib>
#include <system_error>

namespace scene {

namespace fs = std::filesystem;

namespace {

std::optional<fs::path> firstExisting(const std::vector<fs::path>& folders, const std::string& name)
{
    for (const fs::path& folder : folders) {
        const fs::path candidate = folder / name;
        std::error_code error;
        if (fs::is_regular_file(candidate, error))
            return candidate;
    }
    return std::nullopt;
}

}  // namespace

FileLookup::FileLookup(fs::path sceneDirectory, fs::path dataDirectory)
    : sceneDirectory_(std::move(sceneDirectory)), dataDirectory_(std::move(dataDirectory))
{
}

FileLookup FileLookup::forScene(const fs::path& scenePath)
{
    fs::path folder = scenePath.parent_path();
    if (folder.empty())
        folder = ".";
    return FileLookup(folder, dataDirectory());
}

fs::path FileLookup::dataDirectory()
{
    if (const char* overridden = std::getenv("RAYTRACER_DATA_DIR"); overridden && *overridden)
        return overridden;
    return RAYTRACER_DEFAULT_DATA_DIR;
}

std::vector<fs::path> FileLookup::textureFolders() const
{
    return {sceneDirectory_, sceneDirectory_ / "textures", dataDirectory_ / "textures"};
}

std::vector<fs::path> FileLookup::shaderFolders() const
{
    return {sceneDirectory_, sceneDirectory_ / "shaders", dataDirectory_ / "scenes" / "sdf"};
}

std::optional<fs::path> FileLookup::findTexture(const std::string& name) const
{
    if (fs::path(name).is_absolute())
        return firstExisting({fs::path()}, name);
    return firstExisting(textureFolders(), name);
}

std::optional<fs::path> FileLookup::findUserSdf(const std::string& name) const
{
    return firstExisting(shaderFolders(), name + ".glsl");
}

std::string joinFolders(const std::vector<fs::path>& folders)
{
    std::string text;
    for (const fs::path& folder : folders)
        text += (text.empty() ? "" : ", ") + folder.string();
    return text;
}

}  // namespace scene
