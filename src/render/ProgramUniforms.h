#pragma once
// Sets a program's uniforms by name, and holds the host to the shader's declarations: GL
// ignores a uniform set under a name the program does not have (its location is -1) and
// leaves one never set at zero, so a misspelt name on either side would render a wrong
// image silently. Here setting a uniform the shader does not declare throws at once, and
// checkEveryDeclaredSet() throws for every declared one not set since the program was built.
#include "gl/Shader.h"
#include "settings/OptionValues.h"

#include <glm/glm.hpp>

#include <set>
#include <string>
#include <vector>

namespace render {

class ProgramUniforms {
public:
    // `declared`: every uniform the program's source declares (shadergen::declaredUniforms);
    // some may have been optimised away, which makes setting them a no-op, not an error.
    ProgramUniforms(const gl::Program& program, std::set<std::string> declared);

    bool declares(const std::string& name) const { return declared_.count(name) != 0; }

    // The program must be in use. Throws std::logic_error when `name` is not declared.
    void set(const std::string& name, const settings::UniformValue& value);
    void setArray(const std::string& name, const std::vector<glm::vec4>& values);
    void setArray(const std::string& name, const std::vector<glm::ivec4>& values);

    // Throws std::logic_error naming every declared uniform never set.
    void checkEveryDeclaredSet() const;

private:
    GLint location(const std::string& name);

    const gl::Program& program_;
    std::set<std::string> declared_;
    std::set<std::string> set_;
};

}  // namespace render
