#pragma once
#include "film/ToneCurve.h"
#include "gl/Shader.h"
#include "gl/Texture.h"
#include "gl/VertexArray.h"
#include "io/Image.h"
#include "settings/Choices.h"

#include <filesystem>

namespace render {

// The display pass (shaders/modules/tone_map.frag): linear radiance to a picture, drawn to
// the window or to an offscreen target that is read back for image files, by any of the tone
// curves (one program: the curve is a uniform, so the window's panel switches it at once).
class ToneMapper {
public:
    // The original program's exposure: radiance is multiplied by it before the curve.
    static constexpr float kDefaultExposure = film::ToneCurve::kDefaultExposure;

    explicit ToneMapper(const std::filesystem::path& shaderDirectory);

    // Draws `estimate` (its lower-left width x height texels) to whatever framebuffer is
    // bound, of size target.
    void draw(const gl::Texture& estimate, int width, int height, int targetWidth, int targetHeight,
              const gl::VertexArray& triangle, float exposure = kDefaultExposure,
              settings::ToneCurveKind curve = film::ToneCurve::kDefaultCurve) const;

    // The tone-mapped picture of `estimate` as display values in [0, 1], top row first.
    io::Image render(const gl::Texture& estimate, int width, int height,
                     const gl::VertexArray& triangle, float exposure = kDefaultExposure,
                     settings::ToneCurveKind curve = film::ToneCurve::kDefaultCurve) const;

private:
    gl::Program program_;
};

// Reads `width` x `height` RGB pixels of the bound read framebuffer as values in [0, 1],
// top row first.
io::Image readDisplayPixels(int width, int height);

// The same from the window's back buffer, after the picture was drawn and before it is shown.
io::Image readWindowPixels(int width, int height);

}  // namespace render
