#pragma once
// The layouts of the scene's records as the shader reads them from its uniform arrays
// (uObjects, uPigments, uFinishes, uLights), each described once: a record is a C++ struct
// of its values, and its layout says where each value lies in the record's vec4s and which
// GLSL accessor reads it. The host's packing (render/SceneUniforms.cpp) and the shader's
// declarations and accessors (shadergen/UniformBlock.h) are both written from it, so the two
// sides cannot disagree on a slot.
//
// A new field: a member of the record and a line of its layout, read in GLSL by the accessor
// named there.
#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace shadergen {

// Per object (ivec4).
struct ObjectRecord {
    int pigment = 0;
    int finish = 0;
    int sphereLight = -1;       // the sphere light it is, or -1
    int shapeProgramStart = 0;  // the start of its shape program (general shader only)
};

// Per pigment.
struct PigmentRecord {
    int kind = 0;
    float size = 0.0f;  // a checker's cube edge, or a texture's tile size
    float textureLayer = 0.0f;
    glm::vec3 firstColor{0.0f};
    glm::vec3 secondColor{0.0f};
};

// Per finish.
struct FinishRecord {
    glm::vec3 emission{0.0f};
    float phongExponent = 0.0f;
    int material = 0;
    float ior = 1.0f;
    float roughness = 0.0f;  // GGX roughness alpha
};

// Per finish, in shaders of scenes with a rough conductor (HAS_ROUGH_CONDUCTOR): its complex
// index of refraction eta + i k, where it has one; without, its Fresnel is Schlick's with the
// pigment as R0.
struct ConductorRecord {
    glm::vec3 eta{0.0f};
    bool hasComplexIor = false;
    glm::vec3 k{0.0f};
};

// Per light. Lights are chosen in proportion to their emitted power; what each kind's
// record holds is scene/Lights.h's Light.
struct LightRecord {
    glm::vec3 position{0.0f};  // a point light's position, a sphere's centre
    float radius = 0.0f;
    glm::vec3 emission{0.0f};  // a point light's intensity, a sphere's radiance
    float selectionProbability = 0.0f;
    float cumulativeProbability = 0.0f;
    int object = -1;               // the object that is the light, or -1
    std::uint32_t cullingBit = 0;  // that object's culling bit, or 0
    int kind = 0;                  // a LIGHT_* code (scene/Lights.h)
};

template <typename Record>
using RecordMember = std::variant<float Record::*, int Record::*, std::uint32_t Record::*,
                                  glm::vec3 Record::*, bool Record::*>;

template <typename Record>
struct RecordField {
    RecordMember<Record> member;
    int part;                // which of the record's vec4s
    const char* components;  // where in it: "x", "rgb", "w"
    const char* accessor;    // the GLSL function that reads it: `type accessor(int index)`
    const char* comment;     // for the accessor; may be empty
};

// Where a record's values lie and how the shader reads them.
template <typename Record>
struct RecordLayout {
    const char* uniform;      // "uFinishes"
    const char* indexName;    // "finish": the accessors' parameter
    const char* countDefine;  // "FINISH_ARRAY_SIZE": the records the uniform holds
    const char* macro;        // "FINISH_RECORD": (index, part) -> the vec4
    int parts;                // vec4s per record
    bool integer;             // ivec4s (every field an int) rather than vec4s
    std::vector<RecordField<Record>> fields;
    const char* guard = nullptr;  // a define the table is declared under; nullptr: none
    // The buffer texture the general shader reads the table from instead (a table that grows
    // with the scene's objects; render/SceneDataBuffers.h); nullptr: always a uniform array.
    const char* bufferSampler = nullptr;
};

const RecordLayout<ObjectRecord>& objectRecordLayout();
const RecordLayout<PigmentRecord>& pigmentRecordLayout();
const RecordLayout<FinishRecord>& finishRecordLayout();
const RecordLayout<ConductorRecord>& conductorRecordLayout();
const RecordLayout<LightRecord>& lightRecordLayout();

// Appends `record`, laid out by `layout`, to the uniform array `out` (a slot no field takes
// is 0).
void packRecord(const RecordLayout<ObjectRecord>& layout, const ObjectRecord& record,
                std::vector<glm::ivec4>& out);
template <typename Record>
void packRecord(const RecordLayout<Record>& layout, const Record& record,
                std::vector<glm::vec4>& out);

// A layout as text for the GLSL writer.
struct RecordGlsl {
    std::string uniform;
    std::string indexName;
    std::string countDefine;
    std::string macro;
    int parts = 1;
    std::string element;        // "vec4" or "ivec4"
    std::string guard;          // empty: none
    std::string bufferSampler;  // empty: none
    struct Field {
        std::string glslType;
        std::string accessor;
        int part = 0;
        std::string components;
        std::string comment;
    };
    std::vector<Field> fields;
};

// Every record's layout, in the order the shader declares them.
std::vector<RecordGlsl> recordLayoutsForGlsl();

}  // namespace shadergen
