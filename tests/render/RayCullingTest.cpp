// Per-ray culling (shaders/modules/ray_culling.glsl) is exact: a render with it agrees with a
// render without it (--no-culling) within noise, for every kind of piece a scene can be
// culled by and the rays it is hardest for (grazing, inside a solid, specular chains whose
// tolerance grows, a field of view so wide that culling is switched off). Independent seeds,
// so the noise-aware comparison of the regression tests applies.
#include "support/ImageComparison.h"
#include "support/RenderRun.h"

#include <gtest/gtest.h>

namespace render_tests {
namespace {

using namespace testing_support;

struct CullingCase {
    std::string name;
    std::string scene;
};

void PrintTo(const CullingCase& culling, std::ostream* out)
{
    *out << culling.name;
}

// A closed room of six planes, one wall a transformed polyhedron, with marched solids (shapes
// with a closed form are met exactly and never culled, so these are a rounded box and CSG
// blocks: a torus with a sphere in its hole, a cone cut by a sphere, a cylinder scooped by
// one), a point light and a sphere light; the camera in a corner.
const char* const kRoom = R"(
-2.5 2.5 2.5   0 0.5 0   0 1 0   70
1
0 3 0   6 6 6
3
solid 0.8 0.8 0.8
solid 0.8 0.3 0.2
solid 0.2 0.4 0.8
3
0 0 0  0 0 0 0
0 0 0  40 0 0 0
8 8 8  0 0 0 0
7
0 0 polyhedron 5  0 1 0 0  0 -1 0 4  1 0 0 3  0 0 1 3  0 0 -1 3
2 0 translate 3 0 0 rotate 0 0 1 90 polyhedron 1  0 1 0 0
1 1 translate 1 0.5 -1 rotate 0 1 0 30 rounded_box 0 0 0  0.5 0.5 0.5  0.1
2 0 union { torus -1 0.3 -1  0.6 0.25  sphere -1 0.3 -1  0.3 }
1 1 intersection { cone 1.5 1.5 1.5  1 1.5  sphere 1.5 1 1.5  0.8 }
2 0 difference { cylinder -1.5 0.5 1.5  0.4 0.5  sphere -1.5 1 1.5  0.25 }
0 2 sphere 0 3.5 0  0.3
)";

// An open scene seen from a hair above the floor: rays graze it up to the horizon; a cone
// opening downwards cut by a sphere, a sphere and a rounded box above it.
const char* const kHorizon = R"(
0 0.05 6   0 0.3 0   0 1 0   50
1
-3 6 4   60 60 60
2
checker 0.9 0.9 0.9  0.2 0.2 0.2  0.5
solid 0.8 0.3 0.2
1
0 0 0  0 0 0 0
4
0 0 polyhedron 1  0 1 0 0
1 0 sphere -1 0.5 0  0.5
1 0 intersection { cone 1.2 1 -1  1 2  sphere 1.2 0.5 -1  0.6 }
1 0 rounded_box 0 0.2 -3  2 0.2 0.2  0.05
)";

// The camera inside a glass sphere, mirror and Lambertian spheres outside it, under the
// sky: rays start inside a solid, and mirror chains keep their growing tolerance.
const char* const kInsideGlass = R"(
0 0 0   0 0 -1   0 1 0   60
0
2
solid 1 1 1
solid 0.9 0.6 0.3
3
0 0 0  0 0 1 1.5
0 0 0  0 1 0 0
0 0 0  0 0 0 0
4
0 0 sphere 0 0 0  1.5
0 1 sphere -1 0 -4  1
1 2 sphere 1.5 0.5 -3.5  0.7
1 2 polyhedron 1  0 1 0 1.6
)";

// A field of view of 175 degrees: the camera's cone widens faster than culling's margins
// allow, so camera rays are not culled while the rays after them are.
const char* const kWideAngle = R"(
0 1 3   0 1 0   0 1 0   175
1
0 4 0   30 30 30
1
solid 0.8 0.8 0.8
1
0 0 0  0 0 0 0
3
0 0 polyhedron 2  0 1 0 0  0 0 1 2
0 0 sphere 0 1 0  0.7
0 0 rounded_box 1.5 0.5 0.5  0.3 0.5 0.3  0.05
)";

