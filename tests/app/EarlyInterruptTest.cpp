// An interrupt at any moment of a run, from the very start, ends it as documented (docs/USAGE.md,
// "Rendering from the command line"): status 130, the summary line saying it was interrupted, and no file lost. The
// program's libraries take half a second or more to load before its first instruction runs;
// a signal then used to kill it unseen (app/Launcher.cpp).
#include "app/ProgramInFolder.h"
#include "io/ImageFile.h"
#include "support/ChildProcess.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <csignal>
#include <cstring>
#include <fstream>
#include <sstream>

namespace cli_tests {
namespace {

using namespace testing_support;
namespace fs = std::filesystem;

struct EarlyInterrupt {
    int signal;
    int milliseconds;  // after the program started (its exec); 0: pending as it starts
};

void PrintTo(const EarlyInterrupt& interrupt, std::ostream* out)
{
    *out << strsignal(interrupt.signal) << " at " << interrupt.milliseconds << " ms";
}

class InterruptFromTheStart : public ProgramInFolder,
                              public ::testing::WithParamInterface<EarlyInterrupt> {};

TEST_P(InterruptFromTheStart, EndsAsAnInterruptedRenderAndKeepsTheOlderFile)
{
    write("out.exr", "an earlier render");
    ProcessOptions options;
    options.signal = GetParam().signal;
    options.signalAfterSeconds = GetParam().milliseconds / 1000.0;
    // At 0 ms the signal is sent as the program starts: held pending by the test's own child
    // (which has it blocked) until the program's first instruction, the earliest moment a
    // signal can be sent to the program rather than to the test.
    options.startWithSignalBlocked = GetParam().milliseconds == 0;
    options.timeoutSeconds = 60.0;
    const ProcessResult result = run({(sourceDirectory() / "scenes" / "scene1.in").string(), "64",
                                      "48", "--spp", "100000", "--output", "out.exr"},
                                     options);

    ASSERT_TRUE(result.exited) << "the program must end by itself, not be killed by the "
                                  "signal: "
                               << describe(result);
    EXPECT_EQ(result.exitStatus, 130) << describe(result);
    const auto lines = nonEmptyLines(result.standardOutput);
    ASSERT_FALSE(lines.empty()) << describe(result);
    EXPECT_NE(lines.back().find("interrupted"), std::string::npos) << lines.back();
    EXPECT_TRUE(result.standardError.empty()) << describe(result);
    std::ifstream file(folder_ / "out.exr", std::ios::binary);
    std::ostringstream contents;
    contents << file.rdbuf();
    if (lines.back().find("nothing written") != std::string::npos)
        EXPECT_EQ(contents.str(), "an earlier render") << "the older file must be kept";
    else
        EXPECT_TRUE(io::readImageAttribute(folder_ / "out.exr", "raytracer:interrupted"))
            << "a render interrupted after its first sample writes it, marked";
    EXPECT_EQ(filesInFolder(), std::vector<std::string>{"out.exr"}) << "no temporary file left";
}

INSTANTIATE_TEST_SUITE_P(Signals, InterruptFromTheStart,
                         ::testing::Values(EarlyInterrupt{SIGINT, 0}, EarlyInterrupt{SIGINT, 50},
                                           EarlyInterrupt{SIGINT, 200}, EarlyInterrupt{SIGTERM, 0},
                                           EarlyInterrupt{SIGTERM, 50},
                                           EarlyInterrupt{SIGTERM, 200}),
                         [](const ::testing::TestParamInfo<EarlyInterrupt>& info) {
                             return std::string(info.param.signal == SIGINT ? "Sigint"
                                                                            : "Sigterm") +
                                    "At" + std::to_string(info.param.milliseconds) + "ms";
                         });

class Interrupted : public ProgramInFolder {};

TEST_F(Interrupted, InfoEndsWithTheStatusOfAnInterrupt)
{
    // Any command, not only a render: info's status says it was interrupted.
    const ProcessResult rendered = run({(sourceDirectory() / "scenes" / "scene1.in").string(), "8",
                                        "6", "--spp", "1", "--output", "a.exr"});
    ASSERT_TRUE(rendered.exited && rendered.exitStatus == 0) << describe(rendered);
    ProcessOptions options;
    options.signal = SIGTERM;
    options.signalAfterSeconds = 0.0;
    options.startWithSignalBlocked = true;
    const ProcessResult result = run({"info", "a.exr"}, options);
    ASSERT_TRUE(result.exited) << describe(result);
    EXPECT_EQ(result.exitStatus, 130) << describe(result);
    EXPECT_NE(result.standardError.find("raytracer: interrupted"), std::string::npos)
        << describe(result);
}

}  // namespace
}  // namespace cli_tests
