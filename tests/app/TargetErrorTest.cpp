// Rendering to an accuracy (issue 19), through the program as a user runs it: a render to a
// target error gets there against an independent reference; converged pixels stop receiving
// samples, but none before the minimum; a target no render reaches ends at the time or sample
// limit, and the summary says which.
#include "app/ProgramInFolder.h"
#include "film/RenderFile.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <regex>

namespace cli_tests {
namespace {

using namespace testing_support;

// A floor and a sphere under a sphere light, no environment: the sky above the horizon is
// black and noiseless, the floor's penumbrae noisy.
std::string sphereLightScene()
{
    return (sourceDirectory() / "tests" / "scenes" / "light_sphere.in").string();
}

struct StatedError {
    double estimate = 0.0;
    double uncertainty = 0.0;
};

// "error 4.87 % +- 0.061 % (target ...": the summary's estimate and its uncertainty.
StatedError statedError(const std::string& summary)
{
    std::smatch match;
    const std::regex pattern(R"(error ([0-9.e+-]+) % \+- ([0-9.e+-]+) %)");
    if (!std::regex_search(summary, match, pattern))
        return {-1.0, -1.0};
    return {std::stod(match[1]) / 100.0, std::stod(match[2]) / 100.0};
}

// sqrt(mean((x - ref)^2) - mean(Var[ref])) / mean(ref) over pixels and channels: the
// render's error against the reference, less what the reference's own noise adds (its
// variance of the mean, known where its samples are independent).
double errorAgainst(const film::Accumulation& image, const film::Accumulation& reference)
{
    double squares = 0.0, referenceNoise = 0.0, sum = 0.0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const double n = reference.samplesKept(x, y);
            for (int c = 0; c < 3; ++c) {
                const double difference =
                    image.estimate.at(x, y, c) - reference.estimate.at(x, y, c);
                squares += difference * difference;
                referenceNoise += reference.moments.at(x, y, c) / (n * (n - 1.0));
                sum += reference.estimate.at(x, y, c);
            }
        }
    const double values = 3.0 * image.width() * image.height();
    return std::sqrt(std::max(0.0, squares - referenceNoise) / values) / (sum / values);
}

class TargetError : public ProgramInFolder {
protected:
    // The summary line of a render of the sphere-light scene that ends with `status`: 0, or
    // 3 where it ends before its target (app/RenderCommand.h, kExitTargetNotReached).
    std::string render(std::vector<std::string> arguments, int status = 0) const
    {
        arguments.insert(arguments.begin(), sphereLightScene());
        const ProcessResult result = run(arguments);
        EXPECT_TRUE(result.exited && result.exitStatus == status) << describe(result);
        return result.standardOutput;
    }

