#include "scene/Pigments.h"

#include "scene/KindCodes.h"

namespace scene {

namespace {

void readSolidPigment(TokenCursor& in, const FileLookup&, const std::string& which,
                      Pigment& pigment)
{
    pigment.color = in.colour(which + " colour");
}

void readCheckerPigment(TokenCursor& in, const FileLookup&, const std::string& which,
                        Pigment& pigment)
{
    pigment.color = in.colour(which + " first colour");
    pigment.secondColor = in.colour(which + " second colour");
    pigment.size = in.positiveNumber(which + " checker size");
}

void readTexturePigment(TokenCursor& in, const FileLookup& lookup, const std::string& which,
                        Pigment& pigment)
{
    const Token& file = in.next("a texture file name for " + which);
    pigment.textureName = file.text;
    const auto found = lookup.findTexture(file.text);
    if (!found)
        in.failAt(file, "an existing texture file (looked in " +
                            joinFolders(lookup.textureFolders()) + ")");
    pigment.texturePath = *found;
    pigment.size = in.positiveNumber(which + " texture scale");
}

}  // namespace

const std::vector<PigmentDescription>& pigmentDescriptions()
{
    static const std::vector<PigmentDescription> descriptions = [] {
        std::vector<PigmentDescription> list;
#define SCENE_PIGMENT_DESCRIPTION(kind, keyword, featureSwitch, reader, glslFunction)              \
    list.push_back({PigmentKind::kind, static_cast<int>(list.size()), #kind, keyword,              \
                    featureSwitch, reader, glslFunction});
        SCENE_PIGMENTS(SCENE_PIGMENT_DESCRIPTION)
#undef SCENE_PIGMENT_DESCRIPTION
        return list;
    }();
    return descriptions;
}

const PigmentDescription& describe(PigmentKind kind)
{
    return pigmentDescriptions()[static_cast<std::size_t>(kind)];
}

const PigmentDescription* findPigmentKind(const std::string& keyword)
{
    for (const PigmentDescription& description : pigmentDescriptions())
        if (keyword == description.keyword)
            return &description;
    return nullptr;
}

std::string pigmentKeywords()
{
    const std::vector<PigmentDescription>& all = pigmentDescriptions();
    std::string words;
    for (std::size_t i = 0; i < all.size(); ++i)
        words += std::string(i == 0 ? "" : (i + 1 == all.size() ? " or " : ", ")) + all[i].keyword;
    return words;
}

std::string codeName(const PigmentDescription& description)
{
    return codeName("PIGMENT_", description.identifier);
}

}  // namespace scene
