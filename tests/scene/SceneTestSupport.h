#pragma once
// Parsing scene text written in a test, and checking the error it must raise.
#include "scene/FileLookup.h"
#include "scene/SceneError.h"
#include "scene/SceneParser.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <string>

namespace scene_tests {

// The name parsed text goes by in messages.
inline const std::string kFileName = "written-in-test.in";

// Files the text names are looked up in tests/scenes/, then in textures/ and shaders/.
inline scene::Scene parse(const std::string& text)
{
    const scene::FileLookup lookup(testing_support::testScenesDirectory(),
                                   scene::FileLookup::dataDirectory());
    return scene::parseSceneText(text, kFileName, lookup);
}

// Succeeds when parsing `text` throws a SceneError at `line`, naming `token` (empty: the end
// of the file), whose expectation contains `expectedPart`, and whose message names all
// three as "file:line: read 'token', expected ...".
inline ::testing::AssertionResult failsAt(const std::string& text, int line,
                                          const std::string& token, const std::string& expectedPart)
{
    try {
        parse(text);
    } catch (const scene::SceneError& error) {
        const std::string message = error.what();
        const std::string where = kFileName + ":" + std::to_string(line) + ": ";
        const std::string read =
            token.empty() ? "reached the end of the file" : "read '" + token + "'";
        if (error.file() != kFileName || error.line() != line || error.token() != token ||
            error.expected().find(expectedPart) == std::string::npos ||
            message.rfind(where, 0) != 0 || message.find(read) == std::string::npos ||
            message.find("expected " + error.expected()) == std::string::npos)
            return ::testing::AssertionFailure()
                   << "expected an error at line " << line << " on "
                   << (token.empty() ? "the end of the file" : "'" + token + "'")
                   << " expecting \"..." << expectedPart << "...\", got: " << message;
        return ::testing::AssertionSuccess();
    } catch (const std::exception& error) {
        return ::testing::AssertionFailure()
               << "expected a scene::SceneError, got another exception: " << error.what();
    }
    return ::testing::AssertionFailure() << "expected a scene::SceneError, but the text parsed";
}

// A complete, valid scene up to its objects: camera, no lights, two pigments, two finishes
// (the second emits). The object count is on line 12; `objects` starts on line 13.
inline std::string sceneWithObjects(int count, const std::string& objects)
{
    return "0 0 5\n"                       // 1 eye
           "0 0 0\n"                       // 2 target
           "0 1 0\n"                       // 3 up
           "45\n"                          // 4 fovy
           "0\n"                           // 5 point lights
           "2\n"                           // 6 pigments
           "solid 1 0 0\n"                 // 7
           "solid 0 1 0\n"                 // 8
           "2\n"                           // 9 finishes
           "0 0 0  0 0 0 0\n"              // 10
           "5 5 5  0 0 0 0\n"              // 11 emits
           + std::to_string(count) + "\n"  // 12 objects
           + objects;                      // 13...
}

}  // namespace scene_tests
