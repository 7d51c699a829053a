#pragma once
#include "gl/Texture.h"

#include <filesystem>
#include <vector>

namespace render {

// The pigments' images as one sRGB texture array with mipmaps, trilinear filtering and
// repeat wrapping. GLSL cannot index an array of samplers with a value computed at run time
// (the original program did, and Mesa rightly rejects it); a texture array is indexed by
// a coordinate instead. All layers share one size, so every image is resampled to the
// largest width and height among them.
struct PigmentTextures {
    gl::Texture texture{GL_TEXTURE_2D_ARRAY};
    int size = 1;  // texels along the larger side of a layer
};

// Throws std::runtime_error naming the file when an image cannot be read.
PigmentTextures loadPigmentTextures(const std::vector<std::filesystem::path>& files);

}  // namespace render
