#include "scene/SceneError.h"

namespace scene {

namespace {

std::string describe(const std::string& file, int line, const std::string& token,
                     const std::string& expected)
{
    const std::string where = file + ":" + std::to_string(line) + ": ";
    const std::string read = token.empty() ? "reached the end of the file" : "read '" + token + "'";
    return where + read + ", expected " + expected;
}

}  // namespace

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
