// A scene compiles only the code of the features it uses (MISSION.md: "a scene with no glass
// pays nothing for glass"): the rough materials, their energy compensation and the thin lens
// are compiled into the shaders of the scenes that have them and into no other. Each of them
// reads uniforms of its own; the GL reports a uniform as active only when code that the
// compiler kept reads it, so the uniforms say whether the code is there.
#include "render/PathTracerProgram.h"
#include "shadergen/SceneShaderGenerator.h"
#include "support/RenderRun.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace render_tests {
namespace {

using namespace testing_support;

// The uniforms only the microfacet materials, the rough conductor (and its compensation) and
// the thin lens read.
const std::vector<std::string> kMicrofacetUniforms = {"uSeparableMasking"};
const std::vector<std::string> kConductorUniforms = {"uEnergyCompensation", "uFinishConductors"};
const std::vector<std::string> kLensUniforms = {"uLensRadius", "uFocusDistance"};

std::vector<std::string> activeOf(const scene::Scene& scene,
                                  const std::vector<std::string>& uniforms)
{
    const shadergen::SceneShaderCode code =
        shadergen::generateSceneShaderCode(scene, shadergen::ShaderBuild{});
    const auto shaders = sourceDirectory() / "shaders";
    const render::PathTracerProgram program(render::assemblePathTracerSource(code, shaders),
                                            settings::PathKernel::Fragment, shaders);
    std::vector<std::string> active;
    for (const std::string& name : uniforms)
        if (program.program().uniformLocation(name.c_str()) >= 0)
            active.push_back(name);
    return active;
}

std::string ball(const std::string& camera, const std::string& finish)
{
    return "0 0 5\n0 0 0\n0 1 0\n45 " + camera + "\n1\n2 4 3  9 9 9\n1 solid 0.8 0.6 0.3\n1\n" +
           finish + "\n1\n0 0 sphere 0 0 0 1\n";
}

TEST(FeatureCode, AClassicSceneCompilesNoRoughMaterialAndNoLens)
{
    const scene::Scene scene = sceneFromText(ball("", "0 0 0  20 0 0 0"));
    EXPECT_TRUE(activeOf(scene, kMicrofacetUniforms).empty());
    EXPECT_TRUE(activeOf(scene, kConductorUniforms).empty());
    EXPECT_TRUE(activeOf(scene, kLensUniforms).empty());
}

TEST(FeatureCode, ARoughConductorCompilesItsCompensationButNoLens)
{
    const scene::Scene scene = sceneFromText(ball("", "rough_conductor 0.3 gold"));
    EXPECT_EQ(activeOf(scene, kConductorUniforms), kConductorUniforms);
    EXPECT_TRUE(activeOf(scene, kLensUniforms).empty());
}

TEST(FeatureCode, ARoughDielectricCompilesTheMicrofacetsButNoConductor)
{
    const scene::Scene scene = sceneFromText(ball("", "rough_dielectric 0.3 1.5"));
    EXPECT_EQ(activeOf(scene, kMicrofacetUniforms), kMicrofacetUniforms);
    EXPECT_TRUE(activeOf(scene, kConductorUniforms).empty());
}

TEST(FeatureCode, ALensCompilesTheLensAlone)
{
    const scene::Scene scene = sceneFromText(ball("lens 0.1 5", "0 0 0  0 0 0 0"));
    EXPECT_EQ(activeOf(scene, kLensUniforms), kLensUniforms);
    EXPECT_TRUE(activeOf(scene, kMicrofacetUniforms).empty());
    EXPECT_TRUE(activeOf(scene, kConductorUniforms).empty());
}

}  // namespace
}  // namespace render_tests
