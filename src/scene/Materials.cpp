#include "scene/Materials.h"

#include "scene/KindCodes.h"

namespace scene {

const std::vector<MaterialDescription>& materialDescriptions()
{
    static const std::vector<MaterialDescription> descriptions = [] {
        std::vector<MaterialDescription> list;
#define SCENE_MATERIAL_DESCRIPTION(kind, name, featureSwitch, glslPrefix, scattering)             \
    list.push_back({MaterialKind::kind, static_cast<int>(list.size()), #kind, name, featureSwitch,  \
                    glslPrefix, scattering});
        SCENE_MATERIALS(SCENE_MATERIAL_DESCRIPTION)
#undef SCENE_MATERIAL_DESCRIPTION
        return list;
    }();
    return descriptions;
}

const MaterialDescription& describe(MaterialKind kind)
{
    return materialDescriptions()[static_cast<std::size_t>(kind)];
}

std::string codeName(const MaterialDescription& description)
{
    return codeName("MATERIAL_", description.identifier);
}

}  // namespace scene
