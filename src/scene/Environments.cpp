#include "scene/Environments.h"

#include "scene/KindCodes.h"

namespace scene {

// --- the kinds' readers -------------------------------------------------------------------

void readNoArguments(TokenCursor&, const FileLookup&, Environment&) {}

void readEnvironmentColour(TokenCursor& in, const FileLookup&, Environment& environment)
{
    environment.color = in.colour("environment radiance");
}

// FILE, then `intensity S` and `rotate DEGREES` in either order, each at most once. The file
// is looked up as a texture is; whether it can be read is checked where images are read
// (app/SceneLoading, render/EnvironmentMap), which the parser knows nothing of.
void readEnvironmentMap(TokenCursor& in, const FileLookup& lookup, Environment& environment)
{
    const Token& file = in.next("an environment map file name (a latitude-longitude image: "
                                ".exr, .hdr, ...)");
    environment.mapName = file.text;
    const auto found = lookup.findTexture(file.text);
    if (!found)
        in.failAt(file, "an existing environment map file (looked in " +
                            joinFolders(lookup.textureFolders()) + ")");
    environment.mapPath = *found;
    bool intensityRead = false;
    bool rotationRead = false;
    while (const Token* word = in.peek()) {
        if (word->text == "intensity" && !intensityRead) {
            in.skip();
            environment.intensity = in.numberAtLeast("environment map intensity", 0.0f);
            intensityRead = true;
        } else if (word->text == "rotate" && !rotationRead) {
            in.skip();
            environment.rotationDegrees =
                in.number("environment map rotation about the up axis, in degrees");
            rotationRead = true;
        } else if (word->text == "intensity" || word->text == "rotate") {
            in.failAt(*word, "'" + word->text + "' only once on an environment line");
        } else {
            return;
        }
    }
}

// --- the table ---------------------------------------------------------------------------

const std::vector<EnvironmentDescription>& environmentDescriptions()
{
    static const std::vector<EnvironmentDescription> descriptions = [] {
        std::vector<EnvironmentDescription> list;
#define SCENE_ENVIRONMENT_DESCRIPTION(kind, keyword, alias, featureSwitch, reader)                 \
    list.push_back({EnvironmentKind::kind, static_cast<int>(list.size()), #kind, keyword, alias,   \
                    featureSwitch, reader});
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
        if (word == description.keyword ||
            (*description.alias != '\0' && word == description.alias))
            return &description;
    return nullptr;
}

std::string codeName(const EnvironmentDescription& description)
{
    return codeName("ENVIRONMENT_", description.identifier);
}

}  // namespace scene
