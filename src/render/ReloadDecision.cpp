#include "render/ReloadDecision.h"

#include "render/CameraController.h"

#include <algorithm>

namespace render {

namespace fs = std::filesystem;

namespace {

// Paths as the watcher and the parser spell them may differ ("./x.glsl" and "x.glsl").
bool samePath(const fs::path& a, const fs::path& b)
{
    return a.lexically_normal() == b.lexically_normal();
}

bool anyChanged(const std::vector<fs::path>& files, const std::vector<fs::path>& changed)
{
    return std::any_of(files.begin(), files.end(), [&](const fs::path& file) {
        return std::any_of(changed.begin(), changed.end(),
                           [&](const fs::path& other) { return samePath(file, other); });
    });
}

}  // namespace

ReloadDecision decideReload(const SceneShaderCode& shown, const SceneShaderCode& edited,
                            const std::vector<fs::path>& shownTextures,
                            const std::vector<fs::path>& editedTextures,
                            const std::vector<fs::path>& changedFiles)
{
    ReloadDecision decision;
    decision.rebuildShader = shown.variant != edited.variant || shown.defines != edited.defines ||
                             shown.sceneFunctions != edited.sceneFunctions ||
                             shown.userSdfFiles != edited.userSdfFiles ||
                             anyChanged(edited.userSdfFiles, changedFiles);
    decision.reloadTextures =
        shownTextures != editedTextures || anyChanged(editedTextures, changedFiles);
    return decision;
}

bool cameraLinesChanged(const scene::Camera& before, const scene::Camera& after)
{
    return !sameCamera(before, after);
}

}  // namespace render
