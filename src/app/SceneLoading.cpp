#include "app/SceneLoading.h"

#include "io/ImageFile.h"
#include "render/EnvironmentMap.h"
#include "scene/SceneFeatures.h"
#include "scene/SceneParser.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace app {

scene::Scene loadScene(const std::filesystem::path& path)
{
    scene::Scene scene = scene::parseSceneFile(path);
    for (const scene::Pigment& pigment : scene.pigments)
        if (pigment.kind == scene::PigmentKind::Texture) {
            try {
                io::checkReadableImage(pigment.texturePath);
            } catch (const std::exception& error) {
                throw std::runtime_error(path.string() + ":" + std::to_string(pigment.line) +
                                         ": texture '" + pigment.textureName +
                                         "': " + error.what());
            }
        }
    // Read whole and its distribution built, so that a file whose pixels cannot be read
    // fails here too, not only one whose header cannot.
    render::loadSceneEnvironmentMap(scene);
    return scene;
}

std::vector<std::filesystem::path> filesOfScene(const std::filesystem::path& sceneFile,
                                                const scene::Scene& scene)
{
    std::vector<std::filesystem::path> files = {sceneFile};
    auto add = [&files](const std::filesystem::path& file) {
        if (std::find(files.begin(), files.end(), file) == files.end())
            files.push_back(file);
    };
    for (const auto& [name, path] : scene::analyseFeatures(scene).userSdfs)
        add(path);
    for (const scene::Pigment& pigment : scene.pigments)
        if (pigment.kind == scene::PigmentKind::Texture)
            add(pigment.texturePath);
    if (scene.environment.kind == scene::EnvironmentKind::Map)
        add(scene.environment.mapPath);
    return files;
}

}  // namespace app
