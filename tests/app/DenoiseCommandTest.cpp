// Feature buffers and denoising through the program as a user runs it (docs/DENOISING.md):
// --denoise writes the denoised image beside the raw one and says so in its metadata;
// without Open Image Denoise it stops before rendering with how to install it; a merge
// carries the feature layers and `raytracer denoise` denoises the merged file. The runs that
// denoise are skipped where the library is not installed.
#include "app/ProgramInFolder.h"
#include "film/Denoiser.h"
#include "film/RenderFile.h"
#include "io/ImageFile.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

namespace cli_tests {
namespace {

using namespace testing_support;

class Denoising : public ProgramInFolder {
protected:
    static std::string scene3() { return (sourceDirectory() / "scenes" / "scene3.in").string(); }

    void expectSuccess(const std::vector<std::string>& arguments) const
    {
        const ProcessResult result = run(arguments);
        ASSERT_TRUE(result.exited && result.exitStatus == 0) << describe(result);
    }

    // Why the library is not there, or empty where it is.
    static std::string missingOidn()
    {
        try {
            film::denoiserLibrary();
            return "";
        } catch (const film::DenoiserUnavailable& error) {
            return error.what();
        }
    }
};

TEST_F(Denoising, WithoutTheLibraryDenoiseStopsBeforeRenderingAndSaysHowToInstallIt)
{
    ProcessOptions options;
    options.environment["HOME"] = folder_.string();  // no virtual environment there
    options.environment["RAYTRACER_OIDN_LIBRARY"] = (folder_ / "none.so").string();
    options.environment["RAYTRACER_OIDN_VENV"] = std::nullopt;
    options.environment["LD_LIBRARY_PATH"] = std::nullopt;
    const ProcessResult result =
        run({scene3(), "32", "24", "--spp", "1", "--denoise", "-o", "r.exr"}, options);
    ASSERT_TRUE(result.exited) << describe(result);
    if (result.exitStatus == 0)
        GTEST_SKIP() << "a system-wide libOpenImageDenoise.so.2 was found";
    EXPECT_EQ(result.exitStatus, 1) << describe(result);
    EXPECT_NE(result.standardError.find("tools/install-dependencies.sh"), std::string::npos)
        << describe(result);
    EXPECT_TRUE(filesInFolder().empty()) << "nothing rendered, nothing written";
}

TEST_F(Denoising, DenoiseWritesTheDenoisedImageBesideTheRawOneAndSaysSo)
{
    if (const std::string missing = missingOidn(); !missing.empty())
        GTEST_SKIP() << missing;
    expectSuccess({scene3(), "32", "24", "--spp", "2", "--denoise", "-o", "r.exr", "--quiet"});
    EXPECT_EQ(filesInFolder(), (std::vector<std::string>{"r.denoised.exr", "r.exr"}));
    const film::RenderFile raw = film::readRenderFile(folder_ / "r.exr");
    EXPECT_TRUE(raw.accumulation.hasFeatures()) << "--denoise keeps the features it used";
    const auto attribute = io::readImageAttribute(folder_ / "r.denoised.exr", "raytracer:denoised");
    ASSERT_TRUE(attribute.has_value());
    EXPECT_NE(attribute->find("Open Image Denoise"), std::string::npos) << *attribute;
    EXPECT_THROW(film::readRenderFile(folder_ / "r.denoised.exr"), std::runtime_error)
        << "a denoised image is no accumulation: never merged or resumed";
}

TEST_F(Denoising, AMergeKeepsTheFeaturesAndIsDenoisedOnce)
{
    if (const std::string missing = missingOidn(); !missing.empty())
        GTEST_SKIP() << missing;
    for (const char* seed : {"1", "2"})
        expectSuccess({scene3(), "32", "24", "--spp", "2", "--seed", seed, "--feature-buffers",
                       "-o", std::string("s") + seed + ".exr", "--quiet"});
    expectSuccess({"merge", "m.exr", "s1.exr", "s2.exr"});
    EXPECT_TRUE(film::readRenderFile(folder_ / "m.exr").accumulation.hasFeatures());
    expectSuccess({"denoise", "m.exr", "m.png"});
    EXPECT_TRUE(io::readImageAttribute(folder_ / "m.png", "raytracer:denoised").has_value());

    const ProcessResult info = run({"info", "m.exr"});
    EXPECT_NE(info.standardOutput.find("feature buffers"), std::string::npos) << describe(info);
}

TEST_F(Denoising, ARenderWithoutFeaturesIsNotDenoised)
{
    expectSuccess({scene3(), "32", "24", "--spp", "1", "-o", "r.exr", "--quiet"});
    const ProcessResult result = run({"denoise", "r.exr", "d.exr"});
    EXPECT_EQ(result.exitStatus, 1) << describe(result);
    EXPECT_NE(result.standardError.find("--feature-buffers"), std::string::npos)
        << describe(result);
}

}  // namespace
}  // namespace cli_tests
