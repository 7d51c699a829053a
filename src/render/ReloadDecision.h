#pragma once
#include "render/SceneUniforms.h"
#include "scene/Scene.h"
#include "shadergen/SceneShaderGenerator.h"

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
    // The scene's texture files or environment map differ (another file, another order), or
    // one changed on disk.
    bool reloadTextures = false;
    // Nothing the GPU is given differs: the same code, the same number in every uniform, no
    // file it reads changed. An edit of a comment or of spacing, or a number written another
    // way, changes nothing on screen, so the accumulation goes on.
    bool changesNothing = false;
};

// `shown` / `edited`: the code generated for each scene and its numbers laid out as uniforms
// (whose textureLayers are its texture files in layer order). `changedFiles`: the files whose
// bytes changed on disk since the shown scene was loaded (interaction::FileWatcher).
ReloadDecision decideReload(const shadergen::SceneShaderCode& shownCode,
                            const SceneUniforms& shownUniforms,
                            const shadergen::SceneShaderCode& editedCode,
                            const SceneUniforms& editedUniforms,
                            const std::vector<std::filesystem::path>& changedFiles);

// The file's camera lines changed between two loads of a scene file. Only then does a reload
// replace a camera the user has moved in the window.
bool cameraLinesChanged(const scene::Camera& before, const scene::Camera& after);

}  // namespace render
