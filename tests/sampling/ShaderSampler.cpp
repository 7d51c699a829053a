#include "sampling/ShaderSampler.h"

#include "gl/Framebuffer.h"
#include "gl/GlError.h"
#include "gl/Texture.h"
#include "gl/VertexArray.h"
#include "render/EnvironmentMapTextures.h"
#include "render/PathTracerProgram.h"
#include "render/SceneUniforms.h"
#include "shadergen/ShaderCodes.h"
#include "shadergen/ShaderSource.h"
#include "shadergen/UniformBlock.h"
#include "support/TestPaths.h"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <optional>

namespace sampling_tests {

namespace {

shadergen::ShaderSource probeSource()
{
    const auto shaders = testing_support::sourceDirectory() / "shaders";
    shadergen::ShaderSource source;
    // What the modules expect the scene's preamble to define: Blinn-Phong and the rough
    // materials, one element in each scene array (unused here), and the kinds' codes.
    source.add("<preamble: the sampling probe>",
               "#version 330 core\n"
               "#define HAS_BLINN_PHONG 1\n#define HAS_MIRROR 0\n#define HAS_DIELECTRIC 0\n"
               "#define HAS_ROUGH_CONDUCTOR 1\n#define HAS_ROUGH_DIELECTRIC 1\n"
               "#define HAS_MICROFACET 1\n"
               "#define SHAPE_PARAMETER_ARRAY_SIZE 1\n#define SHAPE_PARAMETERS_READ_ONCE 0\n"
               "#define OBJECT_ARRAY_SIZE 1\n"
               "#define PIGMENT_ARRAY_SIZE 1\n#define FINISH_ARRAY_SIZE 1\n"
               "#define LIGHT_ARRAY_SIZE 1\n"
               "#define HAS_ENVIRONMENT_MAP 1\n#define ENVIRONMENT_KIND_FROM_UNIFORM (-1)\n"
               "#define ENVIRONMENT_KIND ENVIRONMENT_MAP\n" +
                   shadergen::shaderCodeDefines());
    const std::vector<std::string> modules = {
        "constants.glsl",  "rng.glsl",        "sampler.glsl",          "sampling.glsl",
        "scene_data.glsl", "fresnel.glsl",    "ggx_albedo_table.glsl", "microfacet.glsl",
        "materials.glsl",  "environment.glsl"};
    source.add("<generated: the uniforms, read once per pixel>",
               shadergen::uniformBlock(render::pathTracerUniformDeclarations(), modules));
    for (const std::string& module : modules)
        source.addFile(shaders / "modules" / module, shaders);
    source.addFile(testing_support::testsDirectory() / "sampling" / "sampling_probe.frag",
                   testing_support::testsDirectory());
    return source;
}

gl::Program compileProbe()
{
    const shadergen::ShaderSource fragment = probeSource();
    return gl::Program(
        render::fullscreenVertexSource(testing_support::sourceDirectory() / "shaders"),
        fragment.text(), "the sampling probe",
        [fragment](const std::string& log) { return fragment.explainLog(log); });
}

}  // namespace

ShaderSampler::ShaderSampler() : program_(compileProbe()) {}

std::vector<glm::vec4> ShaderSampler::draw(int mode, const SamplingCase& samplingCase, int width,
                                           int height, std::uint64_t seed, const GridLayout& grid,
                                           const SamplerChoice& choice) const
{
    const gl::Texture target =
        gl::createTexture2D(GL_RGBA32F, width, height, GL_RGBA, GL_FLOAT, nullptr);
    const gl::Framebuffer framebuffer({&target});
    const gl::VertexArray triangle;

    program_.use();
    auto location = [&](const char* name) { return program_.uniformLocation(name); };
    glUniform1i(location("uMode"), mode);
    glUniform1i(location("uSampler"),
                settings::choiceCode(choice.sobol ? settings::SamplerKind::Sobol
                                                  : settings::SamplerKind::Independent));
    glUniform2ui(location("uSeed"), static_cast<GLuint>(seed), static_cast<GLuint>(seed >> 32));
    glUniform1i(location("uSequence"), choice.onePixelSequence ? 1 : 0);
    glUniform1i(location("uSampleIndex"), choice.sampleIndex);
    glUniform1i(location("uDimension"), choice.dimension);
    glUniform1f(location("uImageWidth"), static_cast<float>(width));
    glUniform1i(location("uRoutine"), static_cast<int>(samplingCase.routine));
    glUniform1f(location("uExponent"), samplingCase.exponent);
    glUniform1f(location("uOneMinusCosThetaMax"), samplingCase.oneMinusCosThetaMax);
    glUniform3fv(location("uNormal"), 1, glm::value_ptr(samplingCase.normal));
    glUniform3fv(location("uOutgoing"), 1, glm::value_ptr(samplingCase.outgoing));
    glUniform3fv(location("uPigment"), 1, glm::value_ptr(samplingCase.pigment));
    glUniformMatrix3fv(location("uGridFrame"), 1, GL_FALSE, glm::value_ptr(grid.frame));
    glUniform2f(location("uGridCells"), static_cast<float>(grid.thetaCells),
                static_cast<float>(grid.phiCells));
    glUniform1f(location("uGridThetaMax"), grid.thetaMax);
    glUniform1i(location("uDielectricFresnel"),
                settings::choiceCode(settings::FresnelModel::Schlick));
    glUniform1f(location("uRoughness"), samplingCase.roughness);
    glUniform1f(location("uIor"), samplingCase.ior);
    glUniform1i(location("uEntering"), samplingCase.entering ? 1 : 0);
    glUniform1i(location("uEnergyCompensation"), samplingCase.energyCompensation ? 1 : 0);

    std::optional<render::EnvironmentMapTextures> environment;
    if (samplingCase.environmentMap != nullptr) {
        environment = render::uploadEnvironmentMap(*samplingCase.environmentMap);
        glUniform1i(location("uEnvironmentMap"), render::EnvironmentMapTextures::kRadianceUnit);
        glUniform1i(location("uEnvironmentDistribution"),
                    render::EnvironmentMapTextures::kDistributionUnit);
        glUniform1f(location("uEnvironmentIntensity"), 1.0f);
        const float angle = glm::radians(samplingCase.environmentRotationDegrees);
        glUniform2f(location("uEnvironmentRotation"), std::cos(angle), std::sin(angle));
    }

    framebuffer.bindForDrawing();
    glViewport(0, 0, width, height);
    triangle.drawFullscreenTriangle();
    framebuffer.bindForReading(0);
    std::vector<glm::vec4> values(static_cast<std::size_t>(width) * height);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, values.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    gl::throwOnGlError("running the sampling probe");
    return values;
}

std::vector<glm::vec4> ShaderSampler::sampleDirections(const SamplingCase& samplingCase, int width,
                                                       int height, std::uint64_t seed,
                                                       const SamplerChoice& choice) const
{
    return draw(0, samplingCase, width, height, seed, GridLayout{}, choice);
}

std::vector<glm::vec4> ShaderSampler::sampleWeights(const SamplingCase& samplingCase, int width,
                                                    int height, std::uint64_t seed,
                                                    const SamplerChoice& choice) const
{
    return draw(2, samplingCase, width, height, seed, GridLayout{}, choice);
}

std::vector<glm::vec3> ShaderSampler::samplerNumbers(int width, int height, std::uint64_t seed,
                                                     const SamplerChoice& choice) const
{
    const std::vector<glm::vec4> values =
        draw(4, SamplingCase{}, width, height, seed, GridLayout{}, choice);
    std::vector<glm::vec3> numbers(values.size());
    for (std::size_t i = 0; i < values.size(); ++i)
        numbers[i] = glm::vec3(values[i]);
    return numbers;
}

std::vector<glm::vec2> ShaderSampler::unscrambledSobol(int count) const
{
    const std::vector<glm::vec4> values =
        draw(5, SamplingCase{}, count, 1, 0, GridLayout{}, SamplerChoice{});
    std::vector<glm::vec2> points(values.size());
    for (std::size_t i = 0; i < values.size(); ++i)
        points[i] = glm::vec2(values[i]);
    return points;
}

std::vector<float> ShaderSampler::pdfOnGrid(const SamplingCase& samplingCase,
                                            const GridLayout& grid) const
{
    const std::vector<glm::vec4> values =
        draw(1, samplingCase, grid.thetaCells, grid.phiCells, 0, grid, SamplerChoice{});
    std::vector<float> pdf(values.size());
    for (std::size_t i = 0; i < values.size(); ++i)
        pdf[i] = values[i].w;
    return pdf;
}

std::vector<glm::vec3> ShaderSampler::reflectanceOnGrid(const SamplingCase& samplingCase,
                                                        const GridLayout& grid) const
{
    const std::vector<glm::vec4> values =
        draw(3, samplingCase, grid.thetaCells, grid.phiCells, 0, grid, SamplerChoice{});
    std::vector<glm::vec3> reflectance(values.size());
    for (std::size_t i = 0; i < values.size(); ++i)
        reflectance[i] = glm::vec3(values[i]);
    return reflectance;
}

}  // namespace sampling_tests