    film::Accumulation accumulation(const std::string& name) const
    {
        return film::readRenderFile(folder_ / name).accumulation;
    }
};

TEST_F(TargetError, ARenderToATargetReachesItAgainstAnIndependentReference)
{
    const std::string summary =
        render({"48", "36", "60", "--target-error", "0.05", "--output", "target.exr"});
    EXPECT_NE(summary.find("target 5 %, adaptive sampling: reached"), std::string::npos) << summary;
    const StatedError stated = statedError(summary);
    ASSERT_GT(stated.estimate, 0.0) << summary;
    EXPECT_LE(stated.estimate + 2.0 * stated.uncertainty, 0.05);

    // Independent samples, whose variance tells their error exactly, and far more of them.
    render({"48", "36", "--spp", "4096", "--sampler", "independent", "--seed", "7", "--output",
            "reference.exr"});
    const double measured = errorAgainst(accumulation("target.exr"), accumulation("reference.exr"));
    // The error measured scatters about its expectation by a few per cent of itself (3 x 1728
    // values); the estimate is an upper one with Sobol points.
    EXPECT_LE(measured, stated.estimate + 2.0 * stated.uncertainty + 0.1 * stated.estimate)
        << "measured " << measured << ", stated " << stated.estimate << " +- "
        << stated.uncertainty;
    EXPECT_GT(measured, 0.3 * stated.estimate) << "an estimate far above the truth wastes time";
}

// Every sample past the target is time wasted: the render stops at the first frame that
// gets there, so the error it stops at is close under the target, not far below it. (Shares
// planned from each pixel's first two samples, before the minimum, and frames of 0.5 s
// however near the target, stopped classic scene 5 at 0.84 of the target, two standard
// deviations up, in 0.84 s; now at 0.97-1.00, in 0.39 s; 0.97-0.99 with three busy loops
// beside it. On an Intel Xeon machine of the same kind, 2026-12-03, runs stopped at
// 0.90-0.96, alone or beside other tests, and 5 of 8 runs of the program as it was then fell
// below the 0.93 asked then: the limit is 0.88, which still fails the old 0.84.)
TEST_F(TargetError, AnAdaptiveRenderStopsCloseUnderItsTargetNotFarBelowIt)
{
    const ProcessResult result =
        run({(sourceDirectory() / "scenes" / "scene5.in").string(), "48", "36", "60",
             "--target-error", "0.05", "--output", "target.exr"});
    ASSERT_TRUE(result.exited && result.exitStatus == 0) << describe(result);
    const std::string summary = result.standardOutput;
    const StatedError stated = statedError(summary);
    ASSERT_GT(stated.estimate, 0.0) << summary;
    EXPECT_GE(stated.estimate + 2.0 * stated.uncertainty, 0.88 * 0.05) << summary;
}

TEST_F(TargetError, WithIndependentSamplesTheEstimateIsTheMeasuredError)
{
    const std::string summary = render({"48", "36", "60", "--target-error", "0.08", "--sampler",
                                        "independent", "--output", "target.exr"});
    render({"48", "36", "--spp", "4096", "--sampler", "independent", "--seed", "7", "--output",
            "reference.exr"});
    const StatedError stated = statedError(summary);
    const double measured = errorAgainst(accumulation("target.exr"), accumulation("reference.exr"));
    EXPECT_NEAR(measured, stated.estimate, 2.0 * stated.uncertainty + 0.1 * stated.estimate)
        << summary;
}

TEST_F(TargetError, ConvergedPixelsStopReceivingSamplesButNoneBeforeTheMinimum)
{
    // tests/scenes/light_sphere.in seen from lower down, looking up: black sky in the top half.
    const std::filesystem::path scene = write("sky.in", R"(environment none
2.2 0.6 4
0 1.6 0
0 1 0
35
0
2
solid 0.8 0.8 0.8
solid 0 0 0
2
0  0  0   0 0 0 0
20 20 20  0 0 0 0
3
0 0 polyhedron 1
    0 1 0 0
0 0 sphere 0 0.5 0  0.5
1 1 sphere 1.0 1.5 0.2  0.25
)");
    const ProcessResult result = run({scene.string(), "48", "36", "60", "--target-error", "0.05",
                                      "--min-spp", "24", "--quiet", "--output", "target.exr"});
    ASSERT_TRUE(result.exited && result.exitStatus == 0) << describe(result);
    const film::Accumulation held = accumulation("target.exr");
    auto black = [&held](int x, int y) {
        return held.estimate.at(x, y, 0) == 0.0f && held.estimate.at(x, y, 1) == 0.0f &&
               held.estimate.at(x, y, 2) == 0.0f;
    };
    // A pixel plans as the noisier of itself and its 3x3 neighbourhood (AdaptiveSampling.h):
    // the sky beside the floor's edge samples on; the sky among sky stops at the minimum.
    auto amongBlack = [&held, &black](int x, int y) {
        for (int ny = std::max(0, y - 1); ny <= std::min(held.height() - 1, y + 1); ++ny)
            for (int nx = std::max(0, x - 1); nx <= std::min(held.width() - 1, x + 1); ++nx)
                if (!black(nx, ny))
                    return false;
        return true;
    };
    int quietPixels = 0;
    float most = 0.0f;
    for (int y = 0; y < held.height(); ++y)
        for (int x = 0; x < held.width(); ++x) {
            const float samples = held.samplesTaken(x, y);
            EXPECT_GE(samples, 24.0f) << "pixel " << x << ", " << y;
            most = std::max(most, samples);
            if (amongBlack(x, y)) {
                ++quietPixels;
                EXPECT_EQ(samples, 24.0f) << "the noiseless sky at " << x << ", " << y;
            }
        }
    EXPECT_GT(quietPixels, 48 * 10) << "the scene's sky should fill the top rows";
    EXPECT_GE(most, 8 * 24.0f) << "the noisy pixels should have taken far more";
}

TEST_F(TargetError, ATargetNoRenderReachesEndsAtTheTimeLimitAndSaysSo)
{
    const std::string summary =
        render({"48", "36", "1.5", "--target-error", "0.0001", "--output", "target.exr"}, 3);
    EXPECT_NE(summary.find("stopped at the time limit before it"), std::string::npos) << summary;
    EXPECT_TRUE(std::filesystem::exists(folder_ / "target.exr"));
}

TEST_F(TargetError, ASampleLimitEndsAnAdaptiveRenderAndSaysSo)
{
    const std::string summary = render(
        {"48", "36", "--spp", "40", "--target-error", "0.0001", "--output", "target.exr"}, 3);
    EXPECT_NE(summary.find("stopped at --spp 40 before it"), std::string::npos) << summary;
    const film::SampleCountSpan span = film::samplesTakenSpan(accumulation("target.exr"));
    EXPECT_EQ(span.most, 40);
    EXPECT_GE(span.fewest, 32) << "the minimum";
}

// Adaptive renders hold different counts per pixel: the file says each pixel's, and a merge
// adds them pixel by pixel.
TEST_F(TargetError, MergedAdaptiveRendersAddTheirPerPixelCounts)
{
    render({"48", "36", "60", "--target-error", "0.1", "--seed", "1", "--output", "a.exr"});
    render({"48", "36", "60", "--target-error", "0.1", "--seed", "2", "--output", "b.exr"});
    const ProcessResult merged = run({"merge", "all.exr", "a.exr", "b.exr"});
    ASSERT_TRUE(merged.exited && merged.exitStatus == 0) << describe(merged);
    const film::Accumulation a = accumulation("a.exr");
    const film::Accumulation b = accumulation("b.exr");
    const film::Accumulation all = accumulation("all.exr");
    const film::SampleCountSpan span = film::samplesTakenSpan(a);
    EXPECT_GT(span.most, 2 * span.fewest) << "the counts should differ from pixel to pixel";
    for (int y = 0; y < all.height(); ++y)
        for (int x = 0; x < all.width(); ++x)
            EXPECT_EQ(all.samplesTaken(x, y), a.samplesTaken(x, y) + b.samplesTaken(x, y))
                << "pixel " << x << ", " << y;
}

}  // namespace
}  // namespace cli_tests
