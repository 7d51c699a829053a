// A row of the option table bound to its field (settings/OptionTable.h): what a range
// accepts and says, how each type is read and written, and rows that ask of a field what its
// type cannot give, refused when the table is built.
#include "settings/OptionTable.h"
#include "settings/SettingsTable.h"

#include <gtest/gtest.h>

#include <optional>
#include <stdexcept>

namespace settings_tests {
namespace {

using namespace settings;

TEST(Range, SaysWhatItAccepts)
{
    EXPECT_EQ(wholeFrom(1, 1024).describe(), "a whole number from 1 to 1024");
    EXPECT_EQ(positive().describe(), "a positive number");
    EXPECT_EQ(positive().atMost(1).describe(), "a number above 0 and at most 1");
    EXPECT_EQ(atLeast(1).below(2).describe(), "a number at least 1 and below 2");
    EXPECT_EQ(atLeast(0).describe(), "a number of 0 or more");
    EXPECT_EQ(wholeAtLeast(0).describe(), "a whole number of 0 or more");
}

TEST(Range, ItsEndsAreIncludedOrNotAsSaid)
{
    EXPECT_TRUE(atLeast(1).below(2).contains(1.0));
    EXPECT_FALSE(atLeast(1).below(2).contains(2.0));
    EXPECT_FALSE(positive().contains(0.0));
    EXPECT_FALSE(wholeFrom(0, 4).contains(1.5));
}

struct Owner {
    float number = 0.25f;
    bool flag = true;
    SamplerKind sampler = SamplerKind::Sobol;
    std::optional<int> count;
};

TEST(BoundOption, ReadsAndWritesEachTypeAsOneWord)
{
    const auto number = bindOption<Owner>(
        "number", [](auto& o) -> auto& { return o.number; },
        option("--number", "F", "").check(positive()));
    Owner owner;
    number.apply(owner, "1.2");
    EXPECT_EQ(owner.number, 1.2f);
    EXPECT_EQ(number.format(owner), "1.2") << "the shortest text that reads back the same float";
    EXPECT_THROW(number.apply(owner, "0"), UsageError);

    const auto sampler = bindOption<Owner>(
        "sampler", [](auto& o) -> auto& { return o.sampler; }, option("--sampler", "KIND", ""));
    EXPECT_EQ(sampler.choiceNames, (std::vector<std::string>{"independent", "sobol"}));
    EXPECT_TRUE(sampler.read(owner, "independent"));
    EXPECT_EQ(owner.sampler, SamplerKind::Independent);
    EXPECT_FALSE(sampler.read(owner, "halton"));

    const auto count = bindOption<Owner>(
        "count", [](auto& o) -> auto& { return o.count; },
        option("--count", "N", "").check(wholeFrom(1, 9)));
    count.apply(owner, "3");
    EXPECT_EQ(owner.count, 3);
    EXPECT_FALSE(count.format) << "an optional has no word of its own";
}

TEST(BoundOption, ARowAskingWhatItsTypeCannotGiveIsRefused)
{
    EXPECT_THROW(
        bindOption<Owner>(
            "flag", [](auto& o) -> auto& { return o.flag; }, switchOption("--no-flag", "")),
        std::logic_error)
        << "a switch without a value to set";
    EXPECT_THROW(
        bindOption<Owner>(
            "flag", [](auto& o) -> auto& { return o.flag; }, switchOption("--no-flag", "").sets(0)),
        std::logic_error)
        << "a switch setting a value of another type";
    EXPECT_THROW(bindOption<Owner>(
                     "flag", [](auto& o) -> auto& { return o.flag; }, option("--flag", "B", "")),
                 std::logic_error)
        << "a value read into a bool";
    EXPECT_THROW(bindOption<Owner>(
                     "count", [](auto& o) -> auto& { return o.count; },
                     option("--count", "N", "").metadata("count", "count")),
                 std::logic_error)
        << "an optional recorded in a file";
}

TEST(SettingsTable, ASixtyFourBitSettingReachesTheShaderLowWordFirst)
{
    RenderSettings settings;
    settings.seed = (std::uint64_t{7} << 32) | 5u;
    const UniformValue value = settingRow("seed").uniform(settings);
    EXPECT_EQ(std::get<glm::uvec2>(value), glm::uvec2(5u, 7u));
    EXPECT_STREQ(settingRow("seed").glslType, "uvec2");
}

TEST(SettingsTable, ChoicesReachTheShaderAsDefinesOfTheirCodes)
{
    const std::string defines = choiceDefines();
    EXPECT_NE(defines.find("#define SAMPLER_SOBOL 1\n"), std::string::npos) << defines;
    EXPECT_NE(defines.find("#define SAMPLER_INDEPENDENT 0\n"), std::string::npos) << defines;
    EXPECT_NE(defines.find("#define FRESNEL_EXACT 1\n"), std::string::npos) << defines;
    EXPECT_EQ(defines.find("SPECIALIZED"), std::string::npos)
        << "the shader variant shapes the code; the shader never reads it";
}

}  // namespace
}  // namespace settings_tests
