// Pigments: the colour of a surface point (albedo, or R0 for the Fresnel of glossy finishes).

#if HAS_TEXTURE_PIGMENT
uniform sampler2DArray uPigmentTextures;  // every image, resized to one size, sRGB-decoded
uniform float uPigmentTextureSize;         // texels along the larger side of a layer
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
// every `tileSize` units, blended by the normal's components. Filtering is trilinear; the
// mip level comes from the footprint of the path's ray cone at the point (explicit LOD: the
// screen-space derivatives GLSL offers mean nothing for a path's later vertices).
// Only the projections with a weight are looked up, one per turn of a loop: llvmpipe
// executes both sides of every branch, so three lookups written out would all be paid at
// every point, while the loop goes round only as often as some pixel of the SIMD group
// needs (once where every pixel sees an axis-aligned plane, such as a floor).
vec3 triplanarPigment(vec3 p, vec3 normal, float layer, float tileSize, float footprint)
{
    vec3 weights = abs(normal);
    weights /= max(weights.x + weights.y + weights.z, 1e-6);
    vec3 q = p / tileSize;
    float lod = log2(max(footprint / tileSize * uPigmentTextureSize, 1e-6));
    vec3 color = vec3(0.0);
    int axis = weights.x > 0.0 ? 0 : (weights.y > 0.0 ? 1 : 2);
    for (int lookup = 0; lookup < 3 && axis < 3; ++lookup) {
        vec2 projected = axis == 0 ? q.yz : (axis == 1 ? q.xz : q.xy);
        float weight = axis == 0 ? weights.x : (axis == 1 ? weights.y : weights.z);
        color += weight * textureLod(uPigmentTextures, vec3(projected, layer), lod).rgb;
        axis = (axis < 1 && weights.y > 0.0) ? 1 : ((axis < 2 && weights.z > 0.0) ? 2 : 3);
    }
    return color;
}
#endif

// --- each kind's colour ------------------------------------------------------------------
// vec3 <kind>PigmentColor(int pigment, vec3 p, vec3 n, float footprint, float offSurface):
// the colour at surface point p with outward normal n; `footprint` is the ray cone's width
// there and `offSurface` how far outside the surface p may lie (0 for a point met on it).
// pigmentColor, which chooses among them by the pigment's kind, is generated from the
// pigment table (render/KindDispatchers.cpp) and follows this module.

vec3 solidPigmentColor(int pigment, vec3 p, vec3 n, float footprint, float offSurface)
{
    return pigmentFirstColor(pigment);
}

#if HAS_CHECKER_PIGMENT
vec3 checkerPigmentColor(int pigment, vec3 p, vec3 n, float footprint, float offSurface)
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
vec3 texturePigmentColor(int pigment, vec3 p, vec3 n, float footprint, float offSurface)
{
    return triplanarPigment(p, n, pigmentTextureLayer(pigment), pigmentSize(pigment),
                            footprint);
}
#endif
