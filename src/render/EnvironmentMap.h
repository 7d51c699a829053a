#pragma once
// An environment map made ready for the shaders (shaders/modules/environment.glsl): its
// radiance, and the distribution by which next-event estimation chooses directions towards
// it, built on the host once per map (not per frame, nor per pixel). GL-free: the textures
// are made from it by render/EnvironmentMapTextures.
//
// The distribution is piecewise constant over the map's texels: the 2D inversion of PBRT 4e,
// section A.5 (a marginal distribution over rows, a conditional one over the columns of
// each row). A texel's probability is its luminance times the solid angle it covers, so
// that the density over directions follows the radiance and not the image's rows (a plain
// luminance would favour the poles' squeezed rows by 1 / sin theta). The luminance is that
// of the bilinear reconstruction the shader looks up, averaged over the texel (weights 1/8,
// 3/4, 1/8 along each axis): every direction whose filtered radiance is not zero then has a
// density that is not zero, so light sampling alone (without MIS) misses nothing. Within a
// texel the shader picks a direction uniform in solid angle, so the density is constant
// over each texel: its probability over its solid angle, which `texels` holds beside the
// radiance.
#include "io/Image.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <filesystem>
#include <memory>
#include <vector>

namespace render {

// The largest map read: 8192 x 4096 texels (a common "8K" map) takes 512 MiB as RGBA floats.
constexpr int kMaxEnvironmentMapWidth = 8192;
constexpr int kMaxEnvironmentMapHeight = 4096;

struct EnvironmentMap {
    int width = 0;
    int height = 0;
    // RGBA per texel, row by row from the top (row 0 faces +y): rgb the radiance as the file
    // holds it (negative values, which lossy compression leaves, made 0), a the density per
    // steradian with which the shader's sampleEnvironmentMap picks a direction in the texel.
    std::vector<float> texels;
    // cumulativeWidth() x (height + 1) values, row by row: row r < height holds the
    // conditional CDF over row r's columns (width + 1 values from 0 to 1), row `height` the
    // marginal CDF over the rows (height + 1 values from 0 to 1); the rest is padding.
    std::vector<float> cumulative;
    // The radiance integrated over the sphere of directions, per channel (W/m^2 per channel
    // for radiance in W/(m^2 sr)): what the light's power is made of.
    glm::dvec3 integral{0.0};

    int cumulativeWidth() const { return std::max(width, height) + 1; }
    // The probability the distribution gives texel (column, row): the product of the two
    // CDFs' steps, as the shader's bisection chooses it.
    double texelProbability(int column, int row) const;
    // The solid angle texel row `row` covers, each texel: (2 pi / width)(cos theta_top -
    // cos theta_bottom).
    double texelSolidAngle(int row) const;
};

// From a latitude-longitude image, rows top first: channels R, G, B (a grey image's one
// channel stands for all three; further channels are ignored). Throws std::runtime_error
// when a value is not finite.
EnvironmentMap buildEnvironmentMap(const io::Image& image);

// Reads the file with OpenImageIO (EXR, Radiance .hdr, PFM, ...) and builds its map. Throws
// std::runtime_error with the library's reason when the file cannot be read.
EnvironmentMap loadEnvironmentMap(const std::filesystem::path& path);

// The map of the scene's environment, or nullptr where its environment is no map. Throws
// std::runtime_error naming the scene file, the line and the map, with the reason, when the
// map cannot be read.
std::shared_ptr<const EnvironmentMap> loadSceneEnvironmentMap(const scene::Scene& scene);

}  // namespace render
