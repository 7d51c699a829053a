#include "scene/TokenCursor.h"

#include "scene/SceneError.h"

#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace scene {

namespace {

// Why a well-formed decimal number does not fit a float: too large, or too small and not
// zero. Read in long double, whose range is far wider (a longer number still comes back as
// HUGE_VALL or 0, and that is enough to tell the two apart).
std::string outOfFloatRange(const std::string& text)
{
    const long double value = std::strtold(text.c_str(), nullptr);
    if (std::fabs(value) > FLT_MAX)
        return "; this one overflows a 32-bit float, whose largest magnitude is 3.4e38";
    return "; this one underflows a 32-bit float, whose smallest non-zero magnitude is "
           "1.4e-45 (write 0 for zero)";
}

}  // namespace

TokenCursor::TokenCursor(std::vector<Token> tokens, std::string fileName)
    : tokens_(std::move(tokens)), fileName_(std::move(fileName))
{
}

const Token& TokenCursor::next(const std::string& expected)
{
    if (atEnd())
        fail(expected);
    return tokens_[position_++];
}

void TokenCursor::fail(const std::string& expected) const
{
    failAtMark(position_, expected);
}

void TokenCursor::failAt(const Token& token, const std::string& expected) const
{
    throw SceneError(fileName_, token.line, token.text, expected);
}

void TokenCursor::failAtMark(std::size_t mark, const std::string& expected) const
{
    if (mark >= tokens_.size()) {
        const int line = tokens_.empty() ? 1 : tokens_.back().line;
        throw SceneError(fileName_, line, "", expected);
    }
    failAt(tokens_[mark], expected);
}

float TokenCursor::number(const std::string& what)
{
    const std::string expected = "a number (" + what + ")";
    const Token& token = next(expected);
    const std::string& text = token.text;
    const char* first = text.data();
    const char* last = text.data() + text.size();
    if (first != last && *first == '+')
        ++first;
    float value = 0.0f;
    const auto [end, error] = std::from_chars(first, last, value);
    if (error == std::errc::result_out_of_range && end == last)
        failAt(token, expected + outOfFloatRange(text));
    if (error != std::errc() || end != last || !std::isfinite(value))
        failAt(token, expected);
    return value;
}

float TokenCursor::numberAtLeast(const std::string& what, float minimum)
{
    const std::size_t token = position_;
    const float value = number(what);
    if (value < minimum)
        failAtMark(token, "a number of at least " + formatNumber(minimum) + " (" + what + ")");
    return value;
}

float TokenCursor::positiveNumber(const std::string& what)
{
    const std::size_t token = position_;
    const float value = number(what);
    if (!(value > 0.0f))
        failAtMark(token, "a positive number (" + what + ")");
    return value;
}

glm::vec3 TokenCursor::vector3(const std::string& what)
{
    const float x = number(what + ", x");
    const float y = number(what + ", y");
    const float z = number(what + ", z");
    return {x, y, z};
}

glm::vec3 TokenCursor::colour(const std::string& what)
{
    const float r = numberAtLeast(what + ", red", 0.0f);
    const float g = numberAtLeast(what + ", green", 0.0f);
    const float b = numberAtLeast(what + ", blue", 0.0f);
    return {r, g, b};
}

int TokenCursor::count(const std::string& what)
{
    const std::string expected =
        "a count from 0 to " + std::to_string(kMaxCount) + " (" + what + ")";
    const Token& token = next(expected);
    long long value = 0;
    const char* last = token.text.data() + token.text.size();
    const auto [end, error] = std::from_chars(token.text.data(), last, value);
    if (end != last || (error != std::errc() && error != std::errc::result_out_of_range))
        failAt(token, "a whole number: " + expected);
    if (error != std::errc() || value < 0 || value > kMaxCount)
        failAt(token,
               expected +
                   (value < 0 ? "" : "; a scene holds at most " + std::to_string(kMaxCount)));
    return static_cast<int>(value);
}

int TokenCursor::index(const std::string& what, std::size_t size)
{
    const std::string expected = size == 0
                                     ? "no " + what + " index: the file defines none"
                                     : "a " + what + " index from 0 to " + std::to_string(size - 1);
    const Token* token = peek();
    if (token == nullptr)
        fail(expected);
    int value = 0;
    const char* last = token->text.data() + token->text.size();
    const auto [end, error] = std::from_chars(token->text.data(), last, value);
    if (error != std::errc() || end != last || value < 0 || static_cast<std::size_t>(value) >= size)
        fail(expected);
    ++position_;
    return value;
}

void TokenCursor::expectWord(const std::string& word)
{
    const Token& token = next("'" + word + "'");
    if (token.text != word)
        failAt(token, "'" + word + "'");
}

std::string TokenCursor::formatNumber(float value)
{
    std::ostringstream stream;
    stream << value;
    return stream.str();
}

}  // namespace scene
