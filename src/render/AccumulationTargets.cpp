#include "render/AccumulationTargets.h"

#include "gl/GlError.h"

#include <vector>

namespace render {

namespace {

std::uint64_t splitMix64(std::uint64_t& state)
{
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

AccumulationTargets::Set makeSet(int width, int height, const std::vector<std::uint32_t>& seeds)
{
    const std::vector<float> zeros(static_cast<std::size_t>(width) * height * 4, 0.0f);
    gl::Texture estimate =
        gl::createTexture2D(GL_RGBA32F, width, height, GL_RGBA, GL_FLOAT, zeros.data());
    gl::Texture moments =
        gl::createTexture2D(GL_RGBA32F, width, height, GL_RGBA, GL_FLOAT, zeros.data());
    gl::Texture randomState = gl::createTexture2D(GL_RGBA32UI, width, height, GL_RGBA_INTEGER,
                                                  GL_UNSIGNED_INT, seeds.data());
    gl::Framebuffer framebuffer({&estimate, &moments, &randomState});
    return {std::move(estimate), std::move(moments), std::move(randomState),
            std::move(framebuffer)};
}

std::vector<std::uint32_t> seedPixels(int width, int height, std::uint64_t seed)
{
    std::vector<std::uint32_t> seeds;
    seeds.reserve(static_cast<std::size_t>(width) * height * 4);
    for (std::uint64_t pixel = 0; pixel < static_cast<std::uint64_t>(width) * height; ++pixel)
        for (std::uint32_t word : initialRandomState(seed, pixel))
            seeds.push_back(word);
    return seeds;
}

}  // namespace

std::array<std::uint32_t, 4> initialRandomState(std::uint64_t seed, std::uint64_t pixelIndex)
{
    // Seed and pixel are mixed before either is expanded, so neighbouring pixels and
    // neighbouring seeds start in unrelated places of the generator's period.
    std::uint64_t state = seed;
    std::uint64_t mixedSeed = splitMix64(state);
    std::uint64_t stream = mixedSeed ^ (pixelIndex * 0xD1B54A32D192ED03ull);
    const std::uint64_t low = splitMix64(stream);
    const std::uint64_t high = splitMix64(stream);
    std::array<std::uint32_t, 4> words = {
        static_cast<std::uint32_t>(low), static_cast<std::uint32_t>(low >> 32),
        static_cast<std::uint32_t>(high), static_cast<std::uint32_t>(high >> 32)};
    if ((words[0] | words[1] | words[2] | words[3]) == 0)
        words[0] = 1;  // xoshiro's one forbidden state
    return words;
}

AccumulationTargets::AccumulationTargets(int width, int height, std::uint64_t seed)
    : width_(width),
      height_(height),
      sets_{makeSet(width, height, seedPixels(width, height, seed)),
            makeSet(width, height, seedPixels(width, height, seed))}
{
    gl::throwOnGlError("creating the accumulation targets");
}

}  // namespace render
