// The command line as parseCommandLine reads it, without running the program: both spellings
// of an option's value, the nearest option named for a misspelt one, and values checked by
// the table's ranges.
#include "app/CommandLine.h"
#include "settings/SettingsTable.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace options_tests {
namespace {

app::CommandLine parse(std::vector<std::string> arguments)
{
    arguments.insert(arguments.begin(), "raytracer");
    std::vector<const char*> argv;
    for (const std::string& argument : arguments)
        argv.push_back(argument.c_str());
    return app::parseCommandLine(static_cast<int>(argv.size()), argv.data());
}

std::string refusal(const std::vector<std::string>& arguments)
{
    try {
        parse(arguments);
    } catch (const app::UsageError& error) {
        return error.what();
    }
    return "";
}

TEST(CommandLineParse, ValuesMayFollowAnEqualsSign)
{
    const app::CommandLine line = parse({"s.in", "--hit-tolerance=0.5", "--spp=16",
                                         "--sampler=independent", "--output=a.exr", "--seed=9"});
    EXPECT_EQ(line.settings.hitTolerance, 0.5f);
    EXPECT_EQ(line.samplesPerPixel, 16);
    EXPECT_EQ(line.settings.sampler, settings::SamplerKind::Independent);
    EXPECT_EQ(line.output, std::filesystem::path("a.exr"));
    EXPECT_EQ(line.settings.seed, 9u);
    EXPECT_TRUE(line.given("--seed"));
}

TEST(CommandLineParse, EverySettingWithAValueTakesItAfterAnEqualsSignAsAfterASpace)
{
    for (const settings::SettingRow& row : settings::settingRows()) {
        if (!row.takesValue())
            continue;
        const std::string value = row.choiceNames.empty() ? "1" : row.choiceNames.back();
        const app::CommandLine spaced = parse({"s.in", row.description.flag, value});
        const app::CommandLine joined = parse({"s.in", row.description.flag + "=" + value});
        EXPECT_EQ(row.format(joined.settings), row.format(spaced.settings)) << row.description.flag;
    }
}

TEST(CommandLineParse, ASwitchTakesNoValue)
{
    EXPECT_NE(refusal({"s.in", "--no-mis=yes"}).find("--no-mis takes no value"), std::string::npos)
        << refusal({"s.in", "--no-mis=yes"});
}

TEST(CommandLineParse, AMisspeltOptionIsAnsweredWithTheNearestOne)
{
    EXPECT_NE(refusal({"s.in", "--hit-tolerence", "0.5"}).find("did you mean --hit-tolerance?"),
              std::string::npos)
        << refusal({"s.in", "--hit-tolerence", "0.5"});
    EXPECT_NE(refusal({"s.in", "--max-bounce=4"}).find("did you mean --max-bounces?"),
              std::string::npos)
        << refusal({"s.in", "--max-bounce=4"});
    EXPECT_NE(refusal({"merge", "o.exr", "a.exr", "--pgn", "p.png"}).find("did you mean --png?"),
              std::string::npos);
}

TEST(CommandLineParse, AnOptionMoreThanTwoEditsFromEveryOtherIsOnlyRefused)
{
    const std::string message = refusal({"s.in", "--fast"});
    EXPECT_NE(message.find("unknown option '--fast'"), std::string::npos) << message;
    EXPECT_EQ(message.find("did you mean"), std::string::npos) << message;
}

TEST(CommandLineParse, NumbersOutsideTheirRangeAreRefusedNamingTheRange)
{
    EXPECT_NE(refusal({"s.in", "--over-relaxation", "2"})
                  .find("--over-relaxation must be a number at least 1 and below 2, not '2'"),
              std::string::npos)
        << refusal({"s.in", "--over-relaxation", "2"});
    EXPECT_NE(refusal({"s.in", "--max-bounces", "-1"})
                  .find("--max-bounces must be a whole number from 0 to 1024"),
              std::string::npos);
    EXPECT_NE(refusal({"s.in", "--fresnel", "fast"})
                  .find("--fresnel must be 'schlick' or 'exact', not 'fast'"),
              std::string::npos);
}

TEST(CommandLineParse, EachOptionOnceUnderAnySpelling)
{
    EXPECT_NE(refusal({"s.in", "-o", "a.png", "--output=b.png"}).find("--output is given twice"),
              std::string::npos);
}

TEST(CommandLineParse, ASeedAsLargeAsSixtyThreeBitsIsKeptExactly)
{
    EXPECT_EQ(parse({"s.in", "--seed", "9007199254740993"}).settings.seed, 9007199254740993ull);
}

}  // namespace
}  // namespace options_tests
