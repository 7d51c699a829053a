#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace io {

// The image formats the program writes, described once: the command line's check, its --help
// and the writer all read this table (docs/USAGE.md lists the same).
struct ImageFormat {
    std::vector<std::string> extensions;  // lower case, with the dot
    bool linearRadiance;                  // linear HDR values; else a tone-mapped picture
    bool float32;                         // holds 32-bit floats exactly (per-pixel statistics)
    std::string holds;                    // for --help
    // OpenImageIO's name for the format: the only reader and writer tried for its files
    // (a file is never handed to another format's reader to guess what it is).
    std::string openImageIoName;
};

const std::vector<ImageFormat>& outputFormats();

// `path`'s extension in lower case, with the dot: ".exr" for "A.EXR".
std::string lowerCaseExtension(const std::filesystem::path& path);

// The format `path`'s extension names (in any case), or nullptr.
const ImageFormat* outputFormatOf(const std::filesystem::path& path);

// The format `path`'s extension names; throws std::runtime_error naming the file and the
// extensions known when it names none.
const ImageFormat& imageFormatOf(const std::filesystem::path& path);

// ".ppm, .png, ..., .hdr": every extension of `formats`, for messages.
std::string listExtensions(const std::vector<const ImageFormat*>& formats);

}  // namespace io
