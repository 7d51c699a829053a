#pragma once
#include <string>

namespace gl {

// Throws std::runtime_error naming the GL error and `operation` if GL has recorded one.
void throwOnGlError(const std::string& operation);

}  // namespace gl
