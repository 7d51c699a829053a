#include "scene/Environments.h"

#include "scene/KindCodes.h"

namespace scene {

const std::vector<EnvironmentDescription>& environmentDescriptions()
{
    static const std::vector<EnvironmentDescription> descriptions = [] {
        std::vector<EnvironmentDescription> list;
#define SCENE_ENVIRONMENT_DESCRIPTION(kind, keyword, alias, hasColour)                            \
    list.push_back({EnvironmentKind::kind, static_cast<int>(list.size()), #kind, keyword, alias,   \
                    hasColour});
        SCENE_ENVIRONMENTS(SCENE_ENVIRONMENT_DESCRIPTION)
#undef SCENE_ENVIRONMENT_DESCRIPTION
        return list;
    }();
    return descriptions;
}

const EnvironmentDescription& describe(EnvironmentKind kind)
{
    return environmentDescriptions()[static_cast<std::size_t>(kind)];
}

const EnvironmentDescription* findEnvironmentKind(const std::string& word)
{
    for (const EnvironmentDescription& description : environmentDescriptions())
        if (word == description.keyword || (*description.alias != '\0' && word == description.alias))
            return &description;
    return nullptr;
}

std::string codeName(const EnvironmentDescription& description)
{
    return codeName("ENVIRONMENT_", description.identifier);
}

}  // namespace scene
