#include "scene/UserSdfDeclarations.h"

#include "scene/SceneError.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

namespace scene {

bool isGlslIdentifier(const std::string& word)
{
    if (word.empty() || !(std::isalpha(static_cast<unsigned char>(word[0])) || word[0] == '_'))
        return false;
    const bool allWordCharacters = std::all_of(word.begin(), word.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    });
    return allWordCharacters && word.rfind("gl_", 0) != 0 && word.find("__") == std::string::npos;
}

namespace {

// `NX NY NZ D` after @hull: a plane the whole surface lies behind.
void readHullPlane(UserSdf& user, const std::string& text, int lineNumber)
{
    std::istringstream words(text);
    float values[4] = {};
    std::string word;
    int count = 0;
    bool valid = true;
    while (words >> word) {
        float value = 0.0f;
        const char* last = word.data() + word.size();
        const auto [end, error] = std::from_chars(word.data(), last, value);
        if (count == 4 || error != std::errc() || end != last || !std::isfinite(value)) {
            valid = false;
            break;
        }
        values[count++] = value;
    }
    const glm::vec3 normal(values[0], values[1], values[2]);
    const float length = glm::length(normal);
    if (!valid || count != 4 || !(length > 0.0f))
        throw SceneError(user.sourcePath.string(), lineNumber, word.empty() ? "@hull" : word,
                         "a plane's normal and offset after @hull, four numbers NX NY NZ D "
                         "with a normal other than 0 0 0");
    // Offsets along the unit normal: D was measured along N.
    const glm::vec3 unit = normal / length;
    user.hullPlanes.emplace_back(unit, -values[3] / length);
}

}  // namespace

void readUserSdfDeclarations(UserSdf& user)
{
    std::ifstream file(user.sourcePath);
    std::string line;
    int lineNumber = 0;
    while (std::getline(file, line)) {
        ++lineNumber;
        const std::size_t at = line.find('@');
        const std::size_t comment = line.find("//");
        if (comment == std::string::npos || at == std::string::npos || at < comment)
            continue;
        std::istringstream words(line.substr(at));
        std::string key;
        std::string valueText;
        words >> key >> valueText;
        if (key == "@intersect") {
            std::string extra;
            if (!isGlslIdentifier(valueText) || (words >> extra))
                throw SceneError(user.sourcePath.string(), lineNumber,
                                 valueText.empty() ? key : valueText,
                                 "the name of the GLSL function that intersects the shape "
                                 "after @intersect, alone");
            user.intersectFunction = valueText;
            continue;
        }
        if (key == "@hull") {
            readHullPlane(user, line.substr(at + key.size()), lineNumber);
            continue;
        }
        if (key != "@bound" && key != "@lipschitz")
            continue;
        float value = 0.0f;
        const char* last = valueText.data() + valueText.size();
        const auto [end, error] = std::from_chars(valueText.data(), last, value);
        const bool number = error == std::errc() && end == last && std::isfinite(value);
        if (key == "@bound") {
            if (!number || !(value > 0.0f))
                throw SceneError(user.sourcePath.string(), lineNumber, valueText,
                                 "a positive bounding radius after @bound");
            user.boundingRadius = value;
        } else {
            if (!number || !(value >= 1.0f))
                throw SceneError(user.sourcePath.string(), lineNumber, valueText,
                                 "a Lipschitz factor of at least 1 after @lipschitz");
            user.lipschitz = value;
        }
    }
}

}  // namespace scene
