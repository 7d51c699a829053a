#include "shadergen/ShaderCodes.h"

#include "scene/KindCodes.h"
#include "scene/Lights.h"
#include "scene/PrimitiveKinds.h"
#include "scene/Scene.h"
#include "settings/SettingsTable.h"

#include <sstream>

namespace shadergen {

namespace {

const char* const kOpcodeIdentifiers[] = {"End", "Primitive", "PushFrame", "PopFrame", "Combine"};
static_assert(std::size(kOpcodeIdentifiers) == static_cast<std::size_t>(Opcode::Combine) + 1,
              "one name per opcode");

void define(std::ostringstream& out, const std::string& name, int value)
{
    out << "#define " << name << " " << value << "\n";
}

}  // namespace

std::string shaderCodeDefines()
{
    std::ostringstream out;
    for (std::size_t opcode = 0; opcode < std::size(kOpcodeIdentifiers); ++opcode)
        define(out, scene::codeName("OPCODE_", kOpcodeIdentifiers[opcode]),
               static_cast<int>(opcode));
    for (const scene::PrimitiveKind& kind : scene::primitiveKinds())
        define(out, scene::primitiveCodeName(kind), kind.code);
    define(out, "PRIMITIVE_USER", scene::userSdfCode());
    for (const scene::CsgOperatorDescription& op : scene::csgOperatorDescriptions())
        define(out, scene::codeName(op), op.code);
    for (const scene::MaterialDescription& material : scene::materialDescriptions())
        define(out, scene::codeName(material), material.code);
    for (const scene::PigmentDescription& pigment : scene::pigmentDescriptions())
        define(out, scene::codeName(pigment), pigment.code);
    for (const scene::EnvironmentDescription& environment : scene::environmentDescriptions())
        define(out, scene::codeName(environment), environment.code);
    for (const scene::LightDescription& light : scene::lightDescriptions())
        define(out, scene::codeName(light), light.code);
    out << settings::choiceDefines();
    return out.str();
}

}  // namespace shadergen
