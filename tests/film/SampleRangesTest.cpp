// The sample ranges a file holds (film/SampleRanges.h): what merge refuses as correlated.
#include "film/SampleRanges.h"

#include <gtest/gtest.h>

namespace scale_out_tests {
namespace {

using film::SampleRange;

TEST(SampleRanges, RangesOfOneSeedThatTouchOrOverlapAreJoinedAndOthersSorted)
{
    const std::vector<SampleRange> ranges =
        film::normalizedRanges({{7, 0, 16}, {2, 0, 8}, {7, 16, 16}, {2, 20, 4}, {7, 30, 4}});
    const std::vector<SampleRange> expected = {{2, 0, 8}, {2, 20, 4}, {7, 0, 34}};
    EXPECT_EQ(ranges, expected);
}

TEST(SampleRanges, OverlapIsFoundOnlyForOneSeedAndSharedIndices)
{
    EXPECT_TRUE(film::firstOverlap({{1, 0, 16}}, {{1, 15, 4}}).has_value());
    EXPECT_TRUE(film::firstOverlap({{3, 0, 8}, {1, 0, 16}}, {{1, 0, 16}}).has_value());
    EXPECT_FALSE(film::firstOverlap({{1, 0, 16}}, {{1, 16, 4}}).has_value())
        << "a range that starts where the other ends shares no index";
    EXPECT_FALSE(film::firstOverlap({{1, 0, 16}}, {{2, 0, 16}}).has_value())
        << "other seeds are independent";
}

TEST(SampleRanges, TextFormRoundTrips)
{
    const std::vector<SampleRange> ranges = {{1, 0, 64}, {18446744073709551615ull, 64, 3}};
    EXPECT_EQ(film::formatSampleRanges(ranges), "1:0+64 18446744073709551615:64+3");
    EXPECT_EQ(film::parseSampleRanges(film::formatSampleRanges(ranges)), ranges);
}

TEST(SampleRanges, MalformedTextIsRefused)
{
    for (const char* text : {"1:0", "1+0:3", "x:0+1", "1:-1+3", "1:0+3x"})
        EXPECT_THROW(film::parseSampleRanges(text), std::invalid_argument) << text;
}

TEST(SampleRanges, SeedsAreListedWithRunsShortened)
{
    EXPECT_EQ(film::describeSeeds({{3, 0, 1},
                                   {1, 0, 1},
                                   {2, 0, 1},
                                   {4, 0, 1},
                                   {7, 0, 1},
                                   {9, 0, 1},
                                   {10, 0, 1},
                                   {1, 5, 1}}),
              "1-4, 7, 9, 10");
}

}  // namespace
}  // namespace scale_out_tests
