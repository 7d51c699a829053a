#pragma once
// One shape at a time: its numbers laid out in the parameter array (uShapeParameters, the
// same layout for both shaders), and its distance either as generated GLSL functions (the
// specialised shader) or as a program of instructions for shape_interpreter.glsl (the
// general one).
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace shadergen {

// "SHAPE_PARAMETER(i)": the uniform array's element i, or the buffer texture's texel i in
// the general shader (UniformBlock.cpp).
std::string parameterSlot(int index);

class ShapeCompiler {
public:
    // Values are appended to `parameters`, instructions to `program`. Generated functions are
    // named `functionPrefix` and a number (two compilers whose functions share one shader need
    // different prefixes).
    ShapeCompiler(std::vector<glm::vec4>& parameters, std::vector<glm::ivec4>& program,
                  std::string functionPrefix = "shape");

    // --- specialised: one GLSL function per shape node --------------------------------------

    // The object the functions that follow belong to, named in a comment above each: its
    // index in the scene, and its file and line.
    void beginObject(std::size_t index, const std::string& source, int line);
    // Emits the functions of `shape` and returns the name of its outermost one.
    std::string emitFunction(const scene::Shape& shape);
    // Every function emitted so far, callees before callers.
    std::string functions() const { return functions_.str(); }

    // --- general: instructions for shape_interpreter.glsl -----------------------------------

    // `depth`: the interpreter's distances already on its stack.
    void emitProgram(const scene::Shape& shape, int depth);
    // Ends an object's program.
    void endProgram();
    int programSize() const { return static_cast<int>(program_.size()); }
    int maxStackDepth() const { return maxDepth_; }
    // The user SDFs met so far, by the number the interpreter calls them by.
    const std::map<std::string, int>& userSdfIds() const { return userIds_; }

    // --- values the scene's own code reads ---------------------------------------------------

    int allocateValue(const glm::vec4& value) { return allocate({value}); }
    // Consecutive slots; the first one's index.
    int allocateValues(const std::vector<glm::vec4>& values) { return allocate(values); }
    int allocateBound(const scene::ShapeBound& bound);

private:
    struct PrimitiveLayout {
        int kind;
        int first;
        int extra;
        std::string expression;  // specialised code, in terms of p
    };

    int allocate(const std::vector<glm::vec4>& values);
    int allocateTransform(const scene::Transform& transform);
    int userSdfId(const std::string& name);
    PrimitiveLayout layoutPrimitive(const scene::Geometry& geometry);
    std::string newFunctionName();
    void writeFunction(const std::string& name, const std::string& what, const std::string& body);
    std::string emitGeometry(const scene::Geometry& geometry);
    std::string emitGeometryBody(const scene::Geometry& geometry);
    void emitGeometryProgram(const scene::Geometry& geometry, int depth);

    std::vector<glm::vec4>& parameters_;
    std::vector<glm::ivec4>& program_;
    std::ostringstream functions_;
    std::string functionPrefix_;
    std::string objectLabel_;
    int nextFunction_ = 0;
    int maxDepth_ = 1;
    std::map<std::string, int> userIds_;
};

}  // namespace shadergen
