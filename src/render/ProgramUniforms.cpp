#include "render/ProgramUniforms.h"

#include <glm/gtc/type_ptr.hpp>

#include <stdexcept>
#include <type_traits>
#include <variant>

namespace render {

ProgramUniforms::ProgramUniforms(const gl::Program& program, std::set<std::string> declared)
    : program_(program), declared_(std::move(declared))
{
}

GLint ProgramUniforms::location(const std::string& name)
{
    if (!declares(name))
        throw std::logic_error("the host sets uniform " + name +
                               ", which the shader does not declare");
    set_.insert(name);
    return program_.uniformLocation(name.c_str());
}

void ProgramUniforms::set(const std::string& name, const settings::UniformValue& value)
{
    const GLint at = location(name);
    std::visit(
        [at](const auto& v) {
            using T = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<T, int> || std::is_same_v<T, bool>)
                glUniform1i(at, static_cast<GLint>(v));
            else if constexpr (std::is_same_v<T, unsigned int>)
                glUniform1ui(at, v);
            else if constexpr (std::is_same_v<T, float>)
                glUniform1f(at, v);
            else if constexpr (std::is_same_v<T, glm::vec2>)
                glUniform2fv(at, 1, glm::value_ptr(v));
            else if constexpr (std::is_same_v<T, glm::vec3>)
                glUniform3fv(at, 1, glm::value_ptr(v));
            else if constexpr (std::is_same_v<T, glm::uvec2>)
                glUniform2ui(at, v.x, v.y);
            else
                glUniform4iv(at, 1, glm::value_ptr(v));
        },
        value);
}

// An empty table leaves the array's one element at zero: the shader reads no record of it.
void ProgramUniforms::setArray(const std::string& name, const std::vector<glm::vec4>& values)
{
    const GLint at = location(name);
    if (at >= 0 && !values.empty())
        glUniform4fv(at, static_cast<GLsizei>(values.size()), glm::value_ptr(values[0]));
}

void ProgramUniforms::setArray(const std::string& name, const std::vector<glm::ivec4>& values)
{
    const GLint at = location(name);
    if (at >= 0 && !values.empty())
        glUniform4iv(at, static_cast<GLsizei>(values.size()), glm::value_ptr(values[0]));
}

void ProgramUniforms::checkEveryDeclaredSet() const
{
    std::string unset;
    for (const std::string& name : declared_)
        if (set_.count(name) == 0)
            unset += (unset.empty() ? "" : ", ") + name;
    if (!unset.empty())
        throw std::logic_error("the shader declares uniforms the host never sets: " + unset);
}

}  // namespace render
