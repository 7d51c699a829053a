#pragma once
// Named metals for the rough conductor finish: the complex index of refraction eta + i k of
// each, per colour channel. The numbers are the RGB values Mitsuba 3's rgb variants derive
// from the measured spectra they ship (Palik, "Handbook of Optical Constants of Solids",
// 1985, and the other sources of Mitsuba's data/ior), printed by
// `tools/mitsuba_references.py --metals`; a scene rendered by both renderers with the same
// metal then uses the same Fresnel.
#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace scene {

struct ComplexIor {
    glm::vec3 eta{1.0f};
    glm::vec3 k{0.0f};
};

struct NamedMetal {
    const char* keyword;  // the word in a scene file
    const char* symbol;   // the element, as Mitsuba's `material` names it
    ComplexIor ior;
};

const std::vector<NamedMetal>& namedMetals();
// The metal a scene file's word names, or nullptr.
const NamedMetal* findNamedMetal(const std::string& keyword);
// "gold, silver, ... or nickel": every metal's word, for messages.
std::string namedMetalKeywords();

// The reflectance of a conductor at normal incidence, ((eta - 1)^2 + k^2) / ((eta + 1)^2 + k^2).
glm::vec3 normalIncidenceReflectance(const ComplexIor& ior);

}  // namespace scene
