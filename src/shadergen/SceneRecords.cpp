#include "shadergen/SceneRecords.h"

#include <stdexcept>
#include <type_traits>

namespace shadergen {

const RecordLayout<ObjectRecord>& objectRecordLayout()
{
    static const RecordLayout<ObjectRecord> layout = {
        "uObjects",
        "object",
        "OBJECT_ARRAY_SIZE",
        "OBJECT_RECORD",
        1,
        true,
        {
            {&ObjectRecord::pigment, 0, "x", "objectPigment", ""},
            {&ObjectRecord::finish, 0, "y", "objectFinish", ""},
            {&ObjectRecord::sphereLight, 0, "z", "objectSphereLight",
             "the sphere light it is, or -1"},
            {&ObjectRecord::shapeProgramStart, 0, "w", "objectShapeProgramStart",
             "the start of its shape program (general shader only)"},
        },
        nullptr,
        "uObjectRecords"};
    return layout;
}

const RecordLayout<PigmentRecord>& pigmentRecordLayout()
{
    static const RecordLayout<PigmentRecord> layout = {
        "uPigments",
        "pigment",
        "PIGMENT_ARRAY_SIZE",
        "PIGMENT_RECORD",
        3,
        false,
        {
            {&PigmentRecord::kind, 0, "x", "pigmentKind", ""},
            {&PigmentRecord::size, 0, "y", "pigmentSize",
             "a checker's cube edge, or a texture's tile size (world units per repeat)"},
            {&PigmentRecord::textureLayer, 0, "z", "pigmentTextureLayer", ""},
            {&PigmentRecord::firstColor, 1, "rgb", "pigmentFirstColor", ""},
            {&PigmentRecord::secondColor, 2, "rgb", "pigmentSecondColor", ""},
        }};
    return layout;
}

const RecordLayout<FinishRecord>& finishRecordLayout()
{
    static const RecordLayout<FinishRecord> layout = {
        "uFinishes",
        "finish",
        "FINISH_ARRAY_SIZE",
        "FINISH_RECORD",
        2,
        false,
        {
            {&FinishRecord::emission, 0, "rgb", "finishEmission", "emitted radiance"},
            {&FinishRecord::phongExponent, 0, "w", "finishPhongExponent", ""},
            {&FinishRecord::material, 1, "x", "finishMaterial", ""},
            {&FinishRecord::ior, 1, "y", "finishIor", ""},
            {&FinishRecord::roughness, 1, "z", "finishRoughness", "GGX roughness alpha"},
        }};
    return layout;
}

const RecordLayout<ConductorRecord>& conductorRecordLayout()
{
    static const RecordLayout<ConductorRecord> layout = {
        "uFinishConductors",
        "finish",
        "FINISH_ARRAY_SIZE",
        "CONDUCTOR_RECORD",
        2,
        false,
        {
            {&ConductorRecord::eta, 0, "rgb", "finishConductorEta", ""},
            {&ConductorRecord::hasComplexIor, 0, "w", "finishHasComplexIor",
             "eta + i k below; false: Schlick's Fresnel with the pigment as R0"},
            {&ConductorRecord::k, 1, "rgb", "finishConductorK", ""},
        },
        "HAS_ROUGH_CONDUCTOR"};
    return layout;
}

const RecordLayout<LightRecord>& lightRecordLayout()
{
    static const RecordLayout<LightRecord> layout = {
        "uLights",
        "light",
        "LIGHT_ARRAY_SIZE",
        "LIGHT_RECORD",
        3,
        false,
        {
            {&LightRecord::position, 0, "xyz", "lightPosition", "position or centre"},
            {&LightRecord::radius, 0, "w", "lightRadius", ""},
            {&LightRecord::emission, 1, "rgb", "lightEmission", "intensity or radiance"},
            {&LightRecord::selectionProbability, 1, "w", "lightSelectionProbability", ""},
            {&LightRecord::cumulativeProbability, 2, "x", "lightCumulativeProbability", ""},
            {&LightRecord::object, 2, "y", "lightObject", "the object that is the light, or -1"},
            {&LightRecord::cullingBit, 2, "z", "lightCullingBit",
             "that object's culling bit, or 0"},
            {&LightRecord::kind, 2, "w", "lightKind", "a LIGHT_* code (scene/Lights.h)"},
        }};
    return layout;
}

namespace {

int componentIndex(char letter)
{
    switch (letter) {
    case 'x':
    case 'r':
        return 0;
    case 'y':
    case 'g':
        return 1;
    case 'z':
    case 'b':
        return 2;
    case 'w':
    case 'a':
        return 3;
    }
    throw std::logic_error(std::string("a record component is x, y, z or w, not ") + letter);
}

// Writes one value of a field into its components, converted to the element's scalar (a
// float array holds integers as floats: exact below 2^24, and every code, index and culling
// bit a scene has is).
template <typename Element, typename Value>
void writeComponents(Element& element, const char* components, const Value& value)
{
    using Scalar = typename Element::value_type;
    if constexpr (std::is_same_v<Value, glm::vec3>) {
        for (int i = 0; i < 3; ++i)
            element[componentIndex(components[i])] = static_cast<Scalar>(value[i]);
    } else {
        element[componentIndex(components[0])] = static_cast<Scalar>(value);
    }
}

template <typename Record, typename Element>
void pack(const RecordLayout<Record>& layout, const Record& record, std::vector<Element>& out)
{
    const std::size_t first = out.size();
    out.resize(first + static_cast<std::size_t>(layout.parts), Element(0));
    for (const RecordField<Record>& field : layout.fields)
        std::visit(
            [&](auto member) {
                writeComponents(out[first + static_cast<std::size_t>(field.part)], field.components,
                                record.*member);
            },
            field.member);
}

template <typename Record>
const char* glslTypeOf(const RecordMember<Record>& member)
{
    switch (member.index()) {
    case 0:
        return "float";
    case 1:
        return "int";
    case 2:
        return "uint";
    case 3:
        return "vec3";
    default:
        return "bool";
    }
}

template <typename Record>
RecordGlsl glslOf(const RecordLayout<Record>& layout)
{
    RecordGlsl text;
    text.uniform = layout.uniform;
    text.indexName = layout.indexName;
    text.countDefine = layout.countDefine;
    text.macro = layout.macro;
    text.parts = layout.parts;
    text.element = layout.integer ? "ivec4" : "vec4";
    text.guard = layout.guard ? layout.guard : "";
    text.bufferSampler = layout.bufferSampler ? layout.bufferSampler : "";
    for (const RecordField<Record>& field : layout.fields)
        text.fields.push_back({glslTypeOf(field.member), field.accessor, field.part,
                               field.components, field.comment});
    return text;
}

}  // namespace

void packRecord(const RecordLayout<ObjectRecord>& layout, const ObjectRecord& record,
                std::vector<glm::ivec4>& out)
{
    pack(layout, record, out);
}

template <typename Record>
void packRecord(const RecordLayout<Record>& layout, const Record& record,
                std::vector<glm::vec4>& out)
{
    pack(layout, record, out);
}

template void packRecord(const RecordLayout<PigmentRecord>&, const PigmentRecord&,
                         std::vector<glm::vec4>&);
template void packRecord(const RecordLayout<FinishRecord>&, const FinishRecord&,
                         std::vector<glm::vec4>&);
template void packRecord(const RecordLayout<ConductorRecord>&, const ConductorRecord&,
                         std::vector<glm::vec4>&);
template void packRecord(const RecordLayout<LightRecord>&, const LightRecord&,
                         std::vector<glm::vec4>&);

std::vector<RecordGlsl> recordLayoutsForGlsl()
{
    return {glslOf(objectRecordLayout()), glslOf(pigmentRecordLayout()),
            glslOf(finishRecordLayout()), glslOf(conductorRecordLayout()),
            glslOf(lightRecordLayout())};
}

}  // namespace shadergen
