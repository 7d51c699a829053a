#pragma once
// Reading a scene file's tokens one by one: numbers, counts, indices and words, each
// checked, with errors that name the file, the line, the token and what was expected
// (scene/SceneError.h). The parser and every primitive kind's reader (scene/Primitives.h)
// read through it.
#include "scene/Tokenizer.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace scene {

class TokenCursor {
public:
    // Most lights, pigments, finishes, objects or polyhedron planes a file may count.
    static constexpr int kMaxCount = 100000;

    TokenCursor(std::vector<Token> tokens, std::string fileName);

    bool atEnd() const { return position_ >= tokens_.size(); }
    const Token* peek() const { return atEnd() ? nullptr : &tokens_[position_]; }
    const Token& next(const std::string& expected);
    void skip() { ++position_; }

    // Where the cursor stands, to report an error at a token after reading past it.
    std::size_t mark() const { return position_; }

    // Errors at the token about to be read (or at the end of the file), at a given token,
    // and at the token that stood at `mark`.
    [[noreturn]] void fail(const std::string& expected) const;
    [[noreturn]] void failAt(const Token& token, const std::string& expected) const;
    [[noreturn]] void failAtMark(std::size_t mark, const std::string& expected) const;

    float number(const std::string& what);
    float numberAtLeast(const std::string& what, float minimum);
    float positiveNumber(const std::string& what);
    glm::vec3 vector3(const std::string& what);
    glm::vec3 colour(const std::string& what);
    // A count from 0 to kMaxCount: it bounds what the parser allocates, so a larger one is
    // refused at once rather than read until the file runs out.
    int count(const std::string& what);
    int index(const std::string& what, std::size_t size);
    void expectWord(const std::string& word);

    static std::string formatNumber(float value);

private:
    std::vector<Token> tokens_;
    std::size_t position_ = 0;
    std::string fileName_;
};

}  // namespace scene
