#include "render/ScenePreparation.h"

#include "render/PathTracerProgram.h"
#include "scene/FileLookup.h"
#include "scene/InvisibleObjects.h"

namespace render {

PreparedScene prepareScene(const scene::Scene& scene, const shadergen::ShaderBuild& build,
                           const std::filesystem::path& shaderDirectory,
                           settings::PathKernel kernel)
{
    // Between the steps, the set-up may be abandoned (render::setUpCheckpoint).
    auto checkpoint = [] {
        if (setUpCheckpoint())
            setUpCheckpoint()();
    };
    PreparedScene prepared;
    prepared.visible = scene::dropInvisibleObjects(scene);
    checkpoint();
    prepared.code = generateSceneShaderCode(prepared.visible, build);
    checkpoint();
    prepared.environmentMap = loadSceneEnvironmentMap(prepared.visible);
    checkpoint();
    prepared.uniforms =
        packSceneUniforms(prepared.visible, prepared.code, prepared.environmentMap.get());
    checkpoint();
    prepared.pathTracerSource = assemblePathTracerSource(prepared.code, shaderDirectory, kernel);
    checkpoint();
    return prepared;
}

std::filesystem::path defaultShaderDirectory()
{
    return scene::FileLookup::dataDirectory() / "shaders";
}

}  // namespace render
