#pragma once
#include "gl/EntryPoints.h"

#include <functional>
#include <string>
#include <vector>

namespace gl {

// Turns a compiler or linker log into something a person can act on (for example by
// naming the shader module and line each message refers to).
using LogExplainer = std::function<std::string(const std::string& log)>;

// A linked program: vertex + fragment, or compute. Move-only; deletes the GL program it owns.
class Program {
public:
    // Compiles and links; throws std::runtime_error with the explained log on failure.
    Program(const std::string& vertexSource, const std::string& fragmentSource,
            const std::string& label, const LogExplainer& explainFragmentLog = {});
    // A compute program (OpenGL 4.3), the same way.
    static Program compute(const std::string& computeSource, const std::string& label,
                           const LogExplainer& explainLog = {});
    ~Program();
    Program(Program&& other) noexcept;
    Program& operator=(Program&& other) noexcept;
    Program(const Program&) = delete;
    Program& operator=(const Program&) = delete;

    GLuint id() const { return id_; }
    void use() const;
    // -1 when the uniform does not exist or was optimised away (setting it is then a no-op).
    GLint uniformLocation(const char* name) const;

private:
    Program() = default;
    // Links the compiled `shaders` (and deletes them); throws with the explained log.
    void link(const std::vector<GLuint>& shaders, const std::string& label,
              const LogExplainer& explainLog);

    GLuint id_ = 0;
};

}  // namespace gl
