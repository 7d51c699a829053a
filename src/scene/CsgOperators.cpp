#include "scene/CsgOperators.h"

#include "scene/KindCodes.h"

namespace scene {

const std::vector<CsgOperatorDescription>& csgOperatorDescriptions()
{
    static const std::vector<CsgOperatorDescription> descriptions = [] {
        std::vector<CsgOperatorDescription> list;
#define SCENE_CSG_DESCRIPTION(kind, keyword, smoothingWord, function, combination, smoothing)      \
    list.push_back({CsgOperator::kind, static_cast<int>(list.size()), #kind, keyword,              \
                    smoothingWord, function, CsgCombination::combination,                          \
                    CsgSmoothing::smoothing});
        SCENE_CSG_OPERATORS(SCENE_CSG_DESCRIPTION)
#undef SCENE_CSG_DESCRIPTION
        return list;
    }();
    return descriptions;
}

const CsgOperatorDescription& describe(CsgOperator op)
{
    return csgOperatorDescriptions()[static_cast<std::size_t>(op)];
}

const CsgOperatorDescription* findCsgOperator(const std::string& keyword,
                                              const std::string& smoothingWord)
{
    for (const CsgOperatorDescription& description : csgOperatorDescriptions())
        if (keyword == description.keyword && smoothingWord == description.smoothingWord)
            return &description;
    return nullptr;
}

bool isCsgKeyword(const std::string& word)
{
    for (const CsgOperatorDescription& description : csgOperatorDescriptions())
        if (word == description.keyword)
            return true;
    return false;
}

std::string codeName(const CsgOperatorDescription& description)
{
    return codeName("CSG_", description.identifier);
}

}  // namespace scene
