#pragma once
#include <cstdint>
#include <cstdio>
#include <string>

namespace io {

// Walks the header of an OpenEXR file (OpenEXR's file layout: magic number, version and
// flags, then each part's attributes as name, type, size and value, a part ending with an
// empty name) and throws std::runtime_error "cannot read image NAME: ..." when an attribute
// says it is larger than what is left of the file, or a name runs past its limit. OpenEXR
// allocates an attribute's stated size before it reads it: 1.9 GB for a 3 KB file the fuzz
// target made (tests/README.md, "Fuzzing"). Leaves `file` at its start.
void checkOpenExrHeader(std::FILE* file, std::int64_t fileSize, const std::string& name);

}  // namespace io
