#include "scene/KindCodes.h"

#include <cctype>

namespace scene {

std::string codeName(const std::string& prefix, const std::string& identifier)
{
    std::string name = prefix;
    for (std::size_t i = 0; i < identifier.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(identifier[i]);
        if (i > 0 && std::isupper(c))
            name += '_';
        name += static_cast<char>(std::toupper(c));
    }
    return name;
}

}  // namespace scene
