#include "settings/OptionDescription.h"

#include <cmath>
#include <cstdio>

namespace settings {

namespace {

std::string numberText(double value)
{
    if (value == std::floor(value) && std::fabs(value) < 1e15)
        return std::to_string(static_cast<long long>(value));
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

}  // namespace

Range Range::below(double limit) const
{
    Range range = *this;
    range.high = limit;
    range.highIncluded = false;
    return range;
}

Range Range::atMost(double limit) const
{
    Range range = *this;
    range.high = limit;
    range.highIncluded = true;
    return range;
}

bool Range::contains(double value) const
{
    if (whole && value != std::floor(value))
        return false;
    const bool aboveLow = lowIncluded ? value >= low : value > low;
    const bool belowHigh = highIncluded ? value <= high : value < high;
    return aboveLow && belowHigh;
}

std::string Range::describe() const
{
    const bool bounded = std::isfinite(high);
    const std::string number = whole ? "a whole number" : "a number";
    if (!bounded && !std::isfinite(low))
        return number;
    if (whole && bounded && lowIncluded && highIncluded)
        return number + " from " + numberText(low) + " to " + numberText(high);
    if (!bounded && lowIncluded)
        return number + " of " + numberText(low) + " or more";
    if (!bounded && low == 0.0)
        return whole ? "a positive whole number" : "a positive number";
    std::string text = number + (lowIncluded ? " at least " : " above ") + numberText(low);
    if (bounded)
        text += (highIncluded ? " and at most " : " and below ") + numberText(high);
    return text;
}

Range positive()
{
    return above(0.0);
}

Range atLeast(double low)
{
    Range range;
    range.low = low;
    return range;
}

Range above(double low)
{
    Range range;
    range.low = low;
    range.lowIncluded = false;
    return range;
}

Range wholeFrom(long long low, long long high)
{
    Range range = atLeast(static_cast<double>(low)).atMost(static_cast<double>(high));
    range.whole = true;
    return range;
}

Range wholeAtLeast(long long low)
{
    Range range = atLeast(static_cast<double>(low));
    range.whole = true;
    return range;
}

OptionDescription& OptionDescription::check(Range accepted)
{
    range = accepted;
    return *this;
}

OptionDescription& OptionDescription::alias(std::string spelling)
{
    aliases.push_back(std::move(spelling));
    return *this;
}

OptionDescription& OptionDescription::readBy(std::function<std::any(const std::string&)> reader)
{
    this->reader = std::move(reader);
    return *this;
}

OptionDescription& OptionDescription::defaultShown(std::string text)
{
    defaultText = std::move(text);
    return *this;
}

OptionDescription& OptionDescription::noDefaultShown()
{
    showDefault = false;
    return *this;
}

OptionDescription& OptionDescription::metadata(std::string key, std::string label)
{
    metadataKey = std::move(key);
    metadataLabel = std::move(label);
    return *this;
}

OptionDescription& OptionDescription::uniform(std::string module, std::string guard)
{
    uniformModule = std::move(module);
    uniformGuard = std::move(guard);
    return *this;
}

OptionDescription option(std::string flag, std::string valueName, std::string help)
{
    OptionDescription description;
    description.flag = std::move(flag);
    description.valueName = std::move(valueName);
    description.help = std::move(help);
    return description;
}

OptionDescription switchOption(std::string flag, std::string help)
{
    OptionDescription description;
    description.flag = std::move(flag);
    description.help = std::move(help);
    description.showDefault = false;
    return description;
}

OptionDescription notAnOption(std::string setBy)
{
    OptionDescription description;
    description.setBy = std::move(setBy);
    return description;
}

}  // namespace settings
