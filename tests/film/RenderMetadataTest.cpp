// What a file says of itself (film/RenderMetadata.h) and what makes two renders' samples
// estimates of different images.
#include "film/RenderMetadata.h"

#include <gtest/gtest.h>

#include <functional>

namespace scale_out_tests {
namespace {

film::RenderMetadata someRender()
{
    film::RenderMetadata metadata;
    metadata.width = 64;
    metadata.height = 48;
    metadata.sceneFile = "scenes/scene1.in";
    metadata.sceneSha256 = std::string(64, 'a');
    metadata.camera.eye = {1.0f, -8.4f, 4.44f};
    metadata.camera.target = {1.0f, 10.0f, -2.0f};
    metadata.camera.up = {0.0f, 0.0f, 1.0f};
    metadata.camera.verticalFieldOfViewDegrees = 35.0f;
    metadata.samplesPerPixel = 96;
    metadata.sampleRanges = {{11, 0, 32}, {12, 0, 64}};
    metadata.renderSeconds = 12.25;
    metadata.glContext = "EGL device 0 (GPU, /dev/dri/renderD128)";
    metadata.glRenderer = "NVIDIA H200/PCIe/SSE2";
    metadata.glVersion = "4.6.0 NVIDIA 550.90.07";
    metadata.kernel = "compute";
    metadata.program = "raytracer 1.0.0";
    metadata.gitCommit = "0123456789abcdef0123456789abcdef01234567";
    return metadata;
}

// Every attribute read back as it was written (the size is the image's, not an attribute).
void expectSameMetadata(const film::RenderMetadata& read, const film::RenderMetadata& written)
{
    EXPECT_EQ(read.sceneFile, written.sceneFile);
    EXPECT_EQ(read.sceneSha256, written.sceneSha256);
    EXPECT_EQ(film::formatCamera(read.camera), film::formatCamera(written.camera));
    EXPECT_EQ(read.samplesPerPixel, written.samplesPerPixel);
    EXPECT_EQ(read.sampleRanges, written.sampleRanges);
    EXPECT_DOUBLE_EQ(read.renderSeconds, written.renderSeconds);
    EXPECT_EQ(read.interrupted, written.interrupted);
    EXPECT_EQ(read.glContext, written.glContext);
    EXPECT_EQ(read.glRenderer, written.glRenderer);
    EXPECT_EQ(read.glVersion, written.glVersion);
    EXPECT_EQ(read.kernel, written.kernel);
    EXPECT_EQ(read.program, written.program);
    EXPECT_EQ(read.gitCommit, written.gitCommit);
    EXPECT_EQ(read.mergedFrom, written.mergedFrom);
    for (const settings::SettingRow* setting : film::imageSettings())
        EXPECT_EQ(setting->format(read.settings), setting->format(written.settings))
            << setting->description.metadataKey;
}

// One change of each image-changing setting away from the defaults. A setting added to the
// table without a line here fails ChangingEveryImageSettingIsADifference.
const std::vector<std::pair<std::string, std::function<void(settings::RenderSettings&)>>>&
settingChanges()
{
    static const std::vector<std::pair<std::string, std::function<void(settings::RenderSettings&)>>>
        changes = {
            {"--exposure", [](settings::RenderSettings& s) { s.exposure = 2.0f; }},
            {"--tone-curve",
             [](settings::RenderSettings& s) { s.toneCurve = settings::ToneCurveKind::Agx; }},
            {"--hit-tolerance", [](settings::RenderSettings& s) { s.hitTolerance = 0.5f; }},
            {"--max-steps", [](settings::RenderSettings& s) { s.maxMarchSteps = 64; }},
            {"--over-relaxation", [](settings::RenderSettings& s) { s.overRelaxation = 1.0f; }},
            {"--step-scale", [](settings::RenderSettings& s) { s.stepScale = 0.9f; }},
            {"--max-bounces", [](settings::RenderSettings& s) { s.maxBounces = 8; }},
            {"--rr-depth", [](settings::RenderSettings& s) { s.russianRouletteDepth = 2; }},
            {"--no-mis", [](settings::RenderSettings& s) { s.multipleImportanceSampling = false; }},
            {"--fresnel",
             [](settings::RenderSettings& s) {
                 s.dielectricFresnel = settings::FresnelModel::Exact;
             }},
            {"--no-energy-compensation",
             [](settings::RenderSettings& s) { s.energyCompensation = false; }},
            {"--masking",
             [](settings::RenderSettings& s) { s.masking = settings::MaskingModel::Separable; }},
            {"--sampler",
             [](settings::RenderSettings& s) { s.sampler = settings::SamplerKind::Independent; }},
            {"--exact-geometry", [](settings::RenderSettings& s) { s.exactGeometry = true; }},
            {"--no-specialize",
             [](settings::RenderSettings& s) { s.variant = settings::ShaderVariant::General; }},
            {"the window's panel", [](settings::RenderSettings& s) { s.environmentLight = false; }},
        };
    return changes;
}

TEST(RenderMetadata, EveryFieldSurvivesTheAttributes)
{
    film::RenderMetadata written = someRender();
    for (const auto& [option, change] : settingChanges())
        change(written.settings);
    written.interrupted = "stopped at 3 of 16 samples per pixel";
    written.mergedFrom = {"a b.exr", "c.exr"};
    const auto read = film::metadataFromAttributes(film::metadataAttributes(written), "x.exr");
    ASSERT_TRUE(read.has_value());
    expectSameMetadata(*read, written);
}

TEST(RenderMetadata, DefaultSettingsAndNoCommitSurviveTheAttributes)
{
    film::RenderMetadata written = someRender();
    written.gitCommit.clear();
    const auto read = film::metadataFromAttributes(film::metadataAttributes(written), "x.exr");
    ASSERT_TRUE(read.has_value());
    expectSameMetadata(*read, written);
}

TEST(RenderMetadata, AttributesCarryThePrefixAndTheSeedList)
{
    bool seeds = false;
    for (const io::ImageAttribute& attribute : film::metadataAttributes(someRender())) {
        EXPECT_EQ(attribute.name.rfind("raytracer:", 0), 0u) << attribute.name;
        if (attribute.name == "raytracer:seed") {
            EXPECT_EQ(attribute.value, "11 12");
            seeds = true;
        }
    }
    EXPECT_TRUE(seeds) << "raytracer:seed is written";
}

TEST(RenderMetadata, FileWithoutItIsNotAnErrorButAMissingOrMalformedAttributeIs)
{
    EXPECT_FALSE(film::metadataFromAttributes({{"compression", "zip"}}, "x.exr").has_value());
    std::vector<io::ImageAttribute> attributes = film::metadataAttributes(someRender());
    for (io::ImageAttribute& attribute : attributes)
        if (attribute.name == "raytracer:maxBounces")
            attribute.value = "many";
    try {
        film::metadataFromAttributes(attributes, "x.exr");
        FAIL() << "a malformed setting must be refused";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("raytracer:maxBounces"), std::string::npos)
            << error.what();
        EXPECT_NE(std::string(error.what()).find("x.exr"), std::string::npos) << error.what();
    }
}

// --crop: recorded where there is one, nothing where the whole frame was traced, and a crop
// that holds no pixel is refused as malformed.
TEST(RenderMetadata, ACropSurvivesTheAttributes)
{
    film::RenderMetadata written = someRender();
    EXPECT_FALSE(film::metadataFromAttributes(film::metadataAttributes(written), "x.exr")->crop);
    written.crop = film::PixelCrop{2, 3, 10, 7};
    const auto read = film::metadataFromAttributes(film::metadataAttributes(written), "x.exr");
    ASSERT_TRUE(read && read->crop);
    EXPECT_TRUE(*read->crop == *written.crop) << film::formatCrop(*read->crop);
    std::vector<io::ImageAttribute> attributes = film::metadataAttributes(written);
    for (io::ImageAttribute& attribute : attributes)
        if (attribute.name == "raytracer:crop")
            attribute.value = "10 3 2 7";
    EXPECT_THROW(film::metadataFromAttributes(attributes, "x.exr"), std::runtime_error);
}

TEST(RenderMetadata, ChangingEveryImageSettingIsADifference)
{
    ASSERT_EQ(settingChanges().size(), film::imageSettings().size())
        << "every image-changing setting needs a change here";
    for (const auto& [option, change] : settingChanges()) {
        film::RenderMetadata changed = someRender();
        change(changed.settings);
        const auto difference = film::imageDifference(someRender(), changed);
        ASSERT_TRUE(difference.has_value()) << option << " should make a difference";
        EXPECT_NE(difference->what.find(option), std::string::npos)
            << "the difference names " << option << ": " << difference->what;
    }
}

TEST(RenderMetadata, SizeSceneCameraAndBuildAreDifferencesButSeedsSamplesAndTimeAreNot)
{
    const film::RenderMetadata base = someRender();
    auto differs = [&](const std::function<void(film::RenderMetadata&)>& change) {
        film::RenderMetadata other = base;
        change(other);
        return film::imageDifference(base, other).has_value();
    };
    EXPECT_TRUE(differs([](film::RenderMetadata& m) { m.width = 32; }));
    EXPECT_TRUE(differs([](film::RenderMetadata& m) { m.sceneSha256[0] = 'b'; }));
    EXPECT_TRUE(differs([](film::RenderMetadata& m) { m.camera.eye.x += 0.001f; }));
    EXPECT_TRUE(differs([](film::RenderMetadata& m) { m.gitCommit = "fedcba"; }));
    EXPECT_FALSE(differs([](film::RenderMetadata& m) { m.sampleRanges = {{99, 0, 4}}; }));
    EXPECT_FALSE(differs([](film::RenderMetadata& m) { m.samplesPerPixel = 4; }));
    EXPECT_FALSE(differs([](film::RenderMetadata& m) { m.renderSeconds = 1.0; }));
    EXPECT_FALSE(differs([](film::RenderMetadata& m) { m.sceneFile = "elsewhere/s.in"; }))
        << "the scene's contents count, not where it was read";
    EXPECT_FALSE(differs([](film::RenderMetadata& m) { m.settings.samplesPerFrame = 7; }))
        << "how frames cut the samples changes no sample";
    EXPECT_FALSE(differs([](film::RenderMetadata& m) {
        m.glContext = "OSMesa";
        m.glRenderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
        m.kernel = "fragment";
    })) << "another device or kernel traces the same samples: shards on different GPUs merge";
}

TEST(RenderMetadata, AFileWrittenBeforeTheRendererWasRecordedReadsWithoutIt)
{
    std::vector<io::ImageAttribute> attributes;
    for (const io::ImageAttribute& attribute : film::metadataAttributes(someRender()))
        if (attribute.name.rfind("raytracer:gl", 0) != 0 && attribute.name != "raytracer:kernel")
            attributes.push_back(attribute);
    const auto read = film::metadataFromAttributes(attributes, "old.exr");
    ASSERT_TRUE(read.has_value());
    EXPECT_EQ(read->glRenderer, "");
    EXPECT_EQ(read->kernel, "");
}

TEST(RenderMetadata, RenderingDevicesOfCombinedRendersAreEachListedOnce)
{
    film::RenderMetadata combined = someRender();
    film::RenderMetadata other = someRender();
    film::addRenderingDevice(combined, other);
    EXPECT_EQ(combined.glRenderer, "NVIDIA H200/PCIe/SSE2") << "one device, named once";
    other.glContext = "OSMesa";
    other.glRenderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
    other.glVersion = "4.5 (Core Profile) Mesa 22.3.6";
    other.kernel = "fragment";
    film::addRenderingDevice(combined, other);
    film::addRenderingDevice(combined, other);
    EXPECT_EQ(combined.glContext, "EGL device 0 (GPU, /dev/dri/renderD128); OSMesa");
    EXPECT_EQ(combined.glRenderer, "NVIDIA H200/PCIe/SSE2; llvmpipe (LLVM 15.0.6, 256 bits)");
    EXPECT_EQ(combined.glVersion, "4.6.0 NVIDIA 550.90.07; 4.5 (Core Profile) Mesa 22.3.6");
    EXPECT_EQ(combined.kernel, "compute; fragment");
}

}  // namespace
}  // namespace scale_out_tests
