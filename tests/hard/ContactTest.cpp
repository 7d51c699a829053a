// Surfaces that touch: no light leaks through the contact and no acne appears along it.
#include "hard/HardCaseSupport.h"
#include "support/PinholeCamera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace {

// Two boxes sharing a face make one flat top; under a point light that top is a Lambertian
// plane with a closed form, rho / pi * I cos(theta) / d^2, seam or no seam. A self-shadowing
// seam (acne) or a crack would break it.
TEST(Contact, TwoBoxesSharingAFaceLightTheirCommonTopLikeOnePlane)
{
    hard::RenderRequest request;
    // Camera straight above the top face (y = 1), the seam at x = 0 runs through the view.
    request.sceneText = R"(
environment none
0 4 0
0 0 0
0 0 -1
30
1
0.3 3 0.2  9 9 9
1
solid 0.6 0.6 0.6
1
0 0 0 0 0 0 0
2
0 0 box -1 0 0  1 1 2
0 0 box 1 0 0  1 1 2
)";
    request.width = 48;
    request.height = 48;
    request.samplesPerPixel = 16;
    request.settings.samplesPerFrame = 16;
    const hard::RenderOutput output = hard::render(request);
    // Pixel centres only: each pixel's average over its area is compared with the value at
    // its centre, so the tolerance allows the curvature of cos/d^2 across one pixel.
    const double tanHalf = std::tan(15.0 * M_PI / 180.0);
    int checked = 0;
    for (int row = 0; row < request.height; ++row)
        for (int x = 0; x < request.width; ++x) {
            const int glRow = request.height - 1 - row;
            const double u = (2.0 * (x + 0.5) - request.width) / request.height * tanHalf;
            const double v = (2.0 * (glRow + 0.5) - request.height) / request.height * tanHalf;
            // right = (1, 0, 0), true up = (0, 0, -1), forward = (0, -1, 0)
            const double dx = u, dy = -1.0, dz = -v;
            const double t = (4.0 - 1.0) / -dy;
            const double px = dx * t, pz = dz * t;
            if (std::abs(px) > 1.9 || std::abs(pz) > 1.9)
                continue;
            const double lx = 0.3 - px, ly = 3.0 - 1.0, lz = 0.2 - pz;
            const double d2 = lx * lx + ly * ly + lz * lz;
            const double expected = 0.6 / M_PI * 9.0 * (ly / std::sqrt(d2)) / d2;
            EXPECT_NEAR(output.radiance.at(x, row, 0), expected, 0.01 * expected)
                << "top face pixel (" << x << ", " << row << ")";
            ++checked;
        }
    EXPECT_GT(checked, 1000);
}

