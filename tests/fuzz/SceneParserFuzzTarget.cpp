// The libFuzzer entry point for the scene parser (tests/README.md, "Fuzzing"). Any input must
// either parse into a scene that the rest of the GL-free code accepts, or raise a SceneError;
// anything else (a crash, a sanitizer report, another exception, a camera frame that is not
// finite) is a finding. The shader generator runs on every scene that parses.
#include "scene/FileLookup.h"
#include "scene/InvisibleObjects.h"
#include "scene/SceneBounds.h"
#include "scene/SceneError.h"
#include "scene/SceneFeatures.h"
#include "scene/SceneParser.h"
#include "shadergen/SceneShaderGenerator.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace {

// Files a scene names are looked up as for the classic scenes, which sit in scenes/.
const scene::FileLookup& lookup()
{
    static const scene::FileLookup classicScenes(std::filesystem::path(RAYTRACER_SOURCE_DIR) /
                                                     "scenes",
                                                 std::filesystem::path(RAYTRACER_SOURCE_DIR));
    return classicScenes;
}

bool finite(const glm::vec3& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string text(reinterpret_cast<const char*>(data), size);
    scene::Scene parsed;
    try {
        parsed = scene::parseSceneText(text, "fuzz.in", lookup());
    } catch (const scene::SceneError&) {
        return 0;
    }
    const scene::CameraFrame frame = scene::cameraFrame(parsed.camera);
    if (!finite(frame.forward) || !finite(frame.right) || !finite(frame.trueUp))
        std::abort();
    const scene::Scene visible = scene::dropInvisibleObjects(parsed);
    scene::analyseFeatures(visible);
    scene::computeSceneBounds(visible);
    scene::sphereLights(visible);
    // The shader generator is the rest of what a scene file reaches without a GL context.
    shadergen::generateSceneShaderCode(visible, {settings::ShaderVariant::Specialized});
    return 0;
}
