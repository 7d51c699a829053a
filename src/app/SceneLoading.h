#pragma once
#include "scene/Scene.h"

#include <filesystem>
#include <vector>

namespace app {

// Reads a scene file and checks that every texture and environment map it names can be read,
// so that no render starts (and no reload replaces a good scene) with an image that fails
// later. Throws with
// the one line to show: the file, the line and what is wrong.
scene::Scene loadScene(const std::filesystem::path& path);

// The files a scene is made of: the scene file, the user SDF files its objects call, the
// texture files its pigments name, its environment map. A change to any of them is a change to the scene.
std::vector<std::filesystem::path> filesOfScene(const std::filesystem::path& sceneFile,
                                                const scene::Scene& scene);

}  // namespace app
