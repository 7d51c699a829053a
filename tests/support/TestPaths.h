#pragma once
// Where the tests find the project's files. The build passes the folders in, so a test runs
// from any working directory (ctest runs each from the build tree).
#include <filesystem>

namespace testing_support {

inline std::filesystem::path sourceDirectory()
{
    return RAYTRACER_SOURCE_DIR;
}

inline std::filesystem::path testsDirectory()
{
    return TESTS_SOURCE_DIR;
}

inline std::filesystem::path testScenesDirectory()
{
    return testsDirectory() / "scenes";
}

inline std::filesystem::path referencesDirectory()
{
    return testsDirectory() / "references";
}

#ifdef TESTS_FAILURE_DIR
inline std::filesystem::path failureDirectory()
{
    return TESTS_FAILURE_DIR;
}
#endif

}  // namespace testing_support
