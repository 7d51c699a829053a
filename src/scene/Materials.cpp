#include "scene/Materials.h"

#include "scene/KindCodes.h"
#include "scene/Scene.h"

#include <cctype>

namespace scene {

namespace {

// GGX alpha: the width of the microfacets' slope distribution. 0 would be a smooth surface
// (the classic mirror and glass are that); above 1 the energy compensation's table ends.
float readRoughness(TokenCursor& in, const std::string& which)
{
    const std::size_t token = in.mark();
    const float alpha = in.number(which + " roughness alpha");
    if (!(alpha > 0.0f && alpha <= 1.0f))
        in.failAtMark(token, "a roughness alpha greater than 0 and at most 1 (" + which +
                                 "; a smooth surface is the classic mirror or glass finish)");
    return alpha;
}

// rough_conductor ALPHA [METAL | ior ETA_R ETA_G ETA_B K_R K_G K_B]
void readRoughConductor(TokenCursor& in, const std::string& which, Finish& finish)
{
    finish.roughness = readRoughness(in, which);
    const Token* word = in.peek();
    if (word == nullptr)
        return;
    if (const NamedMetal* metal = findNamedMetal(word->text)) {
        in.skip();
        finish.conductorIor = metal->ior;
        return;
    }
    if (word->text == "ior") {
        in.skip();
        ComplexIor ior;
        const std::size_t etaToken = in.mark();
        ior.eta = in.colour(which + " index of refraction eta, r g b");
        if (!(ior.eta.r > 0.0f && ior.eta.g > 0.0f && ior.eta.b > 0.0f))
            in.failAtMark(etaToken, "a positive index of refraction eta (" + which + ")");
        ior.k = in.colour(which + " extinction coefficient k, r g b");
        finish.conductorIor = ior;
        return;
    }
    // Anything else that is a word (a number or a keyword starts what follows the finish)
    // was meant as a metal: say which there are.
    const unsigned char first = static_cast<unsigned char>(word->text.front());
    if (std::isalpha(first) && findFinishKeyword(word->text) == nullptr &&
        word->text != "environment")
        in.fail("a metal (" + namedMetalKeywords() +
                "), 'ior' and six numbers, or the next "
                "finish (" +
                which + ")");
}

// rough_dielectric ALPHA IOR
void readRoughDielectric(TokenCursor& in, const std::string& which, Finish& finish)
{
    finish.roughness = readRoughness(in, which);
    const std::size_t iorToken = in.mark();
    finish.ior = in.number(which + " index of refraction");
    // Index 1 is no interface at all: the classic dielectric of index 1 is that (it tints).
    if (!(finish.ior > 0.0f) || finish.ior == 1.0f)
        in.failAtMark(iorToken, "a positive index of refraction other than 1 (" + which + ")");
}

}  // namespace

const std::vector<MaterialDescription>& materialDescriptions()
{
    static const std::vector<MaterialDescription> descriptions = [] {
        std::vector<MaterialDescription> list;
#define SCENE_MATERIAL_DESCRIPTION(kind, name, keyword, reader, featureSwitch, glslPrefix,         \
                                   scattering, model)                                              \
    list.push_back({MaterialKind::kind, static_cast<int>(list.size()), #kind, name, keyword,       \
                    reader, featureSwitch, glslPrefix, scattering, model});
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

const MaterialDescription* findFinishKeyword(const std::string& keyword)
{
    for (const MaterialDescription& description : materialDescriptions())
        if (description.keyword != nullptr && keyword == description.keyword)
            return &description;
    return nullptr;
}

std::string finishKeywords()
{
    std::vector<const char*> keywords;
    for (const MaterialDescription& description : materialDescriptions())
        if (description.keyword != nullptr)
            keywords.push_back(description.keyword);
    std::string words;
    for (std::size_t i = 0; i < keywords.size(); ++i)
        words +=
            std::string(i == 0 ? "" : (i + 1 == keywords.size() ? " or " : ", ")) + keywords[i];
    return words;
}

std::string codeName(const MaterialDescription& description)
{
    return codeName("MATERIAL_", description.identifier);
}

}  // namespace scene
