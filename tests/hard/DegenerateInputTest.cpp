// Degenerate input, each either refused at parse time with a clear error or rendered finite.
// The decisions: a camera whose up vector is parallel to its view has no frame (error); a
// field of view of 0 or 180 degrees is no pinhole camera (error), while 0.01 and 179.9 are
// (finite); a sphere of radius 0 has no surface and would show as a speck the size of the hit
// tolerance (error); a disk is always of zero thickness and must render from both sides and
// edge-on (finite).
#include "hard/HardCaseSupport.h"
#include "scene/FileLookup.h"
#include "scene/SceneError.h"
#include "scene/SceneParser.h"

#include <gtest/gtest.h>

#include <sstream>

namespace {

std::string sceneWithCamera(const std::string& camera, const std::string& objects)
{
    return camera + "1\n2 5 4  30 30 30\n1\nsolid 0.6 0.6 0.6\n1\n0 0 0 0 0 0 0\n" + objects;
}

void expectParseError(const std::string& text, int line, const std::string& token,
                      const std::string& expectedPart)
{
    const scene::FileLookup lookup(HARD_CASES_DIR, scene::FileLookup::dataDirectory());
    try {
        scene::parseSceneText(text, "degenerate.in", lookup);
        FAIL() << "expected a parse error mentioning '" << expectedPart << "'";
    } catch (const scene::SceneError& error) {
        EXPECT_EQ(error.line(), line) << error.what();
        EXPECT_EQ(error.token(), token) << error.what();
        EXPECT_NE(std::string(error.what()).find(expectedPart), std::string::npos) << error.what();
    }
}

hard::RenderOutput renderText(const std::string& text)
{
    hard::RenderRequest request;
    request.sceneText = text;
    request.samplesPerPixel = 8;
    request.settings.samplesPerFrame = 8;
    return hard::render(request);
}

const char* const kOneSphere = "1\n0 0 sphere 0 0 0 1\n";

TEST(DegenerateInput, UpVectorParallelToViewIsAParseError)
{
    expectParseError(sceneWithCamera("0 5 0\n0 0 0\n0 2 0\n40\n", kOneSphere), 3, "0",
                     "not parallel to the view direction");
}

TEST(DegenerateInput, FieldOfViewOfZeroOrOneHundredEightyIsAParseError)
{
    expectParseError(sceneWithCamera("0 0 5\n0 0 0\n0 1 0\n0\n", kOneSphere), 4, "0",
                     "strictly between 0 and 180");
    expectParseError(sceneWithCamera("0 0 5\n0 0 0\n0 1 0\n180\n", kOneSphere), 4, "180",
                     "strictly between 0 and 180");
}

TEST(DegenerateInput, FieldOfViewNearZeroRendersFinite)
{
    const hard::RenderOutput output =
        renderText(sceneWithCamera("0 0 5\n0 0 0\n0 1 0\n0.01\n", kOneSphere));
    EXPECT_EQ(hard::nonFinitePixels(output.radiance), 0);
    EXPECT_EQ(output.discarded, 0u);
    EXPECT_GT(hard::meanRadiance(output.radiance), 0.0);  // the sphere's centre fills the view
}

TEST(DegenerateInput, FieldOfViewNearOneHundredEightyRendersFinite)
{
    const hard::RenderOutput output =
        renderText(sceneWithCamera("0 0 5\n0 0 0\n0 1 0\n179.9\n", kOneSphere));
    EXPECT_EQ(hard::nonFinitePixels(output.radiance), 0);
    EXPECT_EQ(output.discarded, 0u);
}

TEST(DegenerateInput, ZeroRadiusSphereIsAParseError)
{
    expectParseError(sceneWithCamera("0 0 5\n0 0 0\n0 1 0\n40\n", "1\n0 0 sphere 0 0 0 0\n"), 12,
                     "0", "positive number (sphere radius)");
}

TEST(DegenerateInput, ZeroThicknessDiskRendersFromAboveBelowAndEdgeOn)
{
    const std::string disk = "1\n0 0 disk 0 0 0  0 1 0  1\n";
    for (const char* camera : {"0 3 0.01\n0 0 0\n0 1 0\n40\n", "0 -3 0.01\n0 0 0\n0 1 0\n40\n",
                               "0 0 3\n0 0 0\n0 1 0\n40\n"}) {
        const hard::RenderOutput output = renderText(sceneWithCamera(camera, disk));
        EXPECT_EQ(hard::nonFinitePixels(output.radiance), 0) << camera;
        EXPECT_EQ(output.discarded, 0u) << camera;
    }
}

}  // namespace
