#include "film/RenderFileChecks.h"

#include "film/Accumulation.h"
#include "film/RenderFile.h"
#include "io/Sha256.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <numeric>
#include <stdexcept>

namespace film {

const char* const kPixelDigestAttribute = "raytracer:pixelSha256";

namespace {

std::string number(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", value);
    return text;
}

bool isWholeCount(double value)
{
    return std::isfinite(value) && value >= 0.0 && value == std::floor(value);
}

// The most samples a pixel of the file may hold: what its sample ranges hold, summed.
std::int64_t largestCountOf(const RenderMetadata& metadata)
{
    std::int64_t total = 0;
    for (const SampleRange& range : metadata.sampleRanges)
        total = std::min(kLargestSampleCount, total + range.count);
    return total;
}

class PixelChecker {
public:
    PixelChecker(const io::ImageFileContents& file, const RenderMetadata& metadata,
                 const std::string& fileName)
        : file_(file),
          fileName_(fileName),
          largestCount_(largestCountOf(metadata)),
          kept_(file.channelIndex("samples")),
          discarded_(file.channelIndex("samplesDiscarded")),
          variance_(file.channelIndex("varianceOfMean"))
    {
        const char* means[3] = {"R", "G", "B"};
        const char* moments[3] = {"sumSquaredDeviations.R", "sumSquaredDeviations.G",
                                  "sumSquaredDeviations.B"};
        for (int c = 0; c < 3; ++c) {
            means_[c] = file.channelIndex(means[c]);
            moments_[c] = file.channelIndex(moments[c]);
        }
        const std::vector<std::string>& features = featureChannelNames();
        for (std::size_t c = 0; c < features.size(); ++c)
            features_[c] = file.channelIndex(features[c]);
    }

    void check(int x, int y) const
    {
        double taken = 0.0;
        for (int channel : {kept_, discarded_}) {
            if (channel < 0)
                continue;
            const double count = value(x, y, channel);
            if (!isWholeCount(count))
                refuse(x, y, channel, "is not a number of samples (a whole number from 0)");
            taken += count;
            if (taken > static_cast<double>(largestCount_))
                refuse(x, y, channel,
                       "makes the pixel hold " + number(taken) + " samples, more than the " +
                           std::to_string(largestCount_) +
                           (largestCount_ == kLargestSampleCount
                                ? " a pixel can hold"
                                : " the file's sample ranges (raytracer:sampleRanges) hold"));
        }
        // An accumulation: means and second moments, which only mean something with the count.
        if (kept_ < 0)
            return checkVariance(x, y);
        const double kept = value(x, y, kept_);
        for (int c = 0; c < 3; ++c) {
            if (means_[c] < 0)
                continue;
            const double mean = value(x, y, means_[c]);
            if (!std::isfinite(mean) || mean < 0.0 || mean > kLargestMeanRadiance)
                refuse(x, y, means_[c],
                       "is not a mean radiance (finite, from 0 to " + number(kLargestMeanRadiance) +
                           ")");
            if (kept == 0.0 && mean != 0.0)
                refuse(x, y, means_[c], "is the mean of no sample (samples is 0), which is 0");
            if (moments_[c] < 0)
                continue;
            const double moment = value(x, y, moments_[c]);
            const double largest = 2.0 * kept * (kept - 1.0) * mean * mean;
            if (!std::isfinite(moment) || moment < 0.0)
                refuse(x, y, moments_[c], "is not a sum of squared deviations (finite, from 0)");
            if (moment > largest)
                refuse(x, y, moments_[c],
                       "is more than " + number(kept) + " samples of mean " + number(mean) +
                           " can deviate from it (at most " + number(largest / 2.0) +
                           ", all of it in one sample; twice that is allowed for rounding)");
        }
        checkVariance(x, y);
        checkFeatures(x, y);
    }

private:
    // Feature means (Accumulation.h): albedo from 0 to 1 (the environment's radiance is
    // clamped to 1), normals a mean of unit vectors, depth from 0, coverage a fraction.
    void checkFeatures(int x, int y) const
    {
        const double lowest[8] = {0, 0, 0, -1.001, -1.001, -1.001, 0, 0};
        const double highest[8] = {1.001, 1.001, 1.001, 1.001, 1.001, 1.001, 3.4e38, 1.0};
        for (int c = 0; c < 8; ++c) {
            if (features_[c] < 0)
                continue;
            const double feature = value(x, y, features_[c]);
            if (!std::isfinite(feature) || feature < lowest[c] || feature > highest[c])
                refuse(x, y, features_[c],
                       "is not a feature mean (finite, from " + number(lowest[c]) + " to " +
                           number(highest[c]) + ")");
        }
    }

    double value(int x, int y, int channel) const { return file_.image.at(x, y, channel); }

    void checkVariance(int x, int y) const
    {
        if (variance_ < 0)
            return;
        const double variance = value(x, y, variance_);
        if (!std::isfinite(variance) || variance < 0.0)
            refuse(x, y, variance_, "is not a variance (finite, from 0)");
    }

    [[noreturn]] void refuse(int x, int y, int channel, const std::string& why) const
    {
        throw std::runtime_error(
            fileName_ + ": pixel (" + std::to_string(x) + ", " + std::to_string(y) + "), channel " +
            file_.channelNames[static_cast<std::size_t>(channel)] + ": " +
            number(value(x, y, channel)) + " " + why + ": not a render this program wrote");
    }

    const io::ImageFileContents& file_;
    const std::string& fileName_;
    std::int64_t largestCount_;
    int kept_, discarded_, variance_;
    int means_[3], moments_[3];
    int features_[8];
};

}  // namespace

void checkPixelValues(const io::ImageFileContents& file, const RenderMetadata& metadata,
                      const std::string& fileName)
{
    if (file.format != "openexr")
        return;
    const PixelChecker checker(file, metadata, fileName);
    for (int y = 0; y < file.image.height; ++y)
        for (int x = 0; x < file.image.width; ++x)
            checker.check(x, y);
}

std::string pixelDigest(const io::Image& image, const std::vector<std::string>& channelNames)
{
    std::vector<int> order(channelNames.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return channelNames[a] < channelNames[b]; });
    io::Sha256 digest;
    std::vector<unsigned char> row;
    for (int y = 0; y < image.height; ++y) {
        row.clear();
        for (int x = 0; x < image.width; ++x)
            for (int channel : order) {
                std::uint32_t bits;
                const float value = image.at(x, y, channel);
                std::memcpy(&bits, &value, sizeof bits);
                for (int shift = 0; shift < 32; shift += 8)
                    row.push_back(static_cast<unsigned char>(bits >> shift));
            }
        digest.add(row.data(), row.size());
    }
    return digest.hexDigest();
}

void checkPixelDigest(const io::ImageFileContents& file, const std::string& fileName)
{
    const auto recorded =
        std::find_if(file.attributes.begin(), file.attributes.end(),
                     [](const io::ImageAttribute& a) { return a.name == kPixelDigestAttribute; });
    if (recorded == file.attributes.end())
        return;
    if (pixelDigest(file.image, file.channelNames) != recorded->value)
        throw std::runtime_error(fileName +
                                 ": its pixels are not the ones it was written with "
                                 "(their SHA-256 is not " +
                                 std::string(kPixelDigestAttribute) +
                                 "): the file was damaged after it was written");
}

}  // namespace film
