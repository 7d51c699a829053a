#include "render/ShaderSource.h"

#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace render {

namespace fs = std::filesystem;

std::string readTextFile(const fs::path& file)
{
    std::ifstream stream(file, std::ios::binary);
    if (!stream)
        throw std::runtime_error("cannot read " + file.string());
    std::ostringstream text;
    text << stream.rdbuf();
    return text.str();
}

void ShaderSource::add(std::string name, std::string text)
{
    if (!text.empty() && text.back() != '\n')
        text += '\n';
    names_.push_back(std::move(name));
    texts_.push_back(std::move(text));
}

void ShaderSource::addFile(const fs::path& file, const fs::path& root)
{
    std::error_code error;
    fs::path name = fs::relative(file, root, error);
    if (error || name.empty() || name.native().rfind("..", 0) == 0)
        name = file;
    add(name.generic_string(), readTextFile(file));
}

std::string ShaderSource::text() const
{
    std::string result;
    for (std::size_t i = 0; i < texts_.size(); ++i) {
        // The first piece carries #version, which must come before anything else.
        if (i > 0)
            result += "#line 1 " + std::to_string(i) + "\n";
        result += texts_[i];
    }
    return result;
}

std::string ShaderSource::explainLog(const std::string& log) const
{
    static const std::regex mesa(R"(^\s*(\d+):(\d+)\((\d+)\):\s*(.*)$)");
    static const std::regex nvidia(R"(^\s*(\d+)\((\d+)\)\s*:\s*(.*)$)");
    static const std::regex amd(R"(^\s*(ERROR|WARNING):\s*(\d+):(\d+):\s*(.*)$)");

    auto lineOf = [&](std::size_t piece, int line) -> std::string {
        if (piece >= texts_.size() || line < 1)
            return {};
        std::istringstream stream(texts_[piece]);
        std::string text;
        for (int i = 0; i < line && std::getline(stream, text); ++i) {
        }
        return text;
    };
    auto describe = [&](const std::string& pieceText, const std::string& lineText,
                        const std::string& message) {
        const std::size_t piece = std::stoul(pieceText);
        const int line = std::stoi(lineText);
        const std::string name = piece < names_.size() ? names_[piece] : "source " + pieceText;
        std::string result = name + ":" + lineText + ": " + message;
        const std::string code = lineOf(piece, line);
        if (!code.empty())
            result += "\n    | " + code;
        return result;
    };

    std::istringstream stream(log);
    std::string line;
    std::string result;
    while (std::getline(stream, line)) {
        std::smatch match;
        if (std::regex_match(line, match, mesa))
            result += describe(match[1], match[2], match[4]);
        else if (std::regex_match(line, match, nvidia))
            result += describe(match[1], match[2], match[3]);
        else if (std::regex_match(line, match, amd))
            result += describe(match[2], match[3], match[1].str() + ": " + match[4].str());
        else
            result += line;
        result += "\n";
    }
    return result;
}

}  // namespace render
