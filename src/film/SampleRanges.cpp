#include "film/SampleRanges.h"

#include <algorithm>
#include <charconv>
#include <sstream>
#include <stdexcept>

namespace film {

std::vector<SampleRange> normalizedRanges(std::vector<SampleRange> ranges)
{
    ranges.erase(std::remove_if(ranges.begin(), ranges.end(),
                                [](const SampleRange& range) { return range.count <= 0; }),
                 ranges.end());
    std::sort(ranges.begin(), ranges.end(), [](const SampleRange& a, const SampleRange& b) {
        return a.seed != b.seed ? a.seed < b.seed : a.first < b.first;
    });
    std::vector<SampleRange> joined;
    for (const SampleRange& range : ranges) {
        if (!joined.empty() && joined.back().seed == range.seed &&
            range.first <= joined.back().end()) {
            const std::int64_t end = std::max(joined.back().end(), range.end());
            joined.back().count = end - joined.back().first;
        } else {
            joined.push_back(range);
        }
    }
    return joined;
}

std::optional<std::pair<SampleRange, SampleRange>> firstOverlap(const std::vector<SampleRange>& a,
                                                                const std::vector<SampleRange>& b)
{
    for (const SampleRange& first : a)
        for (const SampleRange& second : b)
            if (first.seed == second.seed && first.first < second.end() &&
                second.first < first.end() && first.count > 0 && second.count > 0)
                return std::make_pair(first, second);
    return std::nullopt;
}

std::vector<std::uint64_t> seedsOf(const std::vector<SampleRange>& ranges)
{
    std::vector<std::uint64_t> seeds;
    for (const SampleRange& range : ranges)
        seeds.push_back(range.seed);
    std::sort(seeds.begin(), seeds.end());
    seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
    return seeds;
}

std::string formatSampleRanges(const std::vector<SampleRange>& ranges)
{
    std::string text;
    for (const SampleRange& range : ranges)
        text += (text.empty() ? "" : " ") + std::to_string(range.seed) + ":" +
                std::to_string(range.first) + "+" + std::to_string(range.count);
    return text;
}

namespace {

template <typename Number>
Number parseNumber(const std::string& text, const std::string& whole)
{
    Number value{};
    const char* last = text.data() + text.size();
    const auto [end, error] = std::from_chars(text.data(), last, value);
    if (text.empty() || error != std::errc() || end != last)
        throw std::invalid_argument("'" + whole + "' is not a list of SEED:FIRST+COUNT");
    return value;
}

}  // namespace

std::vector<SampleRange> parseSampleRanges(const std::string& text)
{
    std::vector<SampleRange> ranges;
    std::istringstream words(text);
    for (std::string word; words >> word;) {
        const std::size_t colon = word.find(':');
        const std::size_t plus = word.find('+', colon == std::string::npos ? 0 : colon);
        if (colon == std::string::npos || plus == std::string::npos)
            throw std::invalid_argument("'" + text + "' is not a list of SEED:FIRST+COUNT");
        SampleRange range;
        range.seed = parseNumber<std::uint64_t>(word.substr(0, colon), text);
        range.first = parseNumber<std::int64_t>(word.substr(colon + 1, plus - colon - 1), text);
        range.count = parseNumber<std::int64_t>(word.substr(plus + 1), text);
        if (range.first < 0 || range.count < 0)
            throw std::invalid_argument("'" + text + "' has a negative index or count");
        ranges.push_back(range);
    }
    return ranges;
}

std::string describeSeeds(const std::vector<SampleRange>& ranges)
{
    const std::vector<std::uint64_t> seeds = seedsOf(ranges);
    std::string text;
    for (std::size_t i = 0; i < seeds.size();) {
        std::size_t last = i;
        while (last + 1 < seeds.size() && seeds[last + 1] == seeds[last] + 1)
            ++last;
        text += (text.empty() ? "" : ", ") + std::to_string(seeds[i]);
        if (last > i)
            text += (last == i + 1 ? ", " : "-") + std::to_string(seeds[last]);
        i = last + 1;
    }
    return text;
}

std::string describeSampleRange(const SampleRange& range)
{
    return "seed " + std::to_string(range.seed) + ", samples " + std::to_string(range.first) +
           " to " + std::to_string(range.end() - 1);
}

}  // namespace film