// User SDFs culled by the planes their files declare (`// @hull`) as well as their balls: the
// molecule of classic scene 6 (scenes/sdf/lattice.glsl: a tetrahedron and a cube about it),
// turned and enlarged, and the knot of scene 4 (scenes/sdf/knot.glsl: the slab that holds
// it), turned on its side and shrunk, in a room with a sphere light, so that shadow rays
// cross the planes at every angle. A hull that cuts the molecule's atoms to a triangle
// (its tetrahedron's planes at 0.5 instead of 0.97) fails (capped z^2 1500 against 1322);
// one that shaves only their tips passes, as any local error too small for the comparison.
const char* const kHulls = R"(
0 0 5.5   0 0 0   0 1 0   60
1
2 2 4   10 10 10
3
solid 0.8 0.8 0.8
solid 0.9 0.2 0.1
solid 0.2 0.4 0.9
3
0 0 0  0 0 0 0
0 0 0  0 0 1 1.5
8 8 8  0 0 0 0
5
0 0 polyhedron 4  0 1 0 3  0 -1 0 3  0 0 1 4  1 0 0 4
1 0 translate -0.8 0.2 0 rotate 0 1 0 30 scale 1.5 lattice 0 0 0
2 0 translate 1.6 -1.2 -1.5 scale 0.3 rotate 1 0 0 70 knot 0 0 0
0 2 sphere 1.5 2.6 1.5  0.3
0 0 polyhedron 1  -1 0 0 4
)";

class RayCulling : public ::testing::TestWithParam<CullingCase> {};

TEST_P(RayCulling, RenderAgreesWithTheUnculledRender)
{
    const scene::Scene scene = sceneFromText(GetParam().scene, GetParam().name + ".in");
    settings::RenderSettings culled = settingsWithSeed(21);
    settings::RenderSettings unculled = settingsWithSeed(22);
    unculled.rayCulling = false;
    const RenderedImage withCulling = renderScene(scene, 64, 48, 64, culled);
    const RenderedImage withoutCulling = renderScene(scene, 64, 48, 64, unculled);
    const Comparison comparison = compareImages(withCulling, withoutCulling);
    EXPECT_TRUE(comparison.passed()) << GetParam().name << ": culled against unculled:\n"
                                     << comparison.describe();
}

// The general shader culls nothing by ray (it finds surfaces through the hierarchy over the
// objects, shape_interpreter.glsl): on the same scenes, hardest for what leaves objects out,
// it agrees with the specialised shader.
TEST_P(RayCulling, GeneralShaderThroughTheHierarchyAgreesWithTheSpecialisedShader)
{
    // The closed room was skipped while the general shader marched the whole scene at every
    // step: a few pixels (4) were left without a sample, their paths abandoned at llvmpipe's
    // loop budget (constants.glsl) each time. Marched object by object it passes.
    const scene::Scene scene = sceneFromText(GetParam().scene, GetParam().name + ".in");
    settings::RenderSettings specialized = settingsWithSeed(23);
    settings::RenderSettings general = settingsWithSeed(24);
    general.variant = settings::ShaderVariant::FeaturesOnly;
    const RenderedImage a = renderScene(scene, 64, 48, 32, specialized);
    const RenderedImage b = renderScene(scene, 64, 48, 32, general);
    const Comparison comparison = compareImages(b, a);
    EXPECT_TRUE(comparison.passed()) << GetParam().name << ": general against specialised:\n"
                                     << comparison.describe();
}

INSTANTIATE_TEST_SUITE_P(
    Scene, RayCulling,
    ::testing::Values(CullingCase{"ClosedRoom", kRoom}, CullingCase{"GrazingHorizon", kHorizon},
                      CullingCase{"InsideGlass", kInsideGlass},
                      CullingCase{"WideAngle", kWideAngle}, CullingCase{"UserSdfHulls", kHulls}),
    [](const ::testing::TestParamInfo<CullingCase>& info) { return info.param.name; });

}  // namespace
}  // namespace render_tests
