// What the window asks of ProgressiveRenderer, through OSMesa: a scene edited in values is
// re-uploaded without a rebuild and renders as if loaded afresh; a broken edit leaves the
// renderer as it was; a preview is no part of the accumulation; exposure changes the picture,
// not the radiance; and the variance-based error estimate predicts the real error.
#include "film/ConvergenceEstimate.h"
#include "render/ProgressiveRenderer.h"
#include "scene/FileLookup.h"
#include "scene/SceneParser.h"
#include "support/RenderRun.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <unistd.h>

namespace render_tests {
namespace {

using namespace testing_support;
namespace fs = std::filesystem;

// A sphere of `colour` on a floor under a point light and the sky; `sphere` is its object.
std::string sceneText(const std::string& colour = "0.8 0.1 0.1",
                      const std::string& sphere = "0 0 sphere 0 0.5 0  0.5")
{
    return "0 1.2 4\n0 0.5 0\n0 1 0\n45\n1\n2 5 3  40 40 40\n"
           "2\nsolid " +
           colour +
           "\nsolid 0.5 0.5 0.5\n"
           "1\n0 0 0  0 0 0 0\n"
           "2\n" +
           sphere + "\n1 0 polyhedron 1\n    0 1 0 0\n";
}

void renderSamples(render::ProgressiveRenderer& renderer, int samples)
{
    while (renderer.samplesPerPixel() < samples)
        renderer.renderFrame({}, std::min(4, samples - renderer.samplesPerPixel()));
}

double largestDifference(const io::Image& a, const io::Image& b)
{
    double largest = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        largest = std::max(largest, static_cast<double>(std::abs(a.pixels[i] - b.pixels[i])));
    return largest;
}

TEST(InteractiveRenderer, AValuesEditReuploadsAndRendersAsTheEditedSceneLoadedAfresh)
{
    const settings::RenderSettings settings = settingsWithSeed(5);
    render::ProgressiveRenderer edited(sceneFromText(sceneText()), 48, 36, settings);
    renderSamples(edited, 4);
    const render::ReloadDecision decision =
        edited.setScene(sceneFromText(sceneText("0.1 0.2 0.9", "0 0 sphere 0.2 0.6 0  0.4")));
    EXPECT_FALSE(decision.rebuildShader) << "colour, centre and radius are uniforms";
    EXPECT_EQ(edited.samplesPerPixel(), 0) << "the accumulation restarts";
    renderSamples(edited, 4);

    render::ProgressiveRenderer fresh(
        sceneFromText(sceneText("0.1 0.2 0.9", "0 0 sphere 0.2 0.6 0  0.4")), 48, 36, settings);
    renderSamples(fresh, 4);
    EXPECT_EQ(largestDifference(edited.radiance(), fresh.radiance()), 0.0)
        << "same program, same uniforms, same seed: the same image";
}

TEST(InteractiveRenderer, AnEditThatChangesNothingOnScreenKeepsTheAccumulation)
{
    render::ProgressiveRenderer renderer(sceneFromText(sceneText()), 48, 36, settingsWithSeed(5));
    renderSamples(renderer, 4);
    const io::Image before = renderer.radiance();
    // The same scene with a comment and other spacing: the same code, the same uniforms.
    const render::ReloadDecision decision =
        renderer.setScene(sceneFromText("# saved again\n" + sceneText("0.80 0.1  0.1")));
    EXPECT_TRUE(decision.changesNothing);
    EXPECT_EQ(renderer.samplesPerPixel(), 4) << "nothing changed, so the samples are kept";
    EXPECT_EQ(largestDifference(renderer.radiance(), before), 0.0);
    renderSamples(renderer, 6);
    EXPECT_EQ(renderer.samplesPerPixel(), 6) << "and the accumulation goes on";
}

TEST(InteractiveRenderer, AnEditThatDoesNotCompileLeavesTheRendererAsItWas)
{
    const fs::path folder =
        fs::temp_directory_path() / ("raytracer-broken-sdf-" + std::to_string(::getpid()));
    fs::create_directories(folder);
    std::ofstream(folder / "blob.glsl") << "float blob(vec3 p, vec3 x)\n{\n"
                                           "    return length(p - x) - 0.5;\n}\n";
    const scene::FileLookup lookup(folder, scene::FileLookup::dataDirectory());
    const std::string text = sceneText("0.8 0.1 0.1", "0 0 blob 0 0.5 0");
    render::ProgressiveRenderer renderer(scene::parseSceneText(text, "blob.in", lookup), 48, 36,
                                         settingsWithSeed(2));
    renderSamples(renderer, 4);
    const io::Image before = renderer.radiance();

    std::ofstream(folder / "blob.glsl") << "float blob(vec3 p, vec3 x)\n{\n"
                                           "    return length(p - x) - wobble(p);\n}\n";
    EXPECT_THROW(
        renderer.setScene(scene::parseSceneText(text, "blob.in", lookup), {folder / "blob.glsl"}),
        std::runtime_error);
    fs::remove_all(folder);
    EXPECT_EQ(renderer.samplesPerPixel(), 4) << "the accumulation goes on";
    EXPECT_EQ(largestDifference(renderer.radiance(), before), 0.0) << "the image stays";
    renderSamples(renderer, 8);
    EXPECT_EQ(renderer.samplesPerPixel(), 8) << "the old shader still renders";
}

TEST(InteractiveRenderer, APreviewIsNoPartOfTheAccumulation)
{
    render::ProgressiveRenderer renderer(sceneFromText(sceneText()), 48, 36, settingsWithSeed(3));
    renderSamples(renderer, 4);
    renderer.renderPreview(3, 2);
    EXPECT_TRUE(renderer.showsPreview());
    EXPECT_EQ(renderer.samplesPerPixel(), 0);
    renderer.renderFrame({}, 2);
    EXPECT_FALSE(renderer.showsPreview());
    const io::Image statistics = renderer.sampleStatistics();
    for (int y = 0; y < statistics.height; ++y)
        for (int x = 0; x < statistics.width; ++x)
            ASSERT_EQ(statistics.at(x, y, 0), 2.0f)
                << "pixel (" << x << ", " << y << ") holds samples from before the frame";
}

TEST(InteractiveRenderer, ANewCameraRestartsTheAccumulation)
{
    const scene::Scene scene = sceneFromText(sceneText());
    render::ProgressiveRenderer renderer(scene, 48, 36, settingsWithSeed(3));
    renderSamples(renderer, 4);
    scene::Camera camera = scene.camera;
    camera.eye.x += 1.0f;
    renderer.setCamera(camera);
    EXPECT_EQ(renderer.samplesPerPixel(), 0);
    renderer.renderFrame({}, 1);
    EXPECT_EQ(renderer.sampleStatistics().at(10, 10, 0), 1.0f);
}

TEST(InteractiveRenderer, ExposureBrightensThePictureAndLeavesTheRadiance)
{
    render::ProgressiveRenderer renderer(sceneFromText(sceneText()), 48, 36, settingsWithSeed(4));
    renderSamples(renderer, 4);
    const io::Image radiance = renderer.radiance();
    const io::Image normal = renderer.toneMapped();
    renderer.setExposure(16.0f);
    const io::Image bright = renderer.toneMapped();
    EXPECT_EQ(largestDifference(renderer.radiance(), radiance), 0.0);
    double sumNormal = 0.0;
    double sumBright = 0.0;
    for (std::size_t i = 0; i < normal.pixels.size(); ++i) {
        sumNormal += normal.pixels[i];
        sumBright += bright.pixels[i];
    }
    EXPECT_GT(sumBright, 1.2 * sumNormal);
}

double meanRadiance(const io::Image& image)
{
    double sum = 0.0;
    for (float value : image.pixels)
        sum += value;
    return sum / static_cast<double>(image.pixels.size());
}

// The window's renderer: the environment read from a uniform, so that the panel can switch it.
settings::RenderSettings windowSettings(std::uint64_t seed)
{
    settings::RenderSettings settings = settingsWithSeed(seed);
    settings.switchableEnvironment = true;
    return settings;
}

// The panel's settings (hit tolerance, max bounces, the environment) go through setSettings:
// each restarts the accumulation and changes the picture, and setting it back gives the
// first picture bit for bit, so nothing else moved.
TEST(InteractiveRenderer, EachPanelSettingChangesThePictureAndSettingItBackRestoresIt)
{
    const settings::RenderSettings initial = windowSettings(6);
    render::ProgressiveRenderer renderer(sceneFromText(sceneText()), 48, 36, initial);
    renderSamples(renderer, 4);
    const io::Image base = renderer.radiance();

    auto renderWith = [&](const settings::RenderSettings& settings) {
        renderer.setSettings(settings);
        EXPECT_EQ(renderer.samplesPerPixel(), 0) << "a new setting restarts the accumulation";
        renderSamples(renderer, 4);
        return renderer.radiance();
    };
    settings::RenderSettings noEnvironment = initial;
    noEnvironment.environmentLight = false;
    EXPECT_LT(meanRadiance(renderWith(noEnvironment)), 0.9 * meanRadiance(base))
        << "without the sky only the point light lights the scene";
    EXPECT_EQ(largestDifference(renderWith(initial), base), 0.0) << "the environment back on";

    settings::RenderSettings oneBounce = initial;
    oneBounce.maxBounces = 1;
    EXPECT_LT(meanRadiance(renderWith(oneBounce)), meanRadiance(base))
        << "one bounce leaves out the light of the later ones";
    EXPECT_EQ(largestDifference(renderWith(initial), base), 0.0) << "16 bounces again";

    settings::RenderSettings looseHits = initial;
    looseHits.hitTolerance = 4.0f;
    EXPECT_GT(largestDifference(renderWith(looseHits), base), 0.0)
        << "a hit tolerance of 4 pixels moves the silhouettes";
    EXPECT_EQ(largestDifference(renderWith(initial), base), 0.0) << "0.25 pixels again";
}

TEST(InteractiveRenderer, PanelSettingsRenderAsTheSameSettingsGivenAtTheStart)
{
    settings::RenderSettings tuned = windowSettings(7);
    tuned.environmentLight = false;
    tuned.maxBounces = 2;
    tuned.hitTolerance = 1.0f;
    render::ProgressiveRenderer renderer(sceneFromText(sceneText()), 48, 36, windowSettings(7));
    renderSamples(renderer, 2);
    renderer.setSettings(tuned);
    renderSamples(renderer, 4);
    render::ProgressiveRenderer fresh(sceneFromText(sceneText()), 48, 36, tuned);
    renderSamples(fresh, 4);
    EXPECT_EQ(largestDifference(renderer.radiance(), fresh.radiance()), 0.0)
        << "the same program, uniforms and seed: the same image";
}

// Two renders of different seeds differ by sqrt(2) times the RMS error of each, so the
// estimate from one render's variance must predict the RMS distance between them.
// The relative RMS distance between two renders with different seeds, over sqrt(2): the
// error of one of them, measured.
double measuredRelativeError(const RenderedImage& first, const RenderedImage& second)
{
    double squares = 0.0;
    double sum = 0.0;
    for (std::size_t i = 0; i < first.radiance.pixels.size(); ++i) {
        const double difference = first.radiance.pixels[i] - second.radiance.pixels[i];
        squares += difference * difference;
        sum += 0.5 * (first.radiance.pixels[i] + second.radiance.pixels[i]);
    }
    const double count = static_cast<double>(first.radiance.pixels.size());
    return std::sqrt(squares / count / 2.0) / (sum / count);
}

TEST(ConvergenceEstimate, PredictsTheDistanceBetweenTwoIndependentRenders)
{
    const scene::Scene scene = sceneFromText(sceneText());
    settings::RenderSettings settings = settingsWithSeed(11);
    settings.sampler = settings::SamplerKind::Independent;
    const RenderedImage first = renderScene(scene, 64, 48, 32, settings);
    settings.seed = 12;
    const RenderedImage second = renderScene(scene, 64, 48, 32, settings);
    const std::optional<double> estimate =
        film::estimateRelativeError(first.accumulation)->relativeError;
    ASSERT_TRUE(estimate);
    const double measured = measuredRelativeError(first, second);
    EXPECT_NEAR(*estimate, measured, 0.15 * measured)
        << "estimated relative RMS error " << *estimate << ", measured " << measured;
}

// Stratified samples err less than their spread says: the estimate from the sample
// variance is then an upper bound.
TEST(ConvergenceEstimate, BoundsTheErrorOfAStratifiedRender)
{
    const scene::Scene scene = sceneFromText(sceneText());
    const RenderedImage first = renderScene(scene, 64, 48, 32, settingsWithSeed(11));
    const RenderedImage second = renderScene(scene, 64, 48, 32, settingsWithSeed(12));
    const std::optional<double> estimate =
        film::estimateRelativeError(first.accumulation)->relativeError;
    ASSERT_TRUE(estimate);
    const double measured = measuredRelativeError(first, second);
    EXPECT_GE(*estimate, measured)
        << "estimated relative RMS error " << *estimate << ", measured " << measured;
}

}  // namespace
}  // namespace render_tests
