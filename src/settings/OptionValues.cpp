#include "settings/OptionValues.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace settings {

std::string shortestFloatText(float value)
{
    char text[32];
    for (int digits = 6; digits <= 9; ++digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, static_cast<double>(value));
        if (std::strtof(text, nullptr) == value)
            break;
    }
    return text;
}

std::string shortestDoubleText(double value)
{
    char text[40];
    for (int digits = 1; digits <= 17; ++digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, value);
        if (std::strtod(text, nullptr) == value)
            break;
    }
    return text;
}

bool readFloat(const std::string& text, float& value)
{
    if (text.empty())
        return false;
    char* end = nullptr;
    value = std::strtof(text.c_str(), &end);
    return end == text.c_str() + text.size() && std::isfinite(value);
}

bool readDouble(const std::string& text, double& value)
{
    const char* last = text.data() + text.size();
    const auto [end, error] = std::from_chars(text.data(), last, value);
    return !text.empty() && error == std::errc() && end == last && std::isfinite(value);
}

bool readInteger(const std::string& text, long long& value)
{
    const char* last = text.data() + text.size();
    const auto [end, error] = std::from_chars(text.data(), last, value);
    return !text.empty() && error == std::errc() && end == last;
}

std::string choiceMacro(const std::string& prefix, const std::string& name)
{
    std::string text = prefix;
    for (char c : name)
        text += c == '-' ? '_' : static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return text;
}

long long parseWholeNumber(const std::string& text, const Range& range, const std::string& flag)
{
    long long value = 0;
    if (!readInteger(text, value) || !range.contains(static_cast<double>(value)))
        throw UsageError(flag + " must be " + range.describe() + ", not '" + text + "'");
    return value;
}

double parseDecimalNumber(const std::string& text, const Range& range, const std::string& flag)
{
    double value = 0.0;
    if (!readDouble(text, value) || !range.contains(value))
        throw UsageError(flag + " must be " + range.describe() + ", not '" + text + "'");
    return value;
}

}  // namespace settings
