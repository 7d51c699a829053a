// Which OpenGL renders (issue 31), through the program as a user runs it: a headless render
// goes through EGL, else OSMesa, and every summary line, --features, each file's metadata and
// `raytracer info` name the context, GL_RENDERER, GL_VERSION and the kernel; --gl and
// --gl-device force a choice, and when nothing works the error lists each way tried and why.
#include "app/ProgramInFolder.h"
#include "film/RenderFile.h"
#include "support/ChildProcess.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <regex>

namespace cli_tests {
namespace {

using namespace testing_support;

// libglvnd reads EGL's vendor libraries from this list: a file that does not exist leaves
// EGL without any. Mesa's OpenGL then offers at most 3.0, below the 3.3 core the renderer
// needs, which leaves OSMesa without a context too.
const std::pair<std::string, std::string> kNoEglVendor = {"__EGL_VENDOR_LIBRARY_FILENAMES",
                                                          "/nonexistent/egl_vendor.json"};
const std::pair<std::string, std::string> kMesaBelowGl33 = {"MESA_GL_VERSION_OVERRIDE", "3.0"};

class GlContexts : public ProgramInFolder {
protected:
    static std::string scene1() { return (sourceDirectory() / "scenes" / "scene1.in").string(); }

    ProcessResult
    runWith(const std::vector<std::string>& arguments,
            const std::vector<std::pair<std::string, std::string>>& environment = {}) const
    {
        ProcessOptions options;
        for (const auto& [name, value] : environment)
            options.environment[name] = value;
        return run(arguments, options);
    }