// A black sphere resting on a white floor under a light straight above it: the floor under
// the sphere's shadow receives no direct light and nothing can bounce light there (the
// sphere is black, the floor cannot light itself), so its pixels must be exactly 0.
TEST(Contact, SphereRestingOnPlaneLeaksNoLightIntoItsShadow)
{
    hard::RenderRequest request;
    request.sceneText = R"(
environment none
0 3 3
0 0 0
0 1 0
40
1
0 5 0  20 20 20
2
solid 0.8 0.8 0.8
solid 0 0 0
1
0 0 0 0 0 0 0
2
0 0 polyhedron 1 0 1 0 0
1 0 sphere 0 1 0 1
)";
    request.samplesPerPixel = 32;
    request.settings.samplesPerFrame = 32;
    const hard::RenderOutput output = hard::render(request);
    // The umbra on the floor: points with |(x, z)| < 0.95 * 5/4... every floor point under
    // the sphere whose line to the light crosses it. Find them by ray casting from the camera.
    const double tanHalf = std::tan(20.0 * M_PI / 180.0);
    const double f[3] = {0.0, -3.0 / std::sqrt(18.0), -3.0 / std::sqrt(18.0)};
    const double r[3] = {1.0, 0.0, 0.0};
    const double u[3] = {0.0, 3.0 / std::sqrt(18.0), -3.0 / std::sqrt(18.0)};
    int umbraPixels = 0;
    for (int row = 0; row < request.height; ++row)
        for (int x = 0; x < request.width; ++x) {
            const int glRow = request.height - 1 - row;
            bool allInUmbra = true;
            // The whole pixel must see umbra floor, not sphere and not lit floor.
            for (int corner = 0; corner < 4 && allInUmbra; ++corner) {
                const double cu =
                    (2.0 * (x + (corner & 1)) - request.width) / request.height * tanHalf;
                const double cv =
                    (2.0 * (glRow + (corner >> 1)) - request.height) / request.height * tanHalf;
                double d[3];
                for (int i = 0; i < 3; ++i)
                    d[i] = cu * r[i] + cv * u[i] + f[i];
                if (d[1] >= 0.0) {
                    allInUmbra = false;
                    break;
                }
                const double t = -3.0 / d[1];
                const double p[3] = {t * d[0], 0.0, 3.0 + t * d[2]};
                // Visible floor point (not hidden by the sphere from the camera)...
                const double oc[3] = {0.0 - 0.0, 3.0 - 1.0, 3.0 - 0.0};
                const double b = oc[0] * d[0] + oc[1] * d[1] + oc[2] * d[2];
                const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                const double c = oc[0] * oc[0] + oc[1] * oc[1] + oc[2] * oc[2] - 1.0;
                if (b * b - dd * c > 0.0) {
                    allInUmbra = false;
                    break;
                }
                // ...in the umbra: the line to the light passes inside the sphere with margin.
                const double toLight[3] = {0.0 - p[0], 5.0, 0.0 - p[2]};
                const double length =
                    std::sqrt(toLight[0] * toLight[0] + 25.0 + toLight[2] * toLight[2]);
                const double w[3] = {toLight[0] / length, toLight[1] / length, toLight[2] / length};
                const double pc[3] = {0.0 - p[0], 1.0, 0.0 - p[2]};
                const double along = pc[0] * w[0] + pc[1] * w[1] + pc[2] * w[2];
                const double miss2 = pc[0] * pc[0] + 1.0 + pc[2] * pc[2] - along * along;
                if (miss2 > 0.8 * 0.8)
                    allInUmbra = false;
            }
            if (!allInUmbra)
                continue;
            ++umbraPixels;
            EXPECT_EQ(output.radiance.at(x, row, 0), 0.0f)
                << "umbra pixel (" << x << ", " << row << ") receives light";
        }
    EXPECT_GT(umbraPixels, 20);
}

