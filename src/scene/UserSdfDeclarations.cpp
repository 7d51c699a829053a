#include "scene/UserSdfDeclarations.h"

#include "scene/SceneError.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

namespace scene {

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
