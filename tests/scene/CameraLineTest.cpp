// scene::cameraLine: the window's camera written as a scene file's camera, which must read
// back as exactly that camera.
#include "scene/CameraLine.h"
#include "scene/SceneTestSupport.h"

#include <cmath>

namespace scene_tests {
namespace {

using namespace scene;

// The camera a scene file starting with `cameraText` has (the rest: no lights, one ball).
Camera readBack(const std::string& cameraText)
{
    return parse("# the camera, as pasted\n" + cameraText +
                 "\n0\n1 solid 1 1 1\n1 0 0 0 0 0 0 0\n1\n0 0 sphere 0 0 0 1\n")
        .camera;
}

void expectSameBits(const Camera& read, const Camera& written)
{
    EXPECT_EQ(read.eye, written.eye);
    EXPECT_EQ(read.target, written.target);
    EXPECT_EQ(read.up, written.up);
    EXPECT_EQ(read.verticalFieldOfViewDegrees, written.verticalFieldOfViewDegrees);
    ASSERT_EQ(read.lens.has_value(), written.lens.has_value());
    if (written.lens) {
        EXPECT_EQ(read.lens->apertureRadius, written.lens->apertureRadius);
        EXPECT_EQ(read.lens->focusDistance, written.lens->focusDistance);
    }
}

TEST(CameraLine, ReadsBackAsExactlyTheSameCamera)
{
    // Numbers as an orbit leaves them: no short decimal is exact.
    Camera camera;
    camera.eye = {1.0f / 3.0f, -8.4f * 0.7071068f, 4.44f + 1e-6f};
    camera.target = {0.1f, 1e-7f, -12345.678f};
    camera.up = {0.0f, -0.0f, 1.0f};
    camera.verticalFieldOfViewDegrees = 35.000004f;
    const std::string line = cameraLine(camera);
    EXPECT_EQ(line.find('\n'), std::string::npos) << "one line: " << line;
    expectSameBits(readBack(line), camera);
}

TEST(CameraLine, WritesTheThinLensAndReadsItBack)
{
    Camera camera;
    camera.eye = {0.0f, 1.5f, 5.0f};
    camera.target = {0.0f, 0.5f, -1.6f};
    camera.verticalFieldOfViewDegrees = 40.0f;
    camera.lens = ThinLens{0.12f, 6.4f};
    const std::string line = cameraLine(camera);
    EXPECT_EQ(line, "0 1.5 5  0 0.5 -1.6  0 1 0  40  lens 0.12 6.4");
    expectSameBits(readBack(line), camera);
}

TEST(CameraLine, ScenesOwnCameraReadsBackFromItsLine)
{
    const Scene scene = parse(sceneWithObjects(1, "0 0 sphere 0 0 0 1\n"));
    expectSameBits(readBack(cameraLine(scene.camera)), scene.camera);
    EXPECT_EQ(cameraLine(scene.camera), "0 0 5  0 0 0  0 1 0  45");
}

}  // namespace
}  // namespace scene_tests