// The same contact seen for acne: a black sphere resting on a white floor under a point
// light to one side. Wherever the floor sees the light past the sphere, it is a Lambertian
// plane lit by a point, rho / pi * I cos(theta) / d^2 exactly (the sphere is black, so
// nothing else lights it); a shadow ray that starts too close to the floor or finds the
// sphere's surface near the contact would darken scattered pixels (acne). Compared pixel by
// pixel (as tests/render/DirectLightingTest.cpp does for a plane alone) with the closed form
// averaged over each pixel, on every pixel whose whole area is floor at least a margin away
// from the sphere's silhouette and from the edge of its shadow.
TEST(Contact, SphereRestingOnPlaneShowsNoAcneOnTheLitFloorAroundIt)
{
    constexpr double kAlbedo = 0.8;
    constexpr double kIntensity = 12.0;
    const glm::dvec3 light(1.5, 4.0, 1.0);
    const glm::dvec3 centre(0.0, 1.0, 0.0);
    // Far more than the hit tolerance and the offsets of shadow rays (a few thousandths
    // here), and more than a pixel's footprint (about 0.09), so that no compared pixel
    // touches the silhouette or the shadow's edge.
    constexpr double kMargin = 0.15;

    scene::Camera camera;
    camera.eye = glm::vec3(0.0f, 3.5f, 4.5f);
    camera.target = glm::vec3(0.0f, 0.6f, 0.0f);
    camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    camera.verticalFieldOfViewDegrees = 45.0f;
    hard::RenderRequest request;
    std::ostringstream text;
    text << "environment none\n"
         << camera.eye.x << " " << camera.eye.y << " " << camera.eye.z << "\n"
         << camera.target.x << " " << camera.target.y << " " << camera.target.z << "\n"
         << "0 1 0\n"
         << camera.verticalFieldOfViewDegrees << "\n"
         << "1\n"
         << light.x << " " << light.y << " " << light.z << "  " << kIntensity << " " << kIntensity
         << " " << kIntensity << "\n"
         << "2\nsolid " << kAlbedo << " " << kAlbedo << " " << kAlbedo << "\nsolid 0 0 0\n"
         << "1\n0 0 0  0 0 0 0\n"
         << "2\n0 0 polyhedron 1  0 1 0 0\n1 0 sphere 0 1 0 1\n";
    request.sceneText = text.str();
    request.width = 64;
    request.height = 48;
    request.samplesPerPixel = 256;
    request.settings.samplesPerFrame = 64;
    const hard::RenderOutput output = hard::render(request);
    const testing_support::PinholeCamera pinhole(camera, request.width, request.height);
    const glm::dvec3 eye = pinhole.eye();

    auto floorPoint = [&](const glm::dvec3& direction) {
        return eye + direction * (-eye.y / direction.y);
    };
    auto radiance = [&](const glm::dvec3& direction) {
        const glm::dvec3 toLight = light - floorPoint(direction);
        const double distance = glm::length(toLight);
        return kAlbedo / M_PI * kIntensity * (toLight.y / distance) / (distance * distance);
    };
    // Floor seen past the sphere (the line of sight misses it by the margin) and lit past it
    // (so does the line from the floor point to the light).
    auto litFloorClearOfSphere = [&](const glm::dvec3& direction) {
        if (direction.y >= 0.0 ||
            testing_support::distanceToRay(centre, eye, direction) < 1.0 + kMargin)
            return false;
        const glm::dvec3 p = floorPoint(direction);
        return testing_support::distanceToRay(centre, p, glm::normalize(light - p)) > 1.0 + kMargin;
    };

    int compared = 0;
    int nearContact = 0;
    double worst = 0.0;
    std::string worstPixel;
    for (int y = 0; y < request.height; ++y)
        for (int x = 0; x < request.width; ++x) {
            if (!pinhole.wholePixel(x, y, litFloorClearOfSphere))
                continue;
            ++compared;
            const glm::dvec3 seen = floorPoint(pinhole.direction(x + 0.5, y + 0.5));
            if (glm::length(seen) < 2.0)
                ++nearContact;
            const double expected = pinhole.pixelAverage(x, y, 8, radiance);
            const double got = (output.radiance.at(x, y, 0) + output.radiance.at(x, y, 1) +
                                output.radiance.at(x, y, 2)) /
                               3.0;
            // 5 standard deviations of the pixel's own noise (the jitter across the pixel),
            // plus 0.2 % for the hit point's tolerance and float rounding. Within 2 of the
            // contact that is under 1 %: 3 samples in 256 lost to acne exceed it.
            const double allowance =
                5.0 * std::sqrt(output.statistics.at(x, y, 2)) + 2e-3 * expected + 1e-7;
            const double z = std::abs(got - expected) / allowance;
            if (z > worst) {
                worst = z;
                std::ostringstream where;
                where << "pixel (" << x << ", " << y << "): render " << got << ", closed form "
                      << expected << ", " << got / expected << " of it";
                worstPixel = where.str();
            }
        }
    EXPECT_EQ(output.discarded, 0u);
    EXPECT_GT(compared, 1500) << "too few lit floor pixels compared";
    EXPECT_GT(nearContact, 150) << "too few compared pixels within 2 of the contact point";
    EXPECT_LE(worst, 1.0) << "expected every lit floor pixel around the sphere to equal "
                             "rho/pi I cos(theta)/d^2 within 5 sigma + 0.2 %; worst of "
                          << compared << " pixels was " << worst << " allowances off, "
                          << worstPixel;
}

}  // namespace
