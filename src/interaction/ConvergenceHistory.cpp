#include "interaction/ConvergenceHistory.h"

#include <algorithm>
#include <cmath>

namespace interaction {

void ConvergenceHistory::clear()
{
    errors_.clear();
    seconds_.clear();
    spacing_ = kFirstSpacingSeconds;
}

void ConvergenceHistory::add(double seconds, float relativeError)
{
    const double onTime = 0.95;
    if (!seconds_.empty() && seconds - seconds_.back() < onTime * spacing_)
        return;
    if (errors_.size() == kCapacity) {
        std::vector<float> errors;
        std::vector<double> times;
        for (std::size_t i = 0; i < errors_.size(); i += 2) {
            errors.push_back(errors_[i]);
            times.push_back(seconds_[i]);
        }
        errors_ = std::move(errors);
        seconds_ = std::move(times);
        spacing_ *= 2.0;
        if (seconds - seconds_.back() < onTime * spacing_)
            return;
    }
    errors_.push_back(relativeError);
    seconds_.push_back(seconds);
}

std::optional<double> ConvergenceHistory::secondsLeftToReach(double target, double nowSeconds,
                                                             double errorNow) const
{
    if (!(errorNow > 0.0) || !(target > 0.0) || !(nowSeconds > 0.0))
        return std::nullopt;
    if (errorNow <= target)
        return 0.0;
    double slope = 0.5;
    double sumX = 0.0, sumY = 0.0, sumXX = 0.0, sumXY = 0.0;
    int points = 0;
    double first = 0.0;
    for (std::size_t i = 0; i < seconds_.size(); ++i) {
        if (seconds_[i] < 0.5 * nowSeconds || !(seconds_[i] > 0.0) || !(errors_[i] > 0.0f))
            continue;
        if (points == 0)
            first = seconds_[i];
        const double x = std::log(seconds_[i]);
        const double y = std::log(static_cast<double>(errors_[i]));
        sumX += x;
        sumY += y;
        sumXX += x * x;
        sumXY += x * y;
        ++points;
    }
    if (points >= 3 && seconds_.back() >= 1.4 * first) {
        const double denominator = points * sumXX - sumX * sumX;
        if (denominator > 0.0)
            // Bounded: a few noisy points must not promise the moon, nor despair.
            slope = std::clamp(-(points * sumXY - sumX * sumY) / denominator, 0.35, 1.5);
    }
    return nowSeconds * (std::pow(errorNow / target, 1.0 / slope) - 1.0);
}

}  // namespace interaction
