// Pigments: the colour of a surface point (albedo, or R0 for the Fresnel of glossy finishes).

#if HAS_TEXTURE_PIGMENT
uniform sampler2DArray uPigmentTextures;  // every image, resized to one size, sRGB-decoded
#endif

// 3D checkerboard of cubes of edge `size`: the first colour where
// floor(x/s) + floor(y/s) + floor(z/s) is even. `inward` is a point a hair inside the
// surface, so that a face lying exactly on a cube boundary (a floor at y = 0) takes one
// colour instead of flickering between two with rounding.
vec3 checkerPigment(vec3 inward, vec3 first, vec3 second, float size)
{
    vec3 cell = floor(inward / size);
    float parity = mod(cell.x + cell.y + cell.z, 2.0);
    return parity < 0.5 ? first : second;
}

#if HAS_TEXTURE_PIGMENT
// Triplanar mapping (the seed's section 2.7): the image projected along each axis, one tile
// every `tileSize` units, blended by the normal's components. The blend is taken in
// expectation: one projection is looked up, chosen with probability equal to its weight by
// `uProjection` (uniform on [0, 1)), so the estimate of every path is unbiased for the
// blended colour, which enters it linearly (stochastic texture filtering, Pharr et al.,
// "Filtering After Shading With Stochastic Texture Filtering", 2024). A texture lookup is
// the dearest single thing a path does on llvmpipe, and it runs for all 8 pixels of a SIMD
// group whenever one of them needs it: looking up every projection with a weight cost a
// group as many lookups as its pixel with the most (3 on a sphere), 1.13x scene 1's time and
// more on curved textured objects, for no gain in expectation. The sampler stratifies the
// choice over a pixel's samples, so it adds little noise (docs/PERFORMANCE.md). Filtering is
// trilinear; the mip level comes from the footprint of the path's ray cone at the point
// (explicit LOD: the screen-space derivatives GLSL offers mean nothing for a path's later
// vertices).
vec3 triplanarPigment(vec3 p, vec3 normal, float layer, float tileSize, float footprint,
                      float uProjection)
{
    vec3 weights = abs(normal);
    weights /= max(weights.x + weights.y + weights.z, 1e-6);
    vec3 q = p / tileSize;
    float lod = log2(max(footprint / tileSize * gPigmentTextureSize, 1e-6));
    // Beyond the weights' sum, which rounding can leave short of 1, the last projection
    // with a weight.
    int axis = weights.z > 0.0 ? 2 : (weights.y > 0.0 ? 1 : 0);
    if (uProjection < weights.x)
        axis = 0;
    else if (uProjection < weights.x + weights.y)
        axis = 1;
    vec2 projected = axis == 0 ? q.yz : (axis == 1 ? q.xz : q.xy);
    return textureLod(uPigmentTextures, vec3(projected, layer), lod).rgb;
}
#endif

// --- each kind's colour ------------------------------------------------------------------
// vec3 <kind>PigmentColor(int pigment, vec3 p, vec3 n, float footprint, float offSurface,
//                         float uPattern):
// the colour at surface point p with outward normal n; `footprint` is the ray cone's width
// there and `offSurface` how far outside the surface p may lie (0 for a point met on it).
// `uPattern`, uniform on [0, 1) from the sampler, makes the random choice of a pattern that
// is right in expectation (a texture's projection); the others ignore it.
// pigmentColor, which chooses among them by the pigment's kind, is generated from the
// pigment table (render/KindDispatchers.cpp) and follows this module.

vec3 solidPigmentColor(int pigment, vec3 p, vec3 n, float footprint, float offSurface,
                       float uPattern)
{
    return pigmentFirstColor(pigment);
}

#if HAS_CHECKER_PIGMENT
vec3 checkerPigmentColor(int pigment, vec3 p, vec3 n, float footprint, float offSurface,
                         float uPattern)
{
    // A hair, above float rounding at p, and never a hit tolerance for a point on the
    // surface: an inset that long moves the lookup across cube boundaries on a tilted
    // face, and a wall whose plane runs along cube edges (x - y = 10) showed bands of
    // the other colour half a pixel wide at every one of them.
    vec3 magnitude = abs(p);
    float rounding = 1e-6 * (1.0 + max(max(magnitude.x, magnitude.y), magnitude.z));
    float size = pigmentSize(pigment);
    float inset = max(max(1e-4 * min(size, 1.0), rounding), 2.0 * offSurface);
    return checkerPigment(p - inset * n, pigmentFirstColor(pigment),
                          pigmentSecondColor(pigment), size);
}
#endif

#if HAS_TEXTURE_PIGMENT
vec3 texturePigmentColor(int pigment, vec3 p, vec3 n, float footprint, float offSurface,
                         float uPattern)
{
    return triplanarPigment(p, n, pigmentTextureLayer(pigment), pigmentSize(pigment),
                            footprint, uPattern);
}
#endif
