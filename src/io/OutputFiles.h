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
// them are complete. Each is encoded in memory and written by the program itself: every write
// checked, the file synchronised to the disk (fsync), its size on disk compared with what was
// written, and its header read back; the folder is synchronised before and after the renames.
// On a failure before the renames, every temporary file is removed, no destination is touched,
// and the error names the user's path and the system's reason ("No space left on device").
// Each rename is atomic; only a folder that changes between two renames (removed, made
// read-only) could leave the first done and the second not.
void writeAllOrNothing(const std::vector<OutputImage>& images);

// A temporary file of writeAllOrNothing left behind by a process that ended before it
// renamed it (killed, or the machine stopped): ".NAME.partial-HOST-PID-N.EXT" beside
// NAME.EXT.
struct StaleTemporary {
    std::filesystem::path path;
    long processId = 0;
};

// The name writeAllOrNothing writes the `index`th of its images under before it renames it.
std::filesystem::path temporaryNameFor(const std::filesystem::path& destination, std::size_t index);

// Removes the temporary files of these destinations (by their names, above) whose process no
// longer runs on this machine, and returns them. Temporaries of processes still running, of
// other machines (a folder shared over the network) and of other destinations are left.
std::vector<StaleTemporary>
removeStaleTemporaries(const std::vector<std::filesystem::path>& destinations);

}  // namespace io
