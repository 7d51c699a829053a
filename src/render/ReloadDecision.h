#pragma once
#include "render/SceneShaderGenerator.h"
#include "scene/Scene.h"

#include <filesystem>
#include <vector>

namespace render {

// What has to be redone on the GPU when the scene on screen is replaced by an edited one.
// Only structure reaches the shader's code (which shapes, which CSG tree, which features,
// how large the uniform arrays are); every number is a uniform. So the decision compares
// the code generated for the two scenes, not their text: an edit of values only gives the
// same code and needs nothing but new uniforms.
struct ReloadDecision {
    // The generated code differs, or a user SDF file it includes changed on disk.
    bool rebuildShader = false;
    // The scene's texture files differ (another file, another order), or one changed on disk.
    bool reloadTextures = false;
};

// `shownTextures` / `editedTextures`: the texture files in layer order
// (SceneUniforms::textureLayers). `changedFiles`: the files that changed on disk since the
// shown scene was loaded.
ReloadDecision decideReload(const SceneShaderCode& shown, const SceneShaderCode& edited,
                            const std::vector<std::filesystem::path>& shownTextures,
                            const std::vector<std::filesystem::path>& editedTextures,
                            const std::vector<std::filesystem::path>& changedFiles);

// The file's camera lines changed between two loads of a scene file. Only then does a reload
// replace a camera the user has moved in the window.
bool cameraLinesChanged(const scene::Camera& before, const scene::Camera& after);

}  // namespace render
