// Radiance of rays that escape the scene. ENVIRONMENT_KIND is fixed by the host for the
// scene; the general shader reads the kind from a uniform instead. The kinds' codes
// (ENVIRONMENT_*) are generated #defines, from scene/Environments.h.

#if HAS_ENVIRONMENT_MAP
// The map (render/EnvironmentMap.h): rgb its radiance, rows top first (row 0 faces +y);
// a the density, per steradian, with which sampleEnvironmentMap picks a direction in that
// texel. Filtered bilinearly, repeating in longitude and clamped at the poles.
uniform sampler2D uEnvironmentMap;
// (width + 1) x (height + 1) texels: row r < height the conditional CDF over row r's
// columns, row `height` the marginal CDF over rows; read texel by texel, never filtered.
uniform sampler2D uEnvironmentDistribution;
// gEnvironmentIntensity scales the map; gEnvironmentRotation is the cos and sin of its turn
// about +y (generated from render/SceneUniforms.cpp's scene values).
#endif

#if HAS_ENVIRONMENT_MAP
// --- the map's orientation (docs/SCENE_FORMAT.md, "Environment") ---------------------------
// In the map's own frame, column u in [0, 1) (left to right) is the longitude
// phi = 2 pi (u - 1/2) and row v in [0, 1) (top to bottom) the polar angle theta = pi v from
// +y, with the direction (sin theta sin phi, cos theta, -sin theta cos phi): the middle column
// faces -z, the column at three quarters +x, the top row +y. (Mitsuba 3's envmap has the same
// convention.) The map's frame is the world's turned by the map's rotation about +y, by the
// right-hand rule: a turn of 90 degrees brings the middle column to face -x.

vec3 worldToMapFrame(vec3 d)
{
    float c = gEnvironmentRotation.x;
    float s = gEnvironmentRotation.y;
    return vec3(c * d.x - s * d.z, d.y, s * d.x + c * d.z);
}

vec3 mapFrameToWorld(vec3 m)
{
    float c = gEnvironmentRotation.x;
    float s = gEnvironmentRotation.y;
    return vec3(c * m.x + s * m.z, m.y, -s * m.x + c * m.z);
}

// (u, v) of a unit direction of the world.
vec2 environmentMapCoordinates(vec3 direction)
{
    vec3 m = worldToMapFrame(direction);
    float u = 0.5 + atan(m.x, -m.z) * INV_TWO_PI;
    float v = acos(clamp(m.y, -1.0, 1.0)) * INV_PI;
    return vec2(u, v);
}

// The texel holding (u, v): columns wrap around, rows stop at the poles.
ivec2 environmentMapTexel(vec2 uv)
{
    ivec2 size = textureSize(uEnvironmentMap, 0);
    int column = int(floor(uv.x * float(size.x)));
    column -= size.x * int(floor(float(column) / float(size.x)));
    int row = clamp(int(floor(uv.y * float(size.y))), 0, size.y - 1);
    return ivec2(column, row);
}

vec3 environmentMapRadiance(vec3 direction)
{
    // Level 0 explicitly: no derivatives in the path's divergent loops.
    return gEnvironmentIntensity *
           textureLod(uEnvironmentMap, environmentMapCoordinates(direction), 0.0).rgb;
}

// --- sampling the map: the inverse of its CDFs (PBRT 4e, section A.5; built on the host) ---

// The interval [cdf(i), cdf(i + 1)) of row `row` of the distribution that holds u, with
// cdf(0) = 0 and cdf(count) = 1, by bisection; `fraction` is where u lies in it. An interval
// of zero width (a texel of no radiance) never holds u.
int cumulativeInterval(int row, int count, float u, out float fraction)
{
    int low = 0;
    int high = count;
    // At most 16 halvings: the host refuses maps wider than 2^16 texels.
    for (int halving = 0; halving < 16 && low + 1 < high; ++halving) {
        int middle = (low + high) / 2;
        if (texelFetch(uEnvironmentDistribution, ivec2(middle, row), 0).r <= u)
            low = middle;
        else
            high = middle;
    }
    float below = texelFetch(uEnvironmentDistribution, ivec2(low, row), 0).r;
    float above = texelFetch(uEnvironmentDistribution, ivec2(low + 1, row), 0).r;
    fraction = clamp((u - below) / (above - below), 0.0, 1.0);
    return low;
}

struct EnvironmentMapSample {
    vec3 direction;  // unit, in the world
    float pdf;       // per steradian
};

// A direction with density proportional to the map's radiance, texel by texel: the row by
// the marginal CDF (u.y), the column by that row's conditional CDF (u.x), then a point
// uniform in solid angle inside the texel (uniform in longitude and in cos theta), so that
// the density is constant over each texel: the texel's probability over its solid angle,
// which the map's alpha holds.
EnvironmentMapSample sampleEnvironmentMap(vec2 u)
{
    ivec2 size = textureSize(uEnvironmentMap, 0);
    float rowFraction;
    int row = cumulativeInterval(size.y, size.y, u.y, rowFraction);
    float columnFraction;
    int column = cumulativeInterval(row, size.x, u.x, columnFraction);
    float phi = TWO_PI * ((float(column) + columnFraction) / float(size.x) - 0.5);
    float cosTop = cos(PI * float(row) / float(size.y));
    float cosBottom = cos(PI * float(row + 1) / float(size.y));
    float cosTheta = mix(cosTop, cosBottom, rowFraction);
    float sinTheta = sqrt(max(0.0, 1.0 - cosTheta * cosTheta));
    vec3 m = vec3(sinTheta * sin(phi), cosTheta, -sinTheta * cos(phi));
    return EnvironmentMapSample(mapFrameToWorld(m),
                                texelFetch(uEnvironmentMap, ivec2(column, row), 0).a);
}

// The density per steradian with which sampleEnvironmentMap picks `direction`.
float environmentMapPdf(vec3 direction)
{
    return texelFetch(uEnvironmentMap, environmentMapTexel(environmentMapCoordinates(direction)),
                      0)
        .a;
}
#endif

vec3 environmentRadiance(vec3 direction)
{
#if ENVIRONMENT_KIND == ENVIRONMENT_KIND_FROM_UNIFORM
    int kind = gEnvironmentKind;
#else
    const int kind = ENVIRONMENT_KIND;
#endif
    if (kind == ENVIRONMENT_SKY)
        // The seed's sky: a gradient in the world's up direction (y), whatever the camera.
        return 0.5 * vec3(0.7, 0.8, 1.0) * (1.0 - 0.5 * direction.y);
    if (kind == ENVIRONMENT_CONSTANT)
        return gEnvironmentColor;
#if HAS_ENVIRONMENT_MAP
    if (kind == ENVIRONMENT_MAP)
        return environmentMapRadiance(direction);
#endif
    return vec3(0.0);
}
