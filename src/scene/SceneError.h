#pragma once
#include <stdexcept>
#include <string>

namespace scene {

// A scene file that cannot be rendered. what() is the one line the user sees:
//   scenes/x.in:12: read 'sphre', expected an object type (sphere, polyhedron, ...)
// The message shows at most 40 bytes of the token (then "...") and escapes bytes that are not
// printable ASCII as \xNN; token() is the token whole.
class SceneError : public std::runtime_error {
public:
    SceneError(const std::string& file, int line, const std::string& token,
               const std::string& expected);

    const std::string& file() const { return file_; }
    int line() const { return line_; }
    const std::string& token() const { return token_; }
    const std::string& expected() const { return expected_; }

private:
    std::string file_;
    int line_;
    std::string token_;
    std::string expected_;
};

// A token as messages show it: at most 40 bytes of it, then "...", and every byte outside
// printable ASCII as \xNN. For a word the user wrote that a message quotes elsewhere than as
// the token read (the shader file a user SDF name asks for, say).
std::string shownToken(const std::string& token);

}  // namespace scene
