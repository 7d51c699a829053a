#pragma once
// Which samples a render holds. A path's random numbers follow from (seed, pixel, sample
// index) alone (shaders/modules/sampler.glsl), so two renders hold independent samples when
// their seeds differ, or when their index ranges of one seed are disjoint; the same seed and
// index give the same path twice, and an average that counts it twice is no longer the
// estimate it claims to be. Merge and resume keep this list to tell.
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace film {

// Every pixel's samples of `seed` lie in [first, first + count): a pixel that an interrupted
// render left a sample short holds fewer, never others.
struct SampleRange {
    std::uint64_t seed = 0;
    std::int64_t first = 0;
    std::int64_t count = 0;

    std::int64_t end() const { return first + count; }
    bool operator==(const SampleRange& other) const
    {
        return seed == other.seed && first == other.first && count == other.count;
    }
};

// Sorted by seed, then first index; the ranges of one seed that overlap or touch joined.
std::vector<SampleRange> normalizedRanges(std::vector<SampleRange> ranges);

// A range of `a` and a range of `b` of one seed whose indices overlap, if there is one.
std::optional<std::pair<SampleRange, SampleRange>> firstOverlap(const std::vector<SampleRange>& a,
                                                                const std::vector<SampleRange>& b);

// The seeds of `ranges`, each once, ascending.
std::vector<std::uint64_t> seedsOf(const std::vector<SampleRange>& ranges);

// "1:0+64 2:0+64": seed, first index and count of each range, for a file's header.
std::string formatSampleRanges(const std::vector<SampleRange>& ranges);
// The inverse; throws std::invalid_argument when `text` is not in that form.
std::vector<SampleRange> parseSampleRanges(const std::string& text);

// "1-4, 7, 9": the seeds of `ranges`, runs of consecutive seeds shortened, for people.
std::string describeSeeds(const std::vector<SampleRange>& ranges);

// "seed 1, samples 0 to 63", for people.
std::string describeSampleRange(const SampleRange& range);

}  // namespace film
