#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace shadergen {

// A shader assembled from named pieces (the preamble of #version and #defines, modules
// from shaders/modules/, user SDF files, generated scene code). Each piece gets its own GLSL
// source-string number and its own range of line numbers through `#line FIRST N`: piece N
// starts at line N * 100000 + 1 (later if an earlier piece is longer than that). The line
// number alone then tells which piece a compiler message is about: Mesa reports some errors
// (a call to an undefined function, for one) with source-string number 0 whatever piece they
// are in, but with the right line number.
class ShaderSource {
public:
    // Line numbers per piece: piece N starts at a multiple of this, plus one.
    static constexpr long kLinesPerPiece = 100000;

    void add(std::string name, std::string text);
    // Reads `file` and adds it under a name relative to `root` when it lies inside it.
    void addFile(const std::filesystem::path& file, const std::filesystem::path& root);

    std::string text() const;

    // Rewrites a compiler log's "0:12(5): error: ..." (Mesa), "0(12) : error ..." (NVIDIA)
    // or "ERROR: 0:12: ..." (AMD, Intel) locations as "name:12: error: ...", followed by the
    // offending source line. The piece is the one whose range holds the reported line number,
    // whatever the reported source-string number; only a line outside every range falls back
    // on the source-string number.
    std::string explainLog(const std::string& log) const;

private:
    std::vector<std::string> names_;
    std::vector<std::string> texts_;
    std::vector<long> firstLines_;  // the line number of each piece's first line
};

// The text of a file; throws std::runtime_error naming it when it cannot be read.
std::string readTextFile(const std::filesystem::path& file);

}  // namespace shadergen
