// The seed's exponential smooth minimum, -log(exp(-k a) + exp(-k b)) / k, overflows or
// takes log(0) for large or tiny k unless rewritten; ours is computed as a stable
// log-sum-exp, so distances stay finite.
#include "hard/HardCaseSupport.h"

#include <gtest/gtest.h>

namespace {

std::string smoothPair(const std::string& sharpness)
{
    return "environment sky\n0 0 6\n0 0 0\n0 1 0\n40\n1\n3 4 5 30 30 30\n1\nsolid 0.7 0.5 0.3\n1\n"
           "0 0 0 0 0 0 0\n1\n0 0 smooth_union exp " +
           sharpness + " { sphere -0.6 0 0 0.8 sphere 0.6 0 0 0.8 }\n";
}

TEST(SmoothCsg, SharpnessTenThousandIsAPlainUnion)
{
    hard::RenderRequest smooth;
    smooth.sceneText = smoothPair("1e4");
    smooth.samplesPerPixel = 32;
    smooth.settings.samplesPerFrame = 32;
    smooth.settings.seed = 1;
    const hard::RenderOutput smoothOutput = hard::render(smooth);
    EXPECT_EQ(hard::nonFinitePixels(smoothOutput.radiance), 0);
    EXPECT_EQ(smoothOutput.discarded, 0u);

    hard::RenderRequest plain = smooth;
    plain.sceneText = "environment sky\n0 0 6\n0 0 0\n0 1 0\n40\n1\n3 4 5 30 30 30\n1\n"
                      "solid 0.7 0.5 0.3\n1\n0 0 0 0 0 0 0\n1\n"
                      "0 0 union { sphere -0.6 0 0 0.8 sphere 0.6 0 0 0.8 }\n";
    plain.settings.seed = 2;
    const std::string disagreement =
        hard::disagreementWithinNoise(smoothOutput, hard::render(plain));
    EXPECT_TRUE(disagreement.empty()) << disagreement;
}

TEST(SmoothCsg, SharpnessOneTenThousandthStaysFinite)
{
    // The blend swells the solid by log(2) / k = 6931 units: the camera ends up inside it.
    hard::RenderRequest request;
    request.sceneText = smoothPair("1e-4");
    request.samplesPerPixel = 16;
    request.settings.samplesPerFrame = 16;
    const hard::RenderOutput output = hard::render(request);
    EXPECT_EQ(hard::nonFinitePixels(output.radiance), 0);
    EXPECT_EQ(output.discarded, 0u);
}

}  // namespace
