#pragma once
// The image-regression list: every classic scene and one small scene per feature
// (tests/scenes/), each with a reference in tests/references/NAME.exr. The tests
// (regression/RegressionTest.cpp) and the reference tool (regression/MakeReference.cpp,
// run by tools/update-references.sh) both read this one list.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace testing_support {

struct RegressionCase {
    std::string name;
    std::string scene;    // relative to the project's source folder
    std::string feature;  // what the case guards, for messages
    int width = 64;
    int height = 48;
    // The test renders with another seed and far fewer samples than the reference; the
    // comparison's threshold accounts for both sample counts (tests/README.md).
    int testSamplesPerPixel = 64;
    int referenceSamplesPerPixel = 2048;
};

constexpr std::uint64_t kReferenceSeed = 1000;
constexpr std::uint64_t kTestSeed = 7;

const std::vector<RegressionCase>& regressionCases();
std::optional<RegressionCase> findRegressionCase(const std::string& name);

std::filesystem::path scenePath(const RegressionCase& regressionCase);
std::filesystem::path referencePath(const RegressionCase& regressionCase);

}  // namespace testing_support
