#pragma once
// Render files made wrong on purpose, from a good one: the ways a file from elsewhere can be
// wrong that the program must refuse (docs/USAGE.md, "Files from elsewhere"; issue 35 found each
// of them accepted). The tests of merge, --resume and info, and the EXR fuzz target's
// regression inputs (tests/fuzz/render-file-findings/, written by make_render_file_findings),
// all come from this one list.
#include "io/ImageFile.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace testing_support {

// The pixel whose values the value cases change (every base file is at least 8x6).
inline constexpr int kCraftedPixelX = 3;
inline constexpr int kCraftedPixelY = 2;

struct CraftedRenderFile {
    std::string name;     // the file's name without .exr
    std::string refusal;  // what the program's refusal must say
    // What is changed in the base file: its values and attributes (after which the file is
    // written again, its pixels' SHA-256 made to match, as someone who made it up would),
    // the compression it is written with, then its bytes. Any may be empty.
    std::function<void(io::ImageFileContents&)> editContents;
    std::string compression;
    std::function<void(std::vector<unsigned char>&)> editBytes;
};

const std::vector<CraftedRenderFile>& craftedRenderFiles();
const CraftedRenderFile& craftedRenderFile(const std::string& name);

// Writes `crafted`, made from `base` (an EXR this program wrote, at least 8x6, with every
// pixel holding samples), to `path`.
void writeCraftedRenderFile(const CraftedRenderFile& crafted, const std::filesystem::path& base,
                            const std::filesystem::path& path);

// The value of `channel` at the crafted pixel, to edit.
float& craftedValue(io::ImageFileContents& file, const std::string& channel);

// Sets the attribute `name` (added when missing).
void setAttribute(io::ImageFileContents& file, const std::string& name, const std::string& value);

}  // namespace testing_support
