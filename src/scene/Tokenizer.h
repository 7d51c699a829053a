#pragma once
#include <string>
#include <vector>

namespace scene {

struct Token {
    std::string text;
    int line = 0;
};

// Splits a scene file into whitespace-separated tokens, remembering each one's line.
// '#' starts a comment to the end of the line; '{' and '}' are tokens of their own even
// when written against a word.
std::vector<Token> tokenize(const std::string& text);

}  // namespace scene
