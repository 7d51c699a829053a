#include "shadergen/UniformBlock.h"

#include "settings/SettingsTable.h"
#include "shadergen/SceneRecords.h"

#include <algorithm>
#include <sstream>

namespace shadergen {

std::vector<UniformDeclaration> settingUniformDeclarations()
{
    std::vector<UniformDeclaration> declarations;
    for (const settings::SettingRow& row : settings::settingRows())
        if (row.isUniform())
            declarations.push_back({row.glslType, settings::uniformName(row.field),
                                    settings::perPixelCopyName(row.field),
                                    row.description.uniformModule, row.description.uniformGuard});
    return declarations;
}

namespace {

// "uFinishes" -> "gFinishes"
std::string copyOf(const std::string& uniform)
{
    return "g" + uniform.substr(1);
}

// `#if guard` before what `write` writes and `#endif` after it, where there is a guard.
template <typename Write>
void guarded(std::ostringstream& out, const std::string& guard, Write write)
{
    if (!guard.empty())
        out << "#if " << guard << "\n";
    write();
    if (!guard.empty())
        out << "#endif\n";
}

void declareRecords(std::ostringstream& out, const RecordGlsl& record, bool inBuffers)
{
    const std::string parts = std::to_string(record.parts);
    out << "\n// Per " << record.indexName << ", " << parts << " " << record.element << ":\n";
    for (int part = 0; part < record.parts; ++part) {
        out << "//   " << part << ":";
        for (const RecordGlsl::Field& field : record.fields)
            if (field.part == part)
                out << " " << field.accessor << " ." << field.components;
        out << "\n";
    }
    if (inBuffers && !record.bufferSampler.empty()) {
        out << "uniform " << (record.element == "ivec4" ? "isamplerBuffer " : "samplerBuffer ")
            << record.bufferSampler << ";\n"
            << "#define " << record.macro << "(" << record.indexName << ", part) texelFetch("
            << record.bufferSampler << ", " << (record.parts == 1 ? "" : parts + " * ") << "("
            << record.indexName << ")" << (record.parts == 1 ? "" : " + (part)") << ")\n";
        return;
    }
    const std::string size =
        record.parts == 1 ? record.countDefine : parts + " * " + record.countDefine;
    out << "uniform " << record.element << " " << record.uniform << "[" << size << "];\n";
    out << "#if " << record.countDefine << " == 1\n"
        << record.element << " " << copyOf(record.uniform) << "[" << parts << "];\n"
        << "#define " << record.macro << "(" << record.indexName << ", part) "
        << copyOf(record.uniform) << "[part]\n"
        << "#else\n"
        << "#define " << record.macro << "(" << record.indexName << ", part) " << record.uniform
        << "[" << (record.parts == 1 ? "" : parts + " * ") << "(" << record.indexName << ")"
        << (record.parts == 1 ? "" : " + (part)") << "]\n"
        << "#endif\n";
}

void readRecordsOnce(std::ostringstream& out, const RecordGlsl& record, bool inBuffers)
{
    if (inBuffers && !record.bufferSampler.empty())
        return;
    out << "#if " << record.countDefine << " == 1\n";
    if (record.parts == 1)
        out << "    " << copyOf(record.uniform) << "[0] = " << record.uniform << "[0];\n";
    else
        out << "    for (int part = 0; part < " << record.parts << "; ++part)\n"
            << "        " << copyOf(record.uniform) << "[part] = " << record.uniform << "[part];\n";
    out << "#endif\n";
}

void writeAccessors(std::ostringstream& out, const RecordGlsl& record)
{
    out << "\n";
    for (const RecordGlsl::Field& field : record.fields) {
        if (!field.comment.empty())
            out << "// " << field.accessor << ": " << field.comment << "\n";
        const std::string slot = record.macro + "(" + record.indexName + ", " +
                                 std::to_string(field.part) + ")." + field.components;
        // A float array holds integers as floats, and a flag as 1 or 0.
        const bool converted =
            record.element == "vec4" &&
            (field.glslType == "int" || field.glslType == "uint" || field.glslType == "bool");
        out << field.glslType << " " << field.accessor << "(int " << record.indexName
            << ") { return " << (converted ? field.glslType + "(" + slot + ")" : slot) << "; }\n";
    }
}

}  // namespace

std::string uniformBlock(const std::vector<UniformDeclaration>& scalars,
                         const std::vector<std::string>& modules)
{
    std::vector<const UniformDeclaration*> used;
    for (const UniformDeclaration& scalar : scalars)
        if (std::find(modules.begin(), modules.end(), scalar.module) != modules.end())
            used.push_back(&scalar);
    const std::vector<RecordGlsl> records = recordLayoutsForGlsl();
    // The general shader reads every table that grows with the scene's objects from buffer
    // textures (render/SceneDataBuffers.h): a uniform array holds a few thousand vec4s at most.
    const bool inBuffers =
        std::find(modules.begin(), modules.end(), "shape_interpreter.glsl") != modules.end();

    std::ostringstream out;
    out << "// The uniforms, each read once per pixel into the copy the modules read (uX into\n"
           "// gX): shadergen/UniformBlock.h says why. Generated from their descriptions:\n"
           "// settings/Options.def, render/SceneUniforms.cpp, shadergen/SceneRecords.cpp.\n\n";
    for (const UniformDeclaration* scalar : used)
        guarded(out, scalar->guard, [&] {
            out << "uniform " << scalar->glslType << " " << scalar->name << ";  // "
                << scalar->module << "\n";
        });
    out << "\n";
    for (const UniformDeclaration* scalar : used)
        guarded(out, scalar->guard,
                [&] { out << scalar->glslType << " " << scalar->copy << ";\n"; });

    out << "\n// Shape parameters: one or more vec4 per primitive or transform, addressed by slot\n"
           "// (SHAPE_PARAMETER(slot)).\n";
    if (inBuffers)
        out << "uniform samplerBuffer uShapeParameterBuffer;\n"
               "#define SHAPE_PARAMETER(slot) texelFetch(uShapeParameterBuffer, slot)\n";
    else
        out << "uniform vec4 uShapeParameters[SHAPE_PARAMETER_ARRAY_SIZE];\n"
               "#if SHAPE_PARAMETERS_READ_ONCE\n"
               "vec4 gShapeParameters[SHAPE_PARAMETER_ARRAY_SIZE];\n"
               "#define SHAPE_PARAMETERS gShapeParameters\n"
               "#else\n"
               "#define SHAPE_PARAMETERS uShapeParameters\n"
               "#endif\n"
               "#define SHAPE_PARAMETER(slot) SHAPE_PARAMETERS[slot]\n";
    for (const RecordGlsl& record : records)
        guarded(out, record.guard, [&] { declareRecords(out, record, inBuffers); });

    out << "\nvoid readUniformsOnce()\n{\n"
           "#if SHAPE_PARAMETERS_READ_ONCE\n"
           "    for (int i = 0; i < SHAPE_PARAMETER_ARRAY_SIZE; ++i)\n"
           "        gShapeParameters[i] = uShapeParameters[i];\n"
           "#endif\n";
    for (const RecordGlsl& record : records)
        guarded(out, record.guard, [&] { readRecordsOnce(out, record, inBuffers); });
    for (const UniformDeclaration* scalar : used)
        guarded(out, scalar->guard,
                [&] { out << "    " << scalar->copy << " = " << scalar->name << ";\n"; });
    out << "}\n";

    out << "\n// --- accessors: where object, pigment, finish and light records are decoded\n";
    for (const RecordGlsl& record : records)
        guarded(out, record.guard, [&] { writeAccessors(out, record); });
    return out.str();
}

}  // namespace shadergen
