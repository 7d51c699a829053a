#pragma once
#include <cstdint>
#include <cstdio>
#include <string>

namespace io {

// Parses the header of an OpenEXR file with OpenEXR's core library, strictly (every
// attribute's contents must fill its stated size, every size must fit in the file, the data
// window and tiles within io/ImageFile.h's limits), and throws std::runtime_error "cannot read
// image NAME: ..." with its reason when it fails. The C++ library OpenImageIO reads through
// allocates an attribute's stated size before it reads it, and parses typed attributes by their
// contents, not their sizes: a channel list that runs past its size put the next attribute's
// "size" at 1.9 GB, allocated for a file of 2 KB (the EXR fuzz target's findings,
// tests/README.md, "Fuzzing"). Reads through the file's descriptor; leaves the stream as it was.
// Returns the layout of its first part (the image OpenImageIO reads), for io/ImageFile.h's
// limits to be checked before the C++ library opens the file (it sets aside buffers for the
// data window's rows as it opens).
struct ImageLayout {
    std::int64_t x = 0;
    std::int64_t y = 0;
    std::int64_t width = 0;
    std::int64_t height = 0;
    int channels = 0;
    std::int64_t bytesPerPixel = 0;  // as stored
    int tileWidth = 0;               // 0: scan lines
    int tileHeight = 0;
    bool deep = false;
    bool volume = false;
};
ImageLayout checkOpenExrHeader(std::FILE* file, std::int64_t fileSize, const std::string& name);

}  // namespace io
