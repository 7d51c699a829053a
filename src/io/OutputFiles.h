#pragma once
#include "io/Image.h"
#include "io/ImageFile.h"

#include <filesystem>
#include <vector>

namespace io {

// The files a run writes, and the promise about them: each is checked before any work is
// done, and all of them are written or none is, so that no error and no interrupt leaves a
// half-written file, a set of files from two different runs, or a lost older file.

// What an output holds, which decides the formats it may have.
enum class OutputKind {
    Image,       // any format of io/ImageFormats.h: a picture or linear radiance by extension
    Statistics,  // per-pixel counts and variances: a format that holds 32-bit floats exactly
};

struct OutputRequest {
    std::filesystem::path path;
    OutputKind kind = OutputKind::Image;
};

// Throws std::runtime_error, naming the user's path and the system's reason (strerror), unless
// each output can be created: its folder exists and is writable, the path is not a folder, and
// its extension names a format for its kind.
void checkOutputsCanBeWritten(const std::vector<OutputRequest>& outputs);

// Whether two paths name one file: after making them absolute, resolving symbolic links and
// "." and ".." (the file need not exist yet), or as hard links to one existing file.
bool resolveToSameFile(const std::filesystem::path& a, const std::filesystem::path& b);

struct OutputImage {
    std::filesystem::path path;
    Image image;
    std::vector<ImageAttribute> attributes;
    // Where the format names channels (EXR): one name per channel; empty, R, G, B (A).
    std::vector<std::string> channelNames;
};

// Writes every image under a temporary name beside its destination (same folder, so the
// rename cannot cross file systems) and renames them over their destinations only once all of
// them are complete. On a failure before that, every temporary file is removed and no
// destination is touched. Each rename is atomic; only a folder that changes between two
// renames (removed, made read-only) could leave the first done and the second not.
void writeAllOrNothing(const std::vector<OutputImage>& images);

}  // namespace io
