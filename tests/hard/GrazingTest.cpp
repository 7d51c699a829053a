// Rays that skim surfaces: a camera a hair above an endless plane looking along it, and rays
// tangent to a sphere's silhouette.
#include "hard/HardCaseSupport.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

TEST(Grazing, CameraAHairAbovePlaneSeesFloorBelowAndSkyAboveTheHorizon)
{
    hard::RenderRequest request;
    // Eye 1e-3 above a grey floor, looking along it; the sky is the format's gradient.
    request.sceneText = R"(
environment sky
0 0.001 0
0 0.001 -10
0 1 0
40
1
0 50 -20  4000 4000 4000
1
solid 0.5 0.5 0.5
1
0 0 0 0 0 0 0
1
0 0 polyhedron 1 0 1 0 0
)";
    request.samplesPerPixel = 64;
    request.settings.samplesPerFrame = 64;
    const hard::RenderOutput output = hard::render(request);
    EXPECT_EQ(hard::nonFinitePixels(output.radiance), 0);
    EXPECT_EQ(output.discarded, 0u);
    const io::Image& image = output.radiance;
    // Away from the horizon row each pixel is known in closed form (at its centre; the
    // tolerance covers the variation across a pixel and the noise): above, the sky
    // 0.5 (0.7, 0.8, 1) (1 - 0.5 y); below, the floor of albedo 0.5 lit by the point light,
    // rho / pi I cos / d^2, and by the whole sky, rho times the sky's cosine-weighted mean,
    // 0.5 (0.7, 0.8, 1) (1 - 0.5 * 2/3).
    const double tanHalf = std::tan(20.0 * M_PI / 180.0);
    const double skyRed = 0.5 * 0.7;
    int checked = 0;
    for (int row = 0; row < image.height; ++row) {
        const int glRow = image.height - 1 - row;
        const double v = (2.0 * (glRow + 0.5) - image.height) / image.height * tanHalf;
        if (std::abs(v) < 3.0 * tanHalf / image.height)
            continue;  // the rows at the horizon mix sky and floor
        for (int x = 0; x < image.width; x += 4) {
            const double u = (2.0 * (x + 0.5) - image.width) / image.height * tanHalf;
            // Camera frame: right (1, 0, 0), up (0, 1, 0), forward (0, 0, -1).
            const double length = std::sqrt(u * u + v * v + 1.0);
            const double dy = v / length;
            double expectedRed;
            if (dy > 0.0) {
                expectedRed = skyRed * (1.0 - 0.5 * dy);
            } else {
                const double t = 0.001 / -dy;
                const double px = u / length * t;
                const double pz = -1.0 / length * t;
                const double lx = 0.0 - px, ly = 50.0, lz = -20.0 - pz;
                const double d2 = lx * lx + ly * ly + lz * lz;
                const double direct = 0.5 / M_PI * 4000.0 * (ly / std::sqrt(d2)) / d2;
                expectedRed = direct + 0.5 * skyRed * (1.0 - 0.5 * 2.0 / 3.0);
            }
            EXPECT_NEAR(image.at(x, row, 0), expectedRed, 0.05 * expectedRed)
                << "pixel (" << x << ", " << row << ") " << (dy > 0.0 ? "(sky)" : "(floor)");
            ++checked;
        }
    }
    EXPECT_GT(checked, 500);
}

TEST(Grazing, SilhouetteOfAWhiteSphereInAFurnaceIsExactlyOne)
{
    // Every path ends in the environment of radiance 1 with weight 1, whatever the
    // silhouette pixels' rays do: any lost or doubled path shows.
    hard::RenderRequest request;
    request.sceneText = R"(
environment 1 1 1
0 0 4
0 0 0
0 1 0
40
0
1
solid 1 1 1
1
0 0 0 0 0 0 0
1
0 0 sphere 0 0 0 1
)";
    request.samplesPerPixel = 64;
    request.settings.samplesPerFrame = 16;
    const hard::RenderOutput output = hard::render(request);
    for (int y = 0; y < output.radiance.height; ++y)
        for (int x = 0; x < output.radiance.width; ++x)
            ASSERT_NEAR(output.radiance.at(x, y, 0), 1.0, 1e-5)
                << "pixel (" << x << ", " << y << ")";
}

}  // namespace
