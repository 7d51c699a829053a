#include "scene/Metals.h"

namespace scene {

const std::vector<NamedMetal>& namedMetals()
{
    static const std::vector<NamedMetal> metals = {
        {"gold", "Au", {{0.1430f, 0.3753f, 1.4420f}, {3.9830f, 2.3856f, 1.6034f}}},
        {"silver", "Ag", {{0.1553f, 0.1167f, 0.1384f}, {4.8284f, 3.1222f, 2.1469f}}},
        {"copper", "Cu", {{0.2010f, 0.9237f, 1.1022f}, {3.9133f, 2.4530f, 2.1421f}}},
        {"aluminium", "Al", {{1.6575f, 0.8804f, 0.5212f}, {9.2238f, 6.2695f, 4.8370f}}},
        {"chromium", "Cr", {{4.3697f, 2.9165f, 1.6549f}, {5.2065f, 4.2313f, 3.7547f}}},
        {"tungsten", "W", {{4.3708f, 3.3002f, 2.9984f}, {3.5006f, 2.6049f, 2.2732f}}},
        {"nickel", "Ni_palik", {{2.3673f, 1.6634f, 1.4671f}, {4.4988f, 3.0502f, 2.3454f}}},
    };
    return metals;
}

const NamedMetal* findNamedMetal(const std::string& keyword)
{
    for (const NamedMetal& metal : namedMetals())
        if (keyword == metal.keyword)
            return &metal;
    return nullptr;
}

std::string namedMetalKeywords()
{
    const std::vector<NamedMetal>& all = namedMetals();
    std::string words;
    for (std::size_t i = 0; i < all.size(); ++i)
        words += std::string(i == 0 ? "" : (i + 1 == all.size() ? " or " : ", ")) + all[i].keyword;
    return words;
}

glm::vec3 normalIncidenceReflectance(const ComplexIor& ior)
{
    const glm::vec3 minus = ior.eta - 1.0f;
    const glm::vec3 plus = ior.eta + 1.0f;
    const glm::vec3 k2 = ior.k * ior.k;
    return (minus * minus + k2) / (plus * plus + k2);
}

}  // namespace scene
