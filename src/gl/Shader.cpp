#include "gl/Shader.h"

#include <stdexcept>
#include <utility>
#include <vector>

namespace gl {

namespace {

// A shader's or a program's info log: GL has a pair of functions for each, alike but for
// the object's kind.
template <typename GetParameter, typename GetLog>
std::string infoLog(GLuint object, GetParameter getParameter, GetLog getLog)
{
    GLint length = 0;
    getParameter(object, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    getLog(object, length, nullptr, log.data());
    return log.data();
}

std::string shaderLog(GLuint shader)
{
    return infoLog(shader, glGetShaderiv, glGetShaderInfoLog);
}

std::string programLog(GLuint program)
{
    return infoLog(program, glGetProgramiv, glGetProgramInfoLog);
}

GLuint compile(GLenum stage, const std::string& source, const std::string& label,
               const LogExplainer& explain)
{
    const GLuint shader = glCreateShader(stage);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint compiled = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &compiled);
    if (compiled != GL_TRUE) {
        const std::string log = shaderLog(shader);
        glDeleteShader(shader);
        const char* stageName = stage == GL_VERTEX_SHADER    ? "vertex"
                                : stage == GL_COMPUTE_SHADER ? "compute"
                                                             : "fragment";
        throw std::runtime_error("the " + std::string(stageName) + " shader of " + label +
                                 " does not compile:\n" + (explain ? explain(log) : log));
    }
    return shader;
}

}  // namespace

Program::Program(const std::string& vertexSource, const std::string& fragmentSource,
                 const std::string& label, const LogExplainer& explainFragmentLog)
{
    const GLuint vertex = compile(GL_VERTEX_SHADER, vertexSource, label, {});
    GLuint fragment = 0;
    try {
        fragment = compile(GL_FRAGMENT_SHADER, fragmentSource, label, explainFragmentLog);
    } catch (...) {
        glDeleteShader(vertex);
        throw;
    }
    link({vertex, fragment}, label, explainFragmentLog);
}

Program Program::compute(const std::string& computeSource, const std::string& label,
                         const LogExplainer& explainLog)
{
    Program program;
    program.link({compile(GL_COMPUTE_SHADER, computeSource, label, explainLog)}, label, explainLog);
    return program;
}

void Program::link(const std::vector<GLuint>& shaders, const std::string& label,
                   const LogExplainer& explainLog)
{
    id_ = glCreateProgram();
    for (GLuint shader : shaders)
        glAttachShader(id_, shader);
    glLinkProgram(id_);
    for (GLuint shader : shaders)
        glDeleteShader(shader);
    GLint linked = GL_FALSE;
    glGetProgramiv(id_, GL_LINK_STATUS, &linked);
    if (linked != GL_TRUE) {
        const std::string log = programLog(id_);
        glDeleteProgram(id_);
        id_ = 0;
        throw std::runtime_error("the shaders of " + label + " do not link:\n" +
                                 (explainLog ? explainLog(log) : log));
    }
}

Program::~Program()
{
    if (id_ != 0)
        glDeleteProgram(id_);
}

Program::Program(Program&& other) noexcept : id_(std::exchange(other.id_, 0)) {}

Program& Program::operator=(Program&& other) noexcept
{
    if (this != &other) {
        if (id_ != 0)
            glDeleteProgram(id_);
        id_ = std::exchange(other.id_, 0);
    }
    return *this;
}

void Program::use() const
{
    glUseProgram(id_);
}

GLint Program::uniformLocation(const char* name) const
{
    return glGetUniformLocation(id_, name);
}

}  // namespace gl
