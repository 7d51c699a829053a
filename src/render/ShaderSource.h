#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace render {

// A shader assembled from named pieces (the preamble of #version and #defines, modules
// from shaders/modules/, user SDF files, generated scene code). Each piece gets its own
// GLSL source-string number through `#line 1 N`, so a compiler message can be traced back to
// the piece and line it came from.
class ShaderSource {
public:
    void add(std::string name, std::string text);
    // Reads `file` and adds it under a name relative to `root` when it lies inside it.
    void addFile(const std::filesystem::path& file, const std::filesystem::path& root);

    std::string text() const;
    const std::vector<std::string>& pieceNames() const { return names_; }

    // Rewrites a compiler log's "0:12(5): error: ..." (Mesa), "0(12) : error ..." (NVIDIA)
    // or "ERROR: 0:12: ..." (AMD, Intel) locations as "name:12: error: ...", followed by the
    // offending source line.
    std::string explainLog(const std::string& log) const;

private:
    std::vector<std::string> names_;
    std::vector<std::string> texts_;
};

// The text of a file; throws std::runtime_error naming it when it cannot be read.
std::string readTextFile(const std::filesystem::path& file);

}  // namespace render