    // A tiny render that must succeed; its summary line.
    std::string
    render(std::vector<std::string> arguments,
           const std::vector<std::pair<std::string, std::string>>& environment = {}) const
    {
        arguments.insert(arguments.begin(), {scene1(), "32", "24", "--spp", "2"});
        const ProcessResult result = runWith(arguments, environment);
        EXPECT_TRUE(result.exited && result.exitStatus == 0) << describe(result);
        const auto lines = nonEmptyLines(result.standardOutput);
        return lines.empty() ? "" : lines.back();
    }
};

// The summary's "[KIND: RENDERER, OpenGL VERSION, KERNEL kernel]".
struct RenderingDevice {
    std::string kind, renderer, version, kernel;
};

RenderingDevice renderingDeviceOf(const std::string& summary)
{
    static const std::regex pattern(
        R"(\[([^:\]]+): (.+), OpenGL (.+), (fragment|compute) kernel\])");
    std::smatch match;
    if (!std::regex_search(summary, match, pattern))
        return {};
    return {match[1], match[2], match[3], match[4]};
}

TEST_F(GlContexts, AnEglRenderNamesItsContextRendererVersionAndKernelInTheSummaryAndTheFile)
{
    const RenderingDevice device = renderingDeviceOf(render({"--gl", "egl", "-o", "a.exr"}));
    ASSERT_EQ(device.kind.rfind("EGL ", 0), 0u) << "'" << device.kind << "'";
    EXPECT_FALSE(device.renderer.empty());
    EXPECT_FALSE(device.version.empty());

    const film::RenderMetadata metadata = film::readRenderFile(folder_ / "a.exr").metadata;
    EXPECT_EQ(metadata.glContext, device.kind);
    EXPECT_EQ(metadata.glRenderer, device.renderer);
    EXPECT_EQ(metadata.glVersion, device.version);
    EXPECT_EQ(metadata.kernel, device.kernel);

    const ProcessResult info = run({"info", "a.exr"});
    ASSERT_EQ(info.exitStatus, 0) << describe(info);
    EXPECT_NE(info.standardOutput.find("OpenGL renderer                   " + device.renderer),
              std::string::npos)
        << info.standardOutput;
    EXPECT_NE(info.standardOutput.find("OpenGL context                    " + device.kind),
              std::string::npos)
        << info.standardOutput;
}

TEST_F(GlContexts, AnOsMesaRenderSaysOsMesa)
{
    EXPECT_EQ(renderingDeviceOf(render({"--gl", "osmesa", "-o", "a.png"})).kind, "OSMesa");
}

TEST_F(GlContexts, WithoutEglAHeadlessRenderFallsBackToOsMesa)
{
    EXPECT_EQ(renderingDeviceOf(render({"-o", "a.png"}, {kNoEglVendor})).kind, "OSMesa");
}

TEST_F(GlContexts, WhenNoContextCanBeMadeTheErrorNamesEachWayTriedAndWhy)
{
    const ProcessResult result = runWith({scene1(), "32", "24", "--spp", "1", "-o", "a.png"},
                                         {kNoEglVendor, kMesaBelowGl33});
    ASSERT_TRUE(result.exited) << describe(result);
    EXPECT_EQ(result.exitStatus, 1) << describe(result);
    for (const char* tried :
         {"no OpenGL context could be made", "EGL devices: ", "EGL surfaceless: ", "OSMesa: "})
        EXPECT_NE(result.standardError.find(tried), std::string::npos)
            << "the error names '" << tried << "': " << result.standardError;
    EXPECT_TRUE(filesInFolder().empty()) << "nothing written";
}

TEST_F(GlContexts, AGpuNumberBeyondThoseEglListsIsAnErrorNotAFallback)
{
    const ProcessResult result =
        run({scene1(), "32", "24", "--spp", "1", "--gl-device", "1023", "-o", "a.png"});
    ASSERT_TRUE(result.exited) << describe(result);
    EXPECT_EQ(result.exitStatus, 1) << describe(result);
    EXPECT_NE(result.standardError.find("--gl-device 1023: EGL lists "), std::string::npos)
        << result.standardError;
    EXPECT_EQ(result.standardError.find("OSMesa"), std::string::npos)
        << "a GPU asked for by number never falls back: " << result.standardError;
    EXPECT_TRUE(filesInFolder().empty()) << "nothing written";
}

// On a farm node a render meant for the GPU must not run on the processor unseen.
TEST_F(GlContexts, GlGpuRendersOnAGpuOrNotAtAll)
{
    const ProcessResult result =
        run({scene1(), "32", "24", "--spp", "1", "--gl", "gpu", "-o", "a.png"});
    ASSERT_TRUE(result.exited) << describe(result);
    if (result.exitStatus == 0) {
        EXPECT_EQ(renderingDeviceOf(result.standardOutput).kind.rfind("EGL device ", 0), 0u)
            << result.standardOutput;
        return;
    }
    EXPECT_EQ(result.exitStatus, 1) << describe(result);
    EXPECT_NE(result.standardError.find("no OpenGL context could be made for --gl gpu"),
              std::string::npos)
        << result.standardError;
    EXPECT_EQ(result.standardError.find("OSMesa"), std::string::npos) << result.standardError;
    EXPECT_EQ(result.standardError.find("software device:"), std::string::npos)
        << "the software device is not tried: " << result.standardError;
    EXPECT_TRUE(filesInFolder().empty()) << "nothing written";
}

TEST_F(GlContexts, FeaturesNameTheOpenGLAndTheKernelAutoChoosesThere)
{
    const ProcessResult result = run({scene1(), "--features", "--gl", "egl"});
    ASSERT_EQ(result.exitStatus, 0) << describe(result);
    EXPECT_TRUE(std::regex_search(result.standardOutput,
                                  std::regex("\nOpenGL: +EGL [^\n]+, OpenGL [^\n]+\n")))
        << result.standardOutput;
    EXPECT_TRUE(std::regex_search(result.standardOutput,
                                  std::regex("\nkernel: +(fragment|compute) \\([^\n]+\\)\n")))
        << result.standardOutput;
}

TEST_F(GlContexts, TheComputeKernelSaysSoInTheSummaryAndTheFile)
{
    const RenderingDevice device =
        renderingDeviceOf(render({"--gl", "egl", "--kernel", "compute", "-o", "a.exr"}));
    EXPECT_EQ(device.kernel, "compute");
    EXPECT_EQ(film::readRenderFile(folder_ / "a.exr").metadata.kernel, "compute");
}

TEST_F(GlContexts, AMergeListsEachDeviceItsInputsCameFrom)
{
    render({"--gl", "egl", "--seed", "1", "-o", "a.exr"});
    render({"--gl", "osmesa", "--seed", "2", "-o", "b.exr"});
    const ProcessResult merged = run({"merge", "m.exr", "a.exr", "b.exr"});
    ASSERT_EQ(merged.exitStatus, 0) << describe(merged);
    const std::string context = film::readRenderFile(folder_ / "m.exr").metadata.glContext;
    EXPECT_EQ(context.rfind("EGL ", 0), 0u) << context;
    EXPECT_NE(context.find("; OSMesa"), std::string::npos) << context;
}

TEST_F(GlContexts, UnknownKindsAndContradictionsAreCommandLineErrors)
{
    const std::vector<std::vector<std::string>> wrong = {
        {"--gl", "vulkan"},
        {"--kernel", "vertex"},
        {"--gl-device", "-1"},
        {"--gl-device", "0", "--gl", "osmesa"},
        {"--gl", "window", "--headless"},
    };
    for (std::vector<std::string> arguments : wrong) {
        arguments.insert(arguments.begin(), {scene1(), "32", "24", "--spp", "1"});
        const ProcessResult result = run(arguments);
        EXPECT_EQ(result.exitStatus, 2)
            << arguments[5] << " " << arguments[6] << ": " << describe(result);
        EXPECT_EQ(nonEmptyLines(result.standardError).size(), 1u) << describe(result);
    }
    const ProcessResult endless = run({scene1(), "--gl", "egl"});
    EXPECT_EQ(endless.exitStatus, 2) << describe(endless);
    EXPECT_NE(endless.standardError.find("--gl egl renders need an end"), std::string::npos)
        << endless.standardError;
}

}  // namespace
}  // namespace cli_tests
