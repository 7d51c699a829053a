// The live progress line on a terminal: redrawn in place, it must never be wider than the
// terminal (a wrapped line leaves a trail of cut lines), and where the terminal does not say
// how wide it is, one short form is used.
#include "app/ProgramInFolder.h"
#include "support/ChildProcess.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

namespace cli_tests {
namespace {

using namespace testing_support;

// The states the line was drawn in: the text between carriage returns and line feeds, with
// the erase-to-end-of-line sequence removed.
std::vector<std::string> drawnLines(std::string text)
{
    for (std::size_t at; (at = text.find("\033[K")) != std::string::npos;)
        text.erase(at, 3);
    std::vector<std::string> lines;
    std::string line;
    for (char c : text) {
        if (c == '\r' || c == '\n') {
            if (!line.empty())
                lines.push_back(line);
            line.clear();
        } else {
            line += c;
        }
    }
    if (!line.empty())
        lines.push_back(line);
    return lines;
}

class ProgressLine : public ProgramInFolder {
protected:
    std::vector<std::string> progressShownOn(int columns)
    {
        ProcessOptions options;
        options.terminalColumns = columns;
        const ProcessResult result =
            run({(sourceDirectory() / "scenes" / "scene1.in").string(), "32", "24", "--spp", "40",
                 "--samples-per-frame", "1", "--output", "p.png"},
                options);
        EXPECT_TRUE(result.exited && result.exitStatus == 0) << result.describeEnd() << "\n"
                                                             << result.standardError;
        const auto lines = drawnLines(result.standardError);
        EXPECT_FALSE(lines.empty()) << "a progress line should be shown on a terminal";
        return lines;
    }
};

TEST_F(ProgressLine, FitsANarrowTerminal)
{
    for (const std::string& line : progressShownOn(30))
        EXPECT_LT(line.size(), 30u) << "drawn on a 30-column terminal: '" << line << "'";
}

TEST_F(ProgressLine, FitsAVeryNarrowTerminal)
{
    for (const std::string& line : progressShownOn(12))
        EXPECT_LT(line.size(), 12u) << "drawn on a 12-column terminal: '" << line << "'";
}

TEST_F(ProgressLine, ShowsEverythingOnAWideTerminal)
{
    const auto lines = progressShownOn(200);
    ASSERT_FALSE(lines.empty());
    EXPECT_NE(lines.back().find("elapsed"), std::string::npos) << lines.back();
    EXPECT_NE(lines.back().find("left"), std::string::npos) << lines.back();
}

TEST_F(ProgressLine, UsesAShortFormWhereTheWidthIsUnknown)
{
    for (const std::string& line : progressShownOn(0))
        EXPECT_LE(line.size(), 24u) << "drawn where the width is unknown: '" << line << "'";
}

}  // namespace
}  // namespace cli_tests
