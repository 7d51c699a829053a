#include "shadergen/ShapeCompiler.h"

#include "scene/PrimitiveKinds.h"
#include "shadergen/ShaderCodes.h"

#include <algorithm>
#include <utility>

namespace shadergen {

using namespace scene;

namespace {

int instruction(Opcode opcode)
{
    return static_cast<int>(opcode);
}

// What a shape node is, for the comment above its function.
std::string describeGeometry(const Geometry& geometry)
{
    if (const PrimitiveKind* kind = primitiveKindOf(geometry))
        return kind->keyword;
    if (const auto* user = std::get_if<UserSdf>(&geometry))
        return "user SDF " + user->name;
    const CsgOperatorDescription& op = describe(std::get<CsgNode>(geometry).op);
    return std::string(op.keyword) + (op.hasParameter() ? " " + std::string(op.smoothingWord) : "");
}

}  // namespace

std::string parameterSlot(int index)
{
    return "SHAPE_PARAMETER(" + std::to_string(index) + ")";
}

ShapeCompiler::ShapeCompiler(std::vector<glm::vec4>& parameters, std::vector<glm::ivec4>& program,
                             std::string functionPrefix)
    : parameters_(parameters), program_(program), functionPrefix_(std::move(functionPrefix))
{
}

void ShapeCompiler::beginObject(std::size_t index, const std::string& source, int line)
{
    objectLabel_ = "object " + std::to_string(index) + ", " + source + ":" + std::to_string(line);
}

std::string ShapeCompiler::newFunctionName()
{
    return functionPrefix_ + std::to_string(nextFunction_++);
}

void ShapeCompiler::writeFunction(const std::string& name, const std::string& what,
                                  const std::string& body)
{
    functions_ << "// " << objectLabel_ << ": " << what << "\n"
               << "float " << name << "(vec3 p)\n{\n"
               << body << "}\n\n";
}

// A function is named before its operands' functions are emitted, and written after them.
std::string ShapeCompiler::emitFunction(const Shape& shape)
{
    if (!shape.transform)
        return emitGeometry(shape.geometry);
    const std::string name = newFunctionName();
    const int frame = allocateTransform(*shape.transform);
    const std::string inner = emitGeometry(shape.geometry);
    writeFunction(name, "the transform of " + inner,
                  "    return toWorldDistance(" + inner + "(toLocalPoint(p, " +
                      std::to_string(frame) + ")), " + std::to_string(frame) + ");\n");
    return name;
}

void ShapeCompiler::emitProgram(const Shape& shape, int depth)
{
    maxDepth_ = std::max(maxDepth_, depth + 1);
    if (shape.transform) {
        const int frame = allocateTransform(*shape.transform);
        program_.emplace_back(instruction(Opcode::PushFrame), frame, 0, 0);
        emitGeometryProgram(shape.geometry, depth + 1);
        program_.emplace_back(instruction(Opcode::PopFrame), frame, 0, 0);
    } else {
        emitGeometryProgram(shape.geometry, depth);
    }
}

void ShapeCompiler::endProgram()
{
    program_.emplace_back(instruction(Opcode::End), 0, 0, 0);
}

int ShapeCompiler::allocateBound(const ShapeBound& bound)
{
    return allocate({glm::vec4(bound.center, bound.radius)});
}

int ShapeCompiler::allocate(const std::vector<glm::vec4>& values)
{
    const int first = static_cast<int>(parameters_.size());
    parameters_.insert(parameters_.end(), values.begin(), values.end());
    return first;
}

int ShapeCompiler::allocateTransform(const Transform& transform)
{
    return allocate({glm::vec4(transform.rotation[0], 0.0f), glm::vec4(transform.rotation[1], 0.0f),
                     glm::vec4(transform.rotation[2], 0.0f),
                     glm::vec4(transform.translation, transform.scale)});
}

int ShapeCompiler::userSdfId(const std::string& name)
{
    const auto found = userIds_.find(name);
    if (found != userIds_.end())
        return found->second;
    const int id = static_cast<int>(userIds_.size());
    userIds_[name] = id;
    return id;
}

// Lays out a primitive's parameters (the same layout for both variants).
ShapeCompiler::PrimitiveLayout ShapeCompiler::layoutPrimitive(const Geometry& geometry)
{
    if (const PrimitiveKind* kind = primitiveKindOf(geometry)) {
        const std::vector<glm::vec4> values = primitiveParameters(geometry);
        const int first = allocate(values);
        if (!kind->unionOfTerms)
            return {kind->code, first, 0,
                    distanceOverSlots(*kind, [&](int k) { return parameterSlot(first + k); })};
        std::string expression;
        for (int i = 0; i < static_cast<int>(values.size()); ++i) {
            const std::string term =
                distanceOverSlots(*kind, [&](int) { return parameterSlot(first + i); });
            expression = i == 0 ? term : "min(" + expression + ", " + term + ")";
        }
        return {kind->code, first, static_cast<int>(values.size()), expression};
    }
    const auto& user = std::get<UserSdf>(geometry);
    // A function that may overestimate by a factor L is stepped by distance / L.
    const int s = allocate({glm::vec4(user.position, 1.0f / user.lipschitz)});
    return {userSdfCode(), s, userSdfId(user.name),
            user.name + "(p, " + parameterSlot(s) + ".xyz) * " + parameterSlot(s) + ".w"};
}

std::string ShapeCompiler::emitGeometry(const Geometry& geometry)
{
    const std::string name = newFunctionName();
    writeFunction(name, describeGeometry(geometry), emitGeometryBody(geometry));
    return name;
}

std::string ShapeCompiler::emitGeometryBody(const Geometry& geometry)
{
    if (const auto* node = std::get_if<CsgNode>(&geometry)) {
        std::vector<std::string> children;
        for (const Shape& child : node->children)
            children.push_back(emitFunction(child));
        const CsgOperatorDescription& op = describe(node->op);
        std::string parameter;
        if (op.hasParameter())
            parameter = ", " +
                        parameterSlot(allocate({glm::vec4(node->parameter, 0.0f, 0.0f, 0.0f)})) +
                        ".x";
        std::string body = "    float d = " + children[0] + "(p);\n";
        for (std::size_t i = 1; i < children.size(); ++i)
            body += "    d = " + std::string(op.function) + "(d, " + children[i] + "(p)" +
                    parameter + ");\n";
        return body + "    return d;\n";
    }
    return "    return " + layoutPrimitive(geometry).expression + ";\n";
}

void ShapeCompiler::emitGeometryProgram(const Geometry& geometry, int depth)
{
    if (const auto* node = std::get_if<CsgNode>(&geometry)) {
        for (std::size_t i = 0; i < node->children.size(); ++i)
            emitProgram(node->children[i], depth + static_cast<int>(i));
        const CsgOperatorDescription& op = describe(node->op);
        const int parameter =
            op.hasParameter() ? allocate({glm::vec4(node->parameter, 0.0f, 0.0f, 0.0f)}) : 0;
        program_.emplace_back(instruction(Opcode::Combine), op.code,
                              static_cast<int>(node->children.size()), parameter);
        return;
    }
    const PrimitiveLayout primitive = layoutPrimitive(geometry);
    program_.emplace_back(instruction(Opcode::Primitive), primitive.kind, primitive.first,
                          primitive.extra);
}

}  // namespace shadergen
