#include "app/ConvergenceHistory.h"

namespace app {

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

}  // namespace app
