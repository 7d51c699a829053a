#include "scene/SceneError.h"

#include <cstdio>

namespace scene {

namespace {

// A token as a message shows it: at most kShownTokenLength bytes of it, then an ellipsis, and
// every byte outside printable ASCII as \xNN, so that a binary file, a terminal control
// sequence or a megabyte-long word still gives one short, readable line.
constexpr std::size_t kShownTokenLength = 40;

std::string describe(const std::string& file, int line, const std::string& token,
                     const std::string& expected)
{
    const std::string where = file + ":" + std::to_string(line) + ": ";
    const std::string read =
        token.empty() ? "reached the end of the file" : "read '" + shownToken(token) + "'";
    return where + read + ", expected " + expected;
}

}  // namespace

std::string shownToken(const std::string& token)
{
    const bool cut = token.size() > kShownTokenLength;
    std::string shown;
    for (std::size_t i = 0; i < token.size() && i < kShownTokenLength; ++i) {
        const unsigned char c = static_cast<unsigned char>(token[i]);
        if (c >= 0x20 && c < 0x7f) {
            shown += static_cast<char>(c);
        } else {
            char escaped[5];
            std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
            shown += escaped;
        }
    }
    return cut ? shown + "..." : shown;
}

SceneError::SceneError(const std::string& file, int line, const std::string& token,
                       const std::string& expected)
    : std::runtime_error(describe(file, line, token, expected)),
      file_(file),
      line_(line),
      token_(token),
      expected_(expected)
{
}

}  // namespace scene
