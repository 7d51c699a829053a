#pragma once
// The raytracer program run as a user runs it, in a fresh, empty working folder per test
// (removed afterwards), headless whatever the environment.
#include "support/ChildProcess.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace cli_tests {

// How a run ended and what it printed, for failure messages.
inline std::string describe(const testing_support::ProcessResult& result)
{
    return result.describeEnd() + "\n--- stdout:\n" + result.standardOutput + "--- stderr:\n" +
           result.standardError;
}

class ProgramInFolder : public ::testing::Test {
protected:
    void SetUp() override
    {
        const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
        // Parameterised names hold '/': one folder, not a tree.
        std::string name = std::string(test->test_suite_name()) + "-" + test->name();
        std::replace(name.begin(), name.end(), '/', '-');
        folder_ = std::filesystem::temp_directory_path() /
                  ("raytracer-cli-" + name + "-" + std::to_string(std::random_device{}()));
        std::filesystem::create_directories(folder_);
    }
    void TearDown() override { std::filesystem::remove_all(folder_); }

    testing_support::ProcessResult run(std::vector<std::string> arguments,
                                       testing_support::ProcessOptions options = {}) const
    {
        arguments.insert(arguments.begin(), RAYTRACER_EXECUTABLE);
        options.workingDirectory = folder_;
        options.environment["DISPLAY"] = std::nullopt;
        options.environment["WAYLAND_DISPLAY"] = std::nullopt;
        return testing_support::runProcess(arguments, options);
    }

    // Writes `text` to `name` (a path relative to the folder, made as needed).
    std::filesystem::path write(const std::filesystem::path& name, const std::string& text) const
    {
        std::filesystem::create_directories((folder_ / name).parent_path());
        std::ofstream(folder_ / name, std::ios::binary) << text;
        return folder_ / name;
    }

    std::vector<std::string> filesInFolder() const
    {
        std::vector<std::string> names;
        for (const auto& entry : std::filesystem::directory_iterator(folder_))
            names.push_back(entry.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }

    std::filesystem::path folder_;
};

}  // namespace cli_tests
