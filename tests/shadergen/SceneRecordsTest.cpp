// The records' layouts (shadergen/SceneRecords.h): the host packs each value where the
// generated accessor reads it, and no two values share a slot.
#include "shadergen/SceneRecords.h"
#include "shadergen/UniformBlock.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <utility>

namespace shadergen_tests {
namespace {

using namespace shadergen;

int componentIndex(char letter)
{
    return std::string("xyzw").find(letter) != std::string::npos
               ? static_cast<int>(std::string("xyzw").find(letter))
               : static_cast<int>(std::string("rgba").find(letter));
}

TEST(SceneRecords, NoTwoFieldsShareASlotAndEveryFieldLiesInsideItsRecord)
{
    for (const RecordGlsl& record : recordLayoutsForGlsl()) {
        std::set<std::pair<int, int>> taken;
        for (const RecordGlsl::Field& field : record.fields) {
            EXPECT_GE(field.part, 0) << field.accessor;
            EXPECT_LT(field.part, record.parts) << field.accessor;
            const std::size_t size = field.glslType == "vec3" ? 3 : 1;
            EXPECT_EQ(field.components.size(), size) << field.accessor;
            for (char letter : field.components) {
                const int component = componentIndex(letter);
                ASSERT_GE(component, 0) << field.accessor << ": " << letter;
                EXPECT_TRUE(taken.insert({field.part, component}).second)
                    << field.accessor << " shares ." << letter << " of vec4 " << field.part;
            }
        }
    }
}

TEST(SceneRecords, EachValueIsPackedWhereItsAccessorReadsIt)
{
    FinishRecord finish;
    finish.emission = {1.0f, 2.0f, 3.0f};
    finish.phongExponent = 4.0f;
    finish.material = 5;
    finish.ior = 6.0f;
    std::vector<glm::vec4> packed;
    packRecord(finishRecordLayout(), finish, packed);
    ASSERT_EQ(packed.size(), 2u);
    EXPECT_EQ(packed[0], glm::vec4(1.0f, 2.0f, 3.0f, 4.0f));  // finishEmission .rgb, exponent .w
    EXPECT_EQ(packed[1], glm::vec4(5.0f, 6.0f, 0.0f, 0.0f));  // finishMaterial .x, finishIor .y

    LightRecord light;
    light.position = {1.0f, 2.0f, 3.0f};
    light.radius = 4.0f;
    light.emission = {5.0f, 6.0f, 7.0f};
    light.selectionProbability = 0.25f;
    light.cumulativeProbability = 0.5f;
    light.object = 9;
    light.cullingBit = 1u << 31;
    std::vector<glm::vec4> lights;
    packRecord(lightRecordLayout(), light, lights);
    ASSERT_EQ(lights.size(), 3u);
    EXPECT_EQ(lights[2], glm::vec4(0.5f, 9.0f, 2147483648.0f, 0.0f));

    ObjectRecord object{1, 2, -1, 7};
    std::vector<glm::ivec4> objects;
    packRecord(objectRecordLayout(), object, objects);
    EXPECT_EQ(objects.at(0), glm::ivec4(1, 2, -1, 7));
}

TEST(SceneRecords, TheGeneratedAccessorsReadTheLayoutsSlots)
{
    const std::string block = uniformBlock({}, {});
    EXPECT_NE(
        block.find("vec3 finishEmission(int finish) { return FINISH_RECORD(finish, 0).rgb; }"),
        std::string::npos)
        << block;
    EXPECT_NE(
        block.find("int finishMaterial(int finish) { return int(FINISH_RECORD(finish, 1).x); }"),
        std::string::npos);
    EXPECT_NE(
        block.find("uint lightCullingBit(int light) { return uint(LIGHT_RECORD(light, 2).z); }"),
        std::string::npos);
    EXPECT_NE(
        block.find("int objectSphereLight(int object) { return OBJECT_RECORD(object, 0).z; }"),
        std::string::npos);
    EXPECT_NE(block.find("uniform vec4 uLights[3 * LIGHT_ARRAY_SIZE];"), std::string::npos);
}

TEST(UniformBlock, DeclaresOnlyTheUniformsOfTheModulesInTheShader)
{
    const std::vector<UniformDeclaration> scalars = {{"float", "uA", "gA", "a.glsl"},
                                                     {"int", "uB", "gB", "b.glsl"}};
    const std::string block = uniformBlock(scalars, {"a.glsl"});
    EXPECT_NE(block.find("uniform float uA;"), std::string::npos) << block;
    EXPECT_NE(block.find("    gA = uA;"), std::string::npos) << block;
    EXPECT_EQ(block.find("uB"), std::string::npos) << block;
}

}  // namespace
}  // namespace shadergen_tests
