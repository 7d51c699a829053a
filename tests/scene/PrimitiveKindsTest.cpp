// The primitive kinds' descriptions (scene/Primitives.h), walked kind by kind: what the
// compiler cannot check about a new kind fails here.
#include "scene/PrimitiveKinds.h"
#include "scene/SceneParser.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>

namespace scene_tests {
namespace {

using namespace scene;

std::string readSource(const std::string& relativePath)
{
    std::ifstream file(testing_support::sourceDirectory() / relativePath);
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

// "sdBox" of "sdBox(p - $0.xyz, $1.xyz)".
std::string functionName(const PrimitiveKind& kind)
{
    const std::string distance = kind.distance;
    return distance.substr(0, distance.find('('));
}

TEST(PrimitiveKinds, EachHasItsOwnKeywordAndTheParserReservesIt)
{
    std::set<std::string> keywords;
    for (const PrimitiveKind& kind : primitiveKinds()) {
        EXPECT_TRUE(keywords.insert(kind.keyword).second) << kind.keyword << " twice";
        EXPECT_TRUE(isReservedShapeWord(kind.keyword)) << kind.keyword;
        EXPECT_EQ(findPrimitiveKind(kind.keyword), &kind) << kind.keyword;
    }
}

TEST(PrimitiveKinds, CodesAreTheirPlaceInTheTableAndUserSdfsComeAfter)
{
    for (std::size_t i = 0; i < primitiveKinds().size(); ++i)
        EXPECT_EQ(primitiveKinds()[i].code, static_cast<int>(i)) << primitiveKinds()[i].keyword;
    EXPECT_EQ(userSdfCode(), static_cast<int>(primitiveKinds().size()));
}

TEST(PrimitiveKinds, EachDistanceFunctionIsDefinedInSdfPrimitivesAndMarkedExactOrBound)
{
    const std::string glsl = readSource("shaders/modules/sdf_primitives.glsl");
    for (const PrimitiveKind& kind : primitiveKinds()) {
        const std::size_t definition = glsl.find("float " + functionName(kind) + "(vec3 p");
        ASSERT_NE(definition, std::string::npos)
            << kind.keyword << ": " << functionName(kind) << " is not in sdf_primitives.glsl";
        // The comment block just above the definition.
        const std::size_t previousCode = glsl.rfind("}\n", definition);
        const std::string comment =
            glsl.substr(previousCode == std::string::npos ? 0 : previousCode,
                        definition - (previousCode == std::string::npos ? 0 : previousCode));
        EXPECT_TRUE(comment.find("EXACT") != std::string::npos ||
                    comment.find("BOUND") != std::string::npos)
            << functionName(kind) << " says neither EXACT nor BOUND";
    }
}

TEST(PrimitiveKinds, EachDistanceReadsOnlyTheParameterSlotsItPacks)
{
    for (const PrimitiveKind& kind : primitiveKinds()) {
        int largestSlot = -1;
        distanceOverSlots(kind, [&](int k) {
            largestSlot = std::max(largestSlot, k);
            return std::string();
        });
        EXPECT_GE(largestSlot, 0) << kind.keyword << " reads no parameter";
        EXPECT_LT(largestSlot, kind.parameterCount) << kind.keyword;
    }
}

TEST(PrimitiveKinds, EachIsDocumentedInTheSceneFormat)
{
    const std::string format = readSource("docs/SCENE_FORMAT.md");
    for (const PrimitiveKind& kind : primitiveKinds())
        EXPECT_NE(format.find("| `" + std::string(kind.keyword) + "` |"), std::string::npos)
            << kind.keyword << " has no row in docs/SCENE_FORMAT.md's table of primitives";
}

}  // namespace
}  // namespace scene_tests
