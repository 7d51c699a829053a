#include "app/ErrorTargetRun.h"

#include <algorithm>
#include <cstdio>

namespace app {

namespace {

// Planning aims this much below the error that stops the render: the stop needs the estimate
// two standard deviations up under the target, and a plan met exactly would leave it a hair
// above, to be crept up on one frame at a time.
constexpr double kPlanningMargin = 0.97;

}  // namespace

ErrorTargetRun::ErrorTargetRun(const film::AdaptiveSampling& sampling, bool adaptive)
    : sampling_(sampling), adaptive_(adaptive)
{
}

void ErrorTargetRun::start(render::ProgressiveRenderer& renderer)
{
    // A resumed render's samples were not added by its first frame.
    noteSamplesAdded(renderer.accumulation());
    if (adaptive_)
        renderer.setTileSampleTargets(
            film::planAdaptiveSampling(film::Accumulation(renderer.width(), renderer.height()),
                                       sampling_)
                .targets);
}

// Estimates the error `accumulation` holds; true when every pixel holds the minimum.
bool ErrorTargetRun::judge(const film::Accumulation& accumulation)
{
    estimate_ = film::estimateRelativeError(accumulation);
    const film::SampleCountSpan span = film::samplesTakenSpan(accumulation);
    const bool minimumHeld =
        span.fewest >= std::min(sampling_.minimumSamples, sampling_.sampleLimit > 0
                                                              ? sampling_.sampleLimit
                                                              : sampling_.minimumSamples);
    reached_ = minimumHeld && estimate_ && estimate_->upperBound() <= sampling_.targetError;
    return minimumHeld;
}

void ErrorTargetRun::noteSamplesAdded(const film::Accumulation& accumulation)
{
    const std::size_t pixels =
        static_cast<std::size_t>(accumulation.width()) * accumulation.height();
    if (samplesTakenBefore_.size() != pixels)
        samplesTakenBefore_.assign(pixels, 0.0f);
    mostSamplesAdded_ = 0.0f;
    std::size_t pixel = 0;
    for (int y = 0; y < accumulation.height(); ++y)
        for (int x = 0; x < accumulation.width(); ++x, ++pixel) {
            const float taken = accumulation.samplesTaken(x, y);
            mostSamplesAdded_ = std::max(mostSamplesAdded_, taken - samplesTakenBefore_[pixel]);
            samplesTakenBefore_[pixel] = taken;
        }
}

void ErrorTargetRun::conclude(const render::ProgressiveRenderer& renderer)
{
    judge(renderer.accumulation());
}

void ErrorTargetRun::afterFrame(render::ProgressiveRenderer& renderer, double elapsedSeconds)
{
    const film::Accumulation accumulation = renderer.accumulation();
    const bool minimumHeld = judge(accumulation);
    noteSamplesAdded(accumulation);

    // Until every pixel holds the minimum the start's plan stands (every pixel to the
    // minimum): a share planned from a pixel's first few samples is planned from noise (a
    // plan made after two samples sent scene 5's pixels to 64-2000 samples, for an error
    // 0.77 of the target).
    if (estimate_ && !reached_ && minimumHeld) {
        film::AdaptiveSampling aim = sampling_;
        // What the estimate's uncertainty asks beyond the target, and the margin.
        aim.targetError = kPlanningMargin * sampling_.targetError * estimate_->relativeError /
                          std::max(estimate_->upperBound(), 1e-30);
        if (adaptive_) {
            film::AdaptivePlan plan = film::planAdaptiveSampling(accumulation, aim);
            // Every tile holds its share but the estimate is not there: the noise grew as it
            // was sampled (a bright path found late). Aim lower until a tile has work, or
            // every pixel holds the limit.
            for (int tries = 0; plan.activeTiles == 0 && tries < 40; ++tries) {
                aim.targetError *= 0.9;
                plan = film::planAdaptiveSampling(accumulation, aim);
            }
            limitReached_ = plan.activeTiles == 0;
            renderer.setTileSampleTargets(plan.targets);
        }
    } else if (!estimate_ && adaptive_) {
        renderer.setTileSampleTargets(film::planAdaptiveSampling(accumulation, sampling_).targets);
    }

    predictedSecondsLeft_.reset();
    if (estimate_ && minimumHeld) {
        history_.add(elapsedSeconds, static_cast<float>(estimate_->upperBound()));
        predictedSecondsLeft_ = history_.secondsLeftToReach(sampling_.targetError, elapsedSeconds,
                                                            estimate_->upperBound());
    }
}

std::string ErrorTargetRun::progressText() const
{
    char text[120];
    if (!estimate_) {
        std::snprintf(text, sizeof text, "target %.3g %%", 100.0 * sampling_.targetError);
        return text;
    }
    if (predictedSecondsLeft_)
        std::snprintf(text, sizeof text, "error %.3g %% (target %.3g %%), about %.0f s left",
                      100.0 * estimate_->relativeError, 100.0 * sampling_.targetError,
                      *predictedSecondsLeft_);
    else
        std::snprintf(text, sizeof text, "error %.3g %% (target %.3g %%)",
                      100.0 * estimate_->relativeError, 100.0 * sampling_.targetError);
    return text;
}

std::string ErrorTargetRun::summaryText(const std::string& stop) const
{
    char text[240];
    const char* sampling = adaptive_ ? "adaptive" : "uniform";
    if (!estimate_) {
        std::snprintf(text, sizeof text, "error not known yet (target %.3g %%, %s sampling: %s)",
                      100.0 * sampling_.targetError, sampling, stop.c_str());
        return text;
    }
    std::snprintf(text, sizeof text, "error %.3g %% +- %.2g %% (target %.3g %%, %s sampling: %s)",
                  100.0 * estimate_->relativeError, 100.0 * estimate_->uncertainty,
                  100.0 * sampling_.targetError, sampling, reached_ ? "reached" : stop.c_str());
    return text;
}

}  // namespace app
