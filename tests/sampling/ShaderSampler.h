#pragma once
// Runs the renderer's GLSL sampling routines and pdfs (shaders/modules/sampling.glsl,
// materials.glsl and environment.glsl, unmodified) on the GPU through a probe shader of the test's own
// (sampling_probe.frag), so that what is tested is the code that renders.
#include "gl/Shader.h"
#include "render/EnvironmentMap.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace sampling_tests {

// Values of the probe's uRoutine.
enum class SamplingRoutine {
    CosineHemisphere = 0,         // sampleCosineHemisphere / cosineHemispherePdf, local frame
    UniformCone = 1,              // sampleUniformCone / uniformConePdf, local frame
    BlinnPhongHalfVector = 2,     // sampleBlinnPhongHalfVector / blinnPhongHalfVectorPdf, local
    BlinnPhongMaterial = 3,       // blinnPhongSample / blinnPhongPdf / blinnPhongEvaluate, world
    RoughConductorMaterial = 4,   // roughConductorSample / Pdf / Evaluate, world
    RoughDielectricMaterial = 5,  // roughDielectricSample / Pdf / Evaluate, world
    EnvironmentMap = 6,           // sampleEnvironmentMap / environmentMapPdf, world
};

struct SamplingCase {
    SamplingRoutine routine = SamplingRoutine::CosineHemisphere;
    float exponent = 1.0f;
    float oneMinusCosThetaMax = 1.0f;
    glm::vec3 normal{0.0f, 0.0f, 1.0f};    // the material's only
    glm::vec3 outgoing{0.0f, 0.0f, 1.0f};  // the material's only: wo, unit
    glm::vec3 pigment{1.0f};               // the material's only: R0 of Schlick's Fresnel
    float roughness = 0.3f;                // the rough materials' GGX alpha
    float ior = 1.5f;                      // the rough dielectric's index
    bool entering = true;                  // the rough dielectric: wo outside the medium
    bool energyCompensation = true;        // the rough conductor's
    // The environment map's only: the map (uploaded for the draw) and its rotation about +y.
    const render::EnvironmentMap* environmentMap = nullptr;
    float environmentRotationDegrees = 0.0f;
};

// The directions of a pdf grid: cell (i, j) is centred on theta = (i + 1/2) thetaMax /
// thetaCells, phi = (j + 1/2) 2 pi / phiCells in `frame` (columns: tangent, bitangent, axis).
// Where the probe's numbers come from: the renderer's sampler (shaders/modules/sampler.glsl).
struct SamplerChoice {
    bool sobol = true;  // false: the independent random stream
    // false: every fragment is a pixel of its own at sample index `sampleIndex`, so
    // fragments are independent draws; true: the fragments are consecutive samples of one
    // pixel (row-major), from `sampleIndex` on.
    bool onePixelSequence = false;
    int sampleIndex = 0;
    // The sampler dimension the 2D numbers come from (the 1D lobe choice takes the next).
    int dimension = 4;
};

struct GridLayout {
    int thetaCells = 512;
    int phiCells = 512;
    float thetaMax = 1.5707963f;
    glm::mat3 frame{1.0f};
};

class ShaderSampler {
public:
    ShaderSampler();

    // width x height samples, one per fragment, its numbers drawn by the renderer's sampler
    // for `seed` as `choice` says. x, y, z: the direction; w: its pdf, or -1 where the
    // routine returned no sample.
    std::vector<glm::vec4> sampleDirections(const SamplingCase& samplingCase, int width, int height,
                                            std::uint64_t seed,
                                            const SamplerChoice& choice = {}) const;

    // The material's sample weights f cos / pdf (xyz; w = 1, or all zero for no sample).
    std::vector<glm::vec4> sampleWeights(const SamplingCase& samplingCase, int width, int height,
                                         std::uint64_t seed,
                                         const SamplerChoice& choice = {}) const;

    // The sampler's own numbers, one fragment each: x, y = sample2D(choice.dimension),
    // z = sample1D(choice.dimension).
    std::vector<glm::vec3> samplerNumbers(int width, int height, std::uint64_t seed,
                                          const SamplerChoice& choice) const;

    // Sobol's first two dimensions, unscrambled, of the points 0 .. count - 1, as the
    // sampler computes them (24-bit fractions).
    std::vector<glm::vec2> unscrambledSobol(int count) const;

    // The pdf at every grid cell centre, theta-major: index = j * thetaCells + i.
    std::vector<float> pdfOnGrid(const SamplingCase& samplingCase, const GridLayout& grid) const;

    // The material's f cos at every grid cell centre (RGB), same order.
    std::vector<glm::vec3> reflectanceOnGrid(const SamplingCase& samplingCase,
                                             const GridLayout& grid) const;

private:
    std::vector<glm::vec4> draw(int mode, const SamplingCase& samplingCase, int width, int height,
                                std::uint64_t seed, const GridLayout& grid,
                                const SamplerChoice& choice) const;

    gl::Program program_;
};

}  // namespace sampling_tests
