#pragma once
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace scene {

struct Token {
    std::string text;
    int line = 0;
};

// Splits a scene file into whitespace-separated tokens, remembering each one's line.
// '#' starts a comment to the end of the line; '{' and '}' are tokens of their own even
// when written against a word. Stops after `maxTokens` tokens, so that what a file can make
// the parser hold is bounded whatever its size.
std::vector<Token> tokenize(std::string_view text, std::size_t maxTokens);

}  // namespace scene
