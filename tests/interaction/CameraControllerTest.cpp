// interaction::CameraController: what each mouse and key action does to the camera, in plain
// values (no GL).
#include "interaction/CameraController.h"
#include "scene/FileLookup.h"
#include "scene/SceneParser.h"

#include <gtest/gtest.h>

#include <cmath>

namespace interaction_tests {
namespace {

using interaction::CameraController;

scene::Camera lookingAtOrigin()
{
    scene::Camera camera;
    camera.eye = {0.0f, 0.0f, 5.0f};
    camera.target = {0.0f, 0.0f, 0.0f};
    camera.up = {0.0f, 1.0f, 0.0f};
    camera.verticalFieldOfViewDegrees = 60.0f;
    return camera;
}

float distanceToTarget(const scene::Camera& camera)
{
    return glm::length(camera.eye - camera.target);
}

// The angle between the view direction and the up vector, in degrees.
float angleFromUp(const scene::Camera& camera)
{
    const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
    return glm::degrees(std::acos(glm::dot(forward, glm::normalize(camera.up))));
}

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance = 1e-4f)
{
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

TEST(CameraOrbit, KeepsTheTargetTheDistanceAndTheUpVector)
{
    CameraController controller(lookingAtOrigin(), 3.0f);
    controller.orbit({37.0f, -21.0f}, 480.0f);
    const scene::Camera& camera = controller.camera();
    expectNear(camera.target, {0.0f, 0.0f, 0.0f});
    EXPECT_NEAR(distanceToTarget(camera), 5.0f, 1e-4f);
    expectNear(camera.up, {0.0f, 1.0f, 0.0f});
}

TEST(CameraOrbit, ADragToTheRightTurnsTheEyeToTheLeftByHalfATurnPerViewportHeight)
{
    CameraController controller(lookingAtOrigin(), 3.0f);
    // A quarter of a turn: half the viewport's height.
    controller.orbit({240.0f, 0.0f}, 480.0f);
    // From +z, a quarter turn to the camera's left (-x) around +y.
    expectNear(controller.camera().eye, {-5.0f, 0.0f, 0.0f});
}

TEST(CameraOrbit, ADragDownRaisesTheEye)
{
    CameraController controller(lookingAtOrigin(), 3.0f);
    controller.orbit({0.0f, 80.0f}, 480.0f);  // 30 degrees
    EXPECT_NEAR(controller.camera().eye.y, 5.0f * std::sin(glm::radians(30.0f)), 1e-4f);
}

TEST(CameraOrbit, StopsShortOfLookingAlongTheUpVector)
{
    CameraController controller(lookingAtOrigin(), 3.0f);
    controller.orbit({0.0f, 5000.0f}, 480.0f);
    EXPECT_NEAR(angleFromUp(controller.camera()), 180.0f - 1.0f, 1e-2f)
        << "the eye stops at 89 degrees above the target, looking down";
    controller.orbit({0.0f, -10000.0f}, 480.0f);
    EXPECT_NEAR(angleFromUp(controller.camera()), 1.0f, 1e-2f);
    const scene::CameraFrame frame = scene::cameraFrame(controller.camera());
    EXPECT_TRUE(std::isfinite(frame.right.x) && std::isfinite(frame.trueUp.y));
}

TEST(CameraPan, MovesEyeAndTargetSoThatThePointUnderTheMouseFollowsIt)
{
    CameraController controller(lookingAtOrigin(), 3.0f);
    // The view is 2 * 5 * tan(30 deg) high at the target: a drag of the viewport's height
    // to the right moves the camera that far to the left.
    controller.pan({480.0f, 0.0f}, 480.0f);
    const float viewHeight = 2.0f * 5.0f * std::tan(glm::radians(30.0f));
    expectNear(controller.camera().eye, {-viewHeight, 0.0f, 5.0f});
    expectNear(controller.camera().target, {-viewHeight, 0.0f, 0.0f});
    controller.pan({0.0f, 240.0f}, 480.0f);  // down: the camera goes up
    EXPECT_NEAR(controller.camera().target.y, viewHeight / 2.0f, 1e-4f);
}

TEST(CameraDolly, TakesTheEyeTowardsTheTargetAndNeverOnto)
{
    CameraController controller(lookingAtOrigin(), 3.0f);
    controller.dolly(1.0f);
    EXPECT_NEAR(distanceToTarget(controller.camera()), 5.0f * (1.0f - CameraController::kDollyStep),
                1e-4f);
    controller.dolly(-2.0f);
    EXPECT_GT(distanceToTarget(controller.camera()), 5.0f);
    controller.dolly(10000.0f);
    EXPECT_GT(distanceToTarget(controller.camera()), 0.0f);
    expectNear(controller.camera().target, {0.0f, 0.0f, 0.0f});
}

TEST(CameraFly, SpeedFollowsTheSceneSizeAndShiftIsFaster)
{
    CameraController small(lookingAtOrigin(), 1.0f);
    CameraController large(lookingAtOrigin(), 10.0f);
    small.fly({0.0f, 0.0f, 1.0f}, 0.5f, false);
    large.fly({0.0f, 0.0f, 1.0f}, 0.5f, false);
    const float smallStep = 5.0f - small.camera().eye.z;
    EXPECT_NEAR(smallStep, CameraController::kFlySpeed * 0.5f, 1e-5f);
    EXPECT_NEAR(5.0f - large.camera().eye.z, 10.0f * smallStep, 1e-4f);

    CameraController fast(lookingAtOrigin(), 1.0f);
    fast.fly({0.0f, 0.0f, 1.0f}, 0.5f, true);
    EXPECT_NEAR(5.0f - fast.camera().eye.z, CameraController::kFastFactor * smallStep, 1e-4f);
}

TEST(CameraFly, MovesEyeAndTargetAlongTheViewsAxesAndTheUpVector)
{
    CameraController controller(lookingAtOrigin(), 2.0f);
    controller.fly({1.0f, 0.0f, 0.0f}, 1.0f, false);  // D: right
    expectNear(controller.camera().eye, {1.0f, 0.0f, 5.0f});
    expectNear(controller.camera().target, {1.0f, 0.0f, 0.0f});
    controller.fly({0.0f, 1.0f, 0.0f}, 1.0f, false);  // E: up
    expectNear(controller.camera().eye, {1.0f, 1.0f, 5.0f});
}

TEST(CameraController, InputOfNothingLeavesTheCameraExactlyAsItWas)
{
    // The window asks every frame; a view that changed restarts the accumulation.
    scene::Camera camera = lookingAtOrigin();
    camera.eye = {0.3f, 1.7f, 4.1f};
    CameraController controller(camera, 3.0f);
    controller.orbit({0.0f, 0.0f}, 480.0f);
    controller.pan({0.0f, 0.0f}, 480.0f);
    controller.dolly(0.0f);
    controller.fly({0.0f, 0.0f, 0.0f}, 0.1f, true);
    EXPECT_TRUE(scene::sameCamera(controller.camera(), camera));
}

TEST(CameraHome, RReturnsToTheFilesCamera)
{
    CameraController controller(lookingAtOrigin(), 3.0f);
    controller.orbit({100.0f, 50.0f}, 480.0f);
    controller.fly({1.0f, 0.0f, 1.0f}, 0.3f, true);
    ASSERT_FALSE(scene::sameCamera(controller.camera(), lookingAtOrigin()));
    controller.returnHome();
    EXPECT_TRUE(scene::sameCamera(controller.camera(), lookingAtOrigin()));
}

TEST(CameraHome, ANewHomeReplacesAMovedCameraOnlyWhenTold)
{
    CameraController controller(lookingAtOrigin(), 3.0f);
    controller.orbit({100.0f, 0.0f}, 480.0f);
    const scene::Camera moved = controller.camera();
    scene::Camera edited = lookingAtOrigin();
    edited.eye = {0.0f, 2.0f, 6.0f};

    controller.setHome(edited, 3.0f, false);
    EXPECT_TRUE(scene::sameCamera(controller.camera(), moved));
    controller.returnHome();
    EXPECT_TRUE(scene::sameCamera(controller.camera(), edited));

    controller.orbit({100.0f, 0.0f}, 480.0f);
    controller.setHome(lookingAtOrigin(), 3.0f, true);
    EXPECT_TRUE(scene::sameCamera(controller.camera(), lookingAtOrigin()));
}

// The showcase scene: its look-at point (1 10 -2) lies behind the back wall, and the
// surface under the view's centre is the front sphere (centre (1 0 1), radius 1).
scene::Scene scene1()
{
    return scene::parseSceneFile(std::string(RAYTRACER_SOURCE_DIR) + "/scenes/scene1.in");
}

// How deep `point` lies in the scene's polyhedra (its walls and floor), the most of any
// plane's distance into a solid (0 when outside every one).
float depthInWalls(const scene::Scene& scene, const glm::vec3& point)
{
    float deepest = 0.0f;
    for (const scene::SceneObject& object : scene.objects) {
        const auto* polyhedron = std::get_if<scene::Polyhedron>(&object.shape.geometry);
        if (polyhedron == nullptr)
            continue;
        for (const glm::vec4& plane : polyhedron->planes) {
            const float height =
                (glm::dot(glm::vec3(plane), point) + plane.w) / glm::length(glm::vec3(plane));
            deepest = std::max(deepest, -height);
        }
    }
    return deepest;
}

// Where the view's centre ray of scene 1's camera meets the front sphere, worked out here.
glm::vec3 frontSphereUnderTheCentre(const scene::Camera& camera)
{
    const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
    const glm::vec3 offset = camera.eye - glm::vec3(1.0f, 0.0f, 1.0f);
    const float b = glm::dot(offset, forward);
    const float c = glm::dot(offset, offset) - 1.0f;
    return camera.eye + (-b - std::sqrt(b * b - c)) * forward;
}

TEST(CameraPivot, IsTheSurfaceUnderTheViewsCentreNotTheLookAtPointBehindTheWall)
{
    const scene::Scene scene = scene1();
    CameraController controller(scene.camera, scene);
    const glm::vec3 pivot = controller.pivot();
    EXPECT_NEAR(glm::length(pivot - frontSphereUnderTheCentre(scene.camera)), 0.0f, 1e-3f)
        << "pivot " << pivot.x << " " << pivot.y << " " << pivot.z;
    EXPECT_EQ(depthInWalls(scene, pivot), 0.0f);
}

TEST(CameraPivot, WhereTheCentreMeetsNothingIsOnTheCentreRayNearestTheScenesMiddle)
{
    // Looking over the floor at the sky: the ray meets no bound.
    scene::Scene scene =
        scene::parseSceneText("0 1 0\n0 1 -1\n0 1 0\n45\n0\n1 solid 1 1 1\n1 0 0 0 0 0 0 0\n"
                              "2\n0 0 sphere 0 3 -10 1\n0 0 polyhedron 1 0 1 0 0\n",
                              "sky.in", scene::FileLookup(".", scene::FileLookup::dataDirectory()));
    CameraController controller(scene.camera, scene);
    const glm::vec3 pivot = controller.pivot();
    const scene::SceneBounds bounds = scene::computeSceneBounds(scene);
    EXPECT_NEAR(pivot.x, 0.0f, 1e-4f);
    EXPECT_NEAR(pivot.y, 1.0f, 1e-4f);
    EXPECT_NEAR(pivot.z, bounds.center.z, 1e-3f);
    EXPECT_LT(pivot.z, 0.0f) << "ahead of the eye";
}

TEST(CameraOrbit, AQuarterTurnInScene1KeepsTheEyeInTheRoomAndTheViewOnThePivot)
{
    const scene::Scene scene = scene1();
    const scene::SceneBounds bounds = scene::computeSceneBounds(scene);
    for (float direction : {1.0f, -1.0f}) {
        CameraController controller(scene.camera, scene);
        const glm::vec3 pivot = controller.pivot();
        // Half the viewport's height: a quarter of a turn, in six drag events as a hand
        // gives them.
        for (int step = 0; step < 6; ++step)
            controller.orbit({direction * 40.0f, 0.0f}, 480.0f);
        const scene::Camera& camera = controller.camera();
        EXPECT_EQ(depthInWalls(scene, camera.eye), 0.0f)
            << "the eye went " << depthInWalls(scene, camera.eye) << " into a wall, at "
            << camera.eye.x << " " << camera.eye.y << " " << camera.eye.z << " (drag " << direction
            << ")";
        EXPECT_LE(glm::length(camera.eye - bounds.center), bounds.radius)
            << "the eye left the scene's bounds";
        EXPECT_NEAR(glm::length(camera.target - pivot), 0.0f, 1e-4f)
            << "the view stays centred on the pivot";
    }
}

TEST(CameraDolly, TenWheelStepsInScene1NeverPassThePivot)
{
    const scene::Scene scene = scene1();
    CameraController controller(scene.camera, scene);
    const glm::vec3 pivot = frontSphereUnderTheCentre(scene.camera);
    const glm::vec3 towards = glm::normalize(pivot - scene.camera.eye);
    float previous = glm::length(pivot - scene.camera.eye);
    for (int step = 1; step <= 10; ++step) {
        controller.dolly(1.0f);
        const glm::vec3 eye = controller.camera().eye;
        const float left = glm::dot(pivot - eye, towards);
        EXPECT_GT(left, 0.0f) << "step " << step << ": the eye passed the pivot by " << -left;
        EXPECT_LT(left, previous) << "step " << step << ": the eye did not come nearer";
        // Each step a fixed share of the distance left: the speed follows it.
        EXPECT_NEAR(left, previous * (1.0f - CameraController::kDollyStep), 1e-3f * previous)
            << "step " << step;
        previous = left;
    }
}

TEST(CameraDolly, OutwardStopsShortOfTheWallBehind)
{
    const scene::Scene scene = scene1();
    CameraController controller(scene.camera, scene);
    controller.orbit({120.0f, 0.0f}, 480.0f);
    for (int step = 0; step < 20; ++step)
        controller.dolly(-1.0f);
    EXPECT_EQ(depthInWalls(scene, controller.camera().eye), 0.0f);
}

}  // namespace
}  // namespace interaction_tests
