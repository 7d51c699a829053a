#pragma once
#include "film/Accumulation.h"
#include "gl/Framebuffer.h"
#include "gl/Texture.h"

#include <array>
#include <optional>

namespace render {

// The per-pixel state that persists between frames, twice over: each frame reads one set and
// writes the other, then they swap (reading and writing one texture in a draw is undefined).
//   estimate      RGBA32F  rgb: running mean of the radiance, a: samples accumulated
//   moments       RGBA32F  rgb: running sum of squared deviations (Welford), a: samples discarded
// With feature buffers (FEATURE_BUFFERS, film/Accumulation.h), two more:
//   albedoDepth     RGBA32F  rgb: first-hit albedo, a: camera distance
//   normalCoverage  RGBA32F  rgb: first-hit normal, a: fraction of samples that hit
// No random state persists: a sample's numbers follow from (seed, pixel, sample index), and
// the index from the two counts (shaders/modules/sampler.glsl).
class AccumulationTargets {
public:
    AccumulationTargets(int width, int height, bool features = false);
    // Both sets holding `initial` (a resumed render's accumulation), its size, with feature
    // targets where `initial` has features.
    explicit AccumulationTargets(const film::Accumulation& initial);

    struct Set {
        gl::Texture estimate;
        gl::Texture moments;
        std::optional<gl::Texture> albedoDepth;     // with feature buffers only
        std::optional<gl::Texture> normalCoverage;  // with feature buffers only
        gl::Framebuffer framebuffer;
    };

    const Set& previous() const { return sets_[current_]; }
    const Set& next() const { return sets_[1 - current_]; }
    // After a frame has been drawn into next(): it becomes previous().
    void swap() { current_ = 1 - current_; }

    bool hasFeatures() const { return sets_[0].albedoDepth.has_value(); }
    int width() const { return width_; }
    int height() const { return height_; }

private:
    int width_;
    int height_;
    std::array<Set, 2> sets_;
    int current_ = 0;
};

}  // namespace render
