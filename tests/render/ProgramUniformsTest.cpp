// The host and the shader agree on every uniform (render/ProgramUniforms.h): a uniform set
// under a name the shader does not declare, or declared and never set, is an error, not a
// value GL quietly drops or leaves at zero; and every setting the shader reads is a live
// uniform of the shader that has every feature.
#include "render/PathTracerProgram.h"
#include "render/ProgressiveRenderer.h"
#include "render/ScenePreparation.h"
#include "scene/SceneParser.h"
#include "settings/SettingsTable.h"
#include "support/RenderRun.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

namespace render_tests {
namespace {

using namespace testing_support;

scene::Scene scene1()
{
    return scene::parseSceneFile(sourceDirectory() / "scenes" / "scene1.in");
}

std::string errorOf(const std::function<void()>& action)
{
    try {
        action();
    } catch (const std::logic_error& error) {
        return error.what();
    }
    return "";
}

TEST(ProgramUniforms, SettingAMisspeltUniformIsAnError)
{
    const render::PreparedScene prepared =
        render::prepareScene(scene1(), {}, render::defaultShaderDirectory());
    render::PathTracerProgram program(prepared.pathTracerSource, settings::PathKernel::Fragment,
                                      render::defaultShaderDirectory());
    program.program().use();
    const std::string error = errorOf([&] { program.uniforms().set("uHitTolerence", 0.5f); });
    EXPECT_NE(error.find("uHitTolerence, which the shader does not declare"), std::string::npos)
        << error;
}

TEST(ProgramUniforms, AUniformDeclaredAndNeverSetIsAnError)
{
    const render::PreparedScene prepared =
        render::prepareScene(scene1(), {}, render::defaultShaderDirectory());
    render::PathTracerProgram program(prepared.pathTracerSource, settings::PathKernel::Fragment,
                                      render::defaultShaderDirectory());
    program.program().use();
    program.uniforms().set("uHitTolerance", 0.5f);
    const std::string error = errorOf([&] { program.uniforms().checkEveryDeclaredSet(); });
    EXPECT_NE(error.find("the shader declares uniforms the host never sets"), std::string::npos)
        << error;
    EXPECT_NE(error.find("uMaxBounces"), std::string::npos) << error;
    EXPECT_EQ(error.find("uHitTolerance"), std::string::npos) << "it was set: " << error;
}

// The renderer checks every shader it builds once its uniforms are set (the constructor
// throws otherwise): each way of building one.
TEST(ProgramUniforms, EveryShaderTheRendererBuildsHasEveryUniformSet)
{
    settings::RenderSettings general;
    general.variant = settings::ShaderVariant::General;
    settings::RenderSettings featuresOnly;
    featuresOnly.variant = settings::ShaderVariant::FeaturesOnly;
    settings::RenderSettings shapesOnly;
    shapesOnly.variant = settings::ShaderVariant::ShapesOnly;
    settings::RenderSettings window;
    window.switchableEnvironment = true;
    settings::RenderSettings exact;
    exact.exactGeometry = true;
    settings::RenderSettings counters;
    counters.profileCounters = true;
    for (const settings::RenderSettings& settings :
         {settings::RenderSettings{}, general, featuresOnly, shapesOnly, window, exact, counters})
        EXPECT_NO_THROW(render::ProgressiveRenderer(scene1(), 8, 6, settings))
            << "variant " << static_cast<int>(settings.variant) << ", exact "
            << settings.exactGeometry;
}

// Live: the shader reads it (GL leaves out a uniform it optimised away). The general shader
// has every feature; the specialised shader of a scene with marched objects (the classic
// scene 6) culls them by the ray, which the general shader does not.
TEST(ProgramUniforms, EverySettingTheShaderReadsIsALiveUniform)
{
    shadergen::ShaderBuild general;
    general.variant = settings::ShaderVariant::General;
    const render::PreparedScene generalScene1 =
        render::prepareScene(scene1(), general, render::defaultShaderDirectory());
    const render::PreparedScene specializedScene6 =
        render::prepareScene(scene::parseSceneFile(sourceDirectory() / "scenes" / "scene6.in"), {},
                             render::defaultShaderDirectory());
    render::PathTracerProgram first(generalScene1.pathTracerSource, settings::PathKernel::Fragment,
                                    render::defaultShaderDirectory());
    render::PathTracerProgram second(specializedScene6.pathTracerSource,
                                     settings::PathKernel::Fragment,
                                     render::defaultShaderDirectory());
    for (const settings::SettingRow& row : settings::settingRows()) {
        if (!row.isUniform())
            continue;
        const std::string name = settings::uniformName(row.field);
        EXPECT_TRUE(first.program().uniformLocation(name.c_str()) >= 0 ||
                    second.program().uniformLocation(name.c_str()) >= 0)
            << name << " (" << row.description.uniformModule << ") is read by neither shader";
    }
}

}  // namespace
}  // namespace render_tests
