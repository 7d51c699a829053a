#include "scene/Tokenizer.h"

#include <cctype>

namespace scene {

std::vector<Token> tokenize(std::string_view text, std::size_t maxTokens)
{
    std::vector<Token> tokens;
    int line = 1;
    std::size_t i = 0;
    while (i < text.size() && tokens.size() < maxTokens) {
        const char c = text[i];
        if (c == '\n') {
            ++line;
            ++i;
        } else if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
        } else if (c == '#') {
            while (i < text.size() && text[i] != '\n')
                ++i;
        } else if (c == '{' || c == '}') {
            tokens.push_back({std::string(1, c), line});
            ++i;
        } else {
            const std::size_t start = i;
            while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i])) &&
                   text[i] != '#' && text[i] != '{' && text[i] != '}')
                ++i;
            tokens.push_back({std::string(text.substr(start, i - start)), line});
        }
    }
    return tokens;
}

}  // namespace scene
