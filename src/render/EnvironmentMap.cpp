#include "render/EnvironmentMap.h"

#include "io/ImageFile.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace render {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Rec. 709 luminance; every weight is positive, so it is zero only where all channels are.
double luminance(const glm::dvec3& rgb)
{
    return 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b;
}

// The bilinear filter's weights over a texel's span, for the texel itself and its two
// neighbours along one axis: the integral of each one's tent over the span.
constexpr double kFilterWeights[3] = {0.125, 0.75, 0.125};

// A CDF from `weights` as floats: count + 1 values from exactly 0 to exactly 1 (uniform
// where all weights are zero, so that the bisection still finds an interval).
void writeCumulative(const std::vector<double>& weights, float* out)
{
    const std::size_t count = weights.size();
    double total = 0.0;
    for (double weight : weights)
        total += weight;
    double running = 0.0;
    out[0] = 0.0f;
    for (std::size_t i = 0; i < count; ++i) {
        running += weights[i];
        out[i + 1] =
            static_cast<float>(total > 0.0 ? running / total : static_cast<double>(i + 1) / count);
    }
    out[count] = 1.0f;
}

}  // namespace

double EnvironmentMap::texelSolidAngle(int row) const
{
    return 2.0 * kPi / width * (std::cos(kPi * row / height) - std::cos(kPi * (row + 1) / height));
}

double EnvironmentMap::texelProbability(int column, int row) const
{
    const std::size_t stride = static_cast<std::size_t>(cumulativeWidth());
    const float* marginal = &cumulative[static_cast<std::size_t>(height) * stride];
    const float* conditional = &cumulative[static_cast<std::size_t>(row) * stride];
    return (static_cast<double>(marginal[row + 1]) - marginal[row]) *
           (static_cast<double>(conditional[column + 1]) - conditional[column]);
}

EnvironmentMap buildEnvironmentMap(const io::Image& image)
{
    if (image.width < 1 || image.height < 1 || image.channels < 1)
        throw std::runtime_error("the image is empty");
    if (image.width > kMaxEnvironmentMapWidth || image.height > kMaxEnvironmentMapHeight)
        throw std::runtime_error(
            "the image is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
            "; an environment map may be at most " + std::to_string(kMaxEnvironmentMapWidth) + "x" +
            std::to_string(kMaxEnvironmentMapHeight));
    EnvironmentMap map;
    const int width = map.width = image.width;
    const int height = map.height = image.height;
    auto at = [&](int column, int row) { return static_cast<std::size_t>(row) * width + column; };

    std::vector<glm::dvec3> radiance(static_cast<std::size_t>(width) * height);
    for (int row = 0; row < height; ++row)
        for (int column = 0; column < width; ++column) {
            glm::dvec3 value;
            for (int channel = 0; channel < 3; ++channel) {
                const float v = image.at(column, row, image.channels >= 3 ? channel : 0);
                if (!std::isfinite(v))
                    throw std::runtime_error("the value at column " + std::to_string(column) +
                                             ", row " + std::to_string(row) +
                                             " is not finite (NaN or infinity)");
                value[channel] = std::max(0.0f, v);
            }
            radiance[at(column, row)] = value;
        }

    // The bilinear reconstruction averaged over each texel: columns wrap around (the
    // texture repeats in longitude), rows stop at the poles (it is clamped there).
    std::vector<glm::dvec3> filtered(radiance.size(), glm::dvec3(0.0));
    for (int row = 0; row < height; ++row)
        for (int column = 0; column < width; ++column)
            for (int dr = -1; dr <= 1; ++dr)
                for (int dc = -1; dc <= 1; ++dc) {
                    const int r = std::clamp(row + dr, 0, height - 1);
                    const int c = (column + dc + width) % width;
                    filtered[at(column, row)] +=
                        kFilterWeights[dr + 1] * kFilterWeights[dc + 1] * radiance[at(c, r)];
                }

    const std::size_t stride = static_cast<std::size_t>(map.cumulativeWidth());
    map.cumulative.assign(stride * (height + 1), 0.0f);
    std::vector<double> rowWeights(height, 0.0);
    std::vector<double> weights(width);
    for (int row = 0; row < height; ++row) {
        const double solidAngle = map.texelSolidAngle(row);
        for (int column = 0; column < width; ++column) {
            const glm::dvec3& value = filtered[at(column, row)];
            weights[column] = luminance(value) * solidAngle;
            rowWeights[row] += weights[column];
            map.integral += value * solidAngle;
        }
        writeCumulative(weights, &map.cumulative[static_cast<std::size_t>(row) * stride]);
    }
    writeCumulative(rowWeights, &map.cumulative[static_cast<std::size_t>(height) * stride]);

    map.texels.resize(4 * radiance.size());
    for (int row = 0; row < height; ++row) {
        const double solidAngle = map.texelSolidAngle(row);
        for (int column = 0; column < width; ++column) {
            float* texel = &map.texels[4 * at(column, row)];
            const glm::dvec3& value = radiance[at(column, row)];
            texel[0] = static_cast<float>(value.r);
            texel[1] = static_cast<float>(value.g);
            texel[2] = static_cast<float>(value.b);
            texel[3] = static_cast<float>(map.texelProbability(column, row) / solidAngle);
        }
    }
    return map;
}

EnvironmentMap loadEnvironmentMap(const std::filesystem::path& path)
{
    // The header first: a file that claims a huge size is refused before anything is
    // allocated for it.
    const io::ImageHeader size = io::readImageHeader(path);
    if (size.width > kMaxEnvironmentMapWidth || size.height > kMaxEnvironmentMapHeight)
        throw std::runtime_error(
            "the image is " + std::to_string(size.width) + "x" + std::to_string(size.height) +
            "; an environment map may be at most " + std::to_string(kMaxEnvironmentMapWidth) + "x" +
            std::to_string(kMaxEnvironmentMapHeight));
    return buildEnvironmentMap(io::readImage(path));
}

std::shared_ptr<const EnvironmentMap> loadSceneEnvironmentMap(const scene::Scene& scene)
{
    const scene::Environment& environment = scene.environment;
    if (environment.kind != scene::EnvironmentKind::Map)
        return nullptr;
    try {
        return std::make_shared<const EnvironmentMap>(loadEnvironmentMap(environment.mapPath));
    } catch (const std::exception& error) {
        throw std::runtime_error(scene.sourcePath.string() + ":" +
                                 std::to_string(environment.line) + ": environment map '" +
                                 environment.mapName + "': " + error.what());
    }
}

}  // namespace render
