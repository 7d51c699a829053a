// A shader that does not compile, as a user meets it: the compiler's log, each message
// located in the file (module or user SDF) and line it is about, with that line quoted.
// Mesa reports some errors (a call to an undefined function) with source-string number 0
// wherever they are; the location must come out right all the same.
#include "app/ProgramInFolder.h"
#include "support/ChildProcess.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <random>

namespace cli_tests {
namespace {

using namespace testing_support;
namespace fs = std::filesystem;

// One sphere, no lights, no textures: the shader needs only shaders/.
const char* const kSphereScene = "0 0 5\n0 0 0\n0 1 0\n45\n0\n1 solid 1 1 1\n"
                                 "1 0 0 0 0 0 0 0\n1\n0 0 sphere 0 0 0 1\n";

// The same with a user SDF `broken` in the sphere's place.
const char* const kUserSdfScene = "0 0 5\n0 0 0\n0 1 0\n45\n0\n1 solid 1 1 1\n"
                                  "1 0 0 0 0 0 0 0\n1\n0 0 broken 0 0 0\n";

// Line 5 calls a function nobody defines.
const char* const kBrokenUserSdf = "// A user SDF with a mistake on line 5.\n"
                                   "// @bound 2.0\n"
                                   "float broken(vec3 p, vec3 x)\n"
                                   "{\n"
                                   "    return sdSphere(p - x, 1.0) + wobble(p);\n"
                                   "}\n";

class ShaderError : public ProgramInFolder {
protected:
    ProcessResult renderUserSdfScene() const
    {
        write("broken.glsl", kBrokenUserSdf);
        const fs::path scene = write("broken.in", kUserSdfScene);
        return run({scene.string(), "32", "24", "--spp", "1", "--output", "out.png"});
    }
};

std::string describe(const ProcessResult& result)
{
    return result.describeEnd() + "\n--- stderr:\n" + result.standardError;
}

bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

// The message "FILE:LINE: error: ..." followed by the quoted line "    | CODE".
void expectErrorAt(const ProcessResult& result, const std::string& file, long line,
                   const std::string& message, const std::string& code)
{
    const std::string location = file + ":" + std::to_string(line) + ": error: " + message;
    const std::string quoted = location + "\n    | " + code + "\n";
    EXPECT_TRUE(contains(result.standardError, quoted)) << "expected the message\n"
                                                        << quoted << "in " << describe(result);
    EXPECT_FALSE(contains(result.standardError, "<preamble"))
        << "no message belongs to the preamble here; " << describe(result);
}

TEST_F(ShaderError, InAUserSdfNamesItsFileAndLineAndQuotesTheLine)
{
    const ProcessResult result = renderUserSdfScene();
    ASSERT_TRUE(result.exited) << describe(result);
    EXPECT_NE(result.exitStatus, 0) << describe(result);
    expectErrorAt(result, "broken.glsl", 5, "no function with name 'wobble'",
                  "    return sdSphere(p - x, 1.0) + wobble(p);");
    EXPECT_FALSE(fs::exists(folder_ / "out.png")) << "nothing may be written";
}

TEST_F(ShaderError, InAModuleNamesTheModuleAndLineAndQuotesTheLine)
{
    // A copy of the project's shaders with a call to an undefined function appended to one
    // module, used through RAYTRACER_DATA_DIR.
    const fs::path data = folder_ / "data";
    fs::create_directories(data);
    fs::copy(sourceDirectory() / "shaders", data / "shaders", fs::copy_options::recursive);
    const fs::path module = data / "shaders" / "modules" / "environment.glsl";
    std::ifstream input(module, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(input)), std::istreambuf_iterator<char>());
    input.close();
    if (!text.empty() && text.back() != '\n')
        text += '\n';
    const long line = static_cast<long>(std::count(text.begin(), text.end(), '\n')) + 1;
    const std::string code =
        "vec3 brokenOnPurpose(vec3 direction) { return undefinedOnPurpose(direction); }";
    std::ofstream(module, std::ios::binary) << text << code << "\n";

    const fs::path scene = write("sphere.in", kSphereScene);
    ProcessOptions options;
    options.environment["RAYTRACER_DATA_DIR"] = data.string();
    const ProcessResult result =
        run({scene.string(), "32", "24", "--spp", "1", "--output", "out.png"}, options);
    ASSERT_TRUE(result.exited) << describe(result);
    EXPECT_NE(result.exitStatus, 0) << describe(result);
    expectErrorAt(result, "modules/environment.glsl", line,
                  "no function with name 'undefinedOnPurpose'", code);
}

TEST_F(ShaderError, LogHoldsNoWarningAboutTheRandomState)
{
    // rngState is set in main before any use; a compiler that cannot see this must not
    // bury the real error under warnings.
    const ProcessResult result = renderUserSdfScene();
    ASSERT_TRUE(result.exited) << describe(result);
    EXPECT_NE(result.exitStatus, 0) << describe(result);
    EXPECT_FALSE(contains(result.standardError, "used uninitialized")) << describe(result);
}

}  // namespace
}  // namespace cli_tests
