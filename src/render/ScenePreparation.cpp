#include "render/ScenePreparation.h"

#include "render/PathTracerProgram.h"
#include "scene/FileLookup.h"
#include "scene/InvisibleObjects.h"

namespace render {

PreparedScene prepareScene(const scene::Scene& scene, const shadergen::ShaderBuild& build,
                           const std::filesystem::path& shaderDirectory,
                           settings::PathKernel kernel)
{
    PreparedScene prepared;
    prepared.visible = scene::dropInvisibleObjects(scene);
    prepared.code = generateSceneShaderCode(prepared.visible, build);
    prepared.environmentMap = loadSceneEnvironmentMap(prepared.visible);
    prepared.uniforms =
        packSceneUniforms(prepared.visible, prepared.code, prepared.environmentMap.get());
    prepared.pathTracerSource = assemblePathTracerSource(prepared.code, shaderDirectory, kernel);
    return prepared;
}

std::filesystem::path defaultShaderDirectory()
{
    return scene::FileLookup::dataDirectory() / "shaders";
}

}  // namespace render
