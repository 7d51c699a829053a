#include "shadergen/ShaderSource.h"

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace shadergen {

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

namespace {

long lineCount(const std::string& text)
{
    return static_cast<long>(std::count(text.begin(), text.end(), '\n'));
}

// The first line of the range after a piece's: the next multiple of kLinesPerPiece, plus one,
// leaving at least one line past the piece's end (where "unexpected end of file" points).
long nextFirstLine(long firstLine, long lines)
{
    const long step = ShaderSource::kLinesPerPiece;
    return (firstLine + lines + step - 1) / step * step + 1;
}

// A number from a compiler log; -1 when it does not fit (no driver prints such lines).
long parseNumber(const std::string& digits)
{
    return digits.size() <= 9 ? std::stol(digits) : -1;
}

}  // namespace

void ShaderSource::add(std::string name, std::string text)
{
    if (!text.empty() && text.back() != '\n')
        text += '\n';
    firstLines_.push_back(
        texts_.empty() ? 1 : nextFirstLine(firstLines_.back(), lineCount(texts_.back())));
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
        // The first piece carries #version, which must come before anything else; it starts
        // at line 1 of source string 0 anyway.
        if (i > 0)
            result += "#line " + std::to_string(firstLines_[i]) + " " + std::to_string(i) + "\n";
        result += texts_[i];
    }
    return result;
}

std::set<std::string> declaredUniforms(const ShaderSource& source)
{
    static const std::regex declaration(R"(^\s*uniform\s+\w+\s+(\w+))");
    std::set<std::string> names;
    std::istringstream lines(source.text());
    std::smatch match;
    for (std::string line; std::getline(lines, line);)
        if (std::regex_search(line, match, declaration))
            names.insert(match[1]);
    return names;
}

std::string ShaderSource::explainLog(const std::string& log) const
{
    static const std::regex mesa(R"(^\s*(\d+):(\d+)\((\d+)\):\s*(.*)$)");
    static const std::regex nvidia(R"(^\s*(\d+)\((\d+)\)\s*:\s*(.*)$)");
    static const std::regex amd(R"(^\s*(ERROR|WARNING):\s*(\d+):(\d+):\s*(.*)$)");

    struct Location {
        long piece;
        long line;
    };
    // The piece whose range of line numbers holds the reported line, and the line within it;
    // failing that, the reported source string and line as they are.
    auto locate = [&](long source, long line) -> Location {
        const auto after = std::upper_bound(firstLines_.begin(), firstLines_.end(), line);
        if (after != firstLines_.begin()) {
            const std::size_t piece = static_cast<std::size_t>(after - firstLines_.begin()) - 1;
            if (line < nextFirstLine(firstLines_[piece], lineCount(texts_[piece])))
                return {static_cast<long>(piece), line - firstLines_[piece] + 1};
        }
        return {source, line};
    };
    auto lineOf = [&](const Location& where) -> std::string {
        if (where.piece < 0 || where.piece >= static_cast<long>(texts_.size()) || where.line < 1)
            return {};
        std::istringstream stream(texts_[static_cast<std::size_t>(where.piece)]);
        std::string text;
        for (long i = 0; i < where.line && std::getline(stream, text); ++i) {
        }
        return text;
    };
    auto describe = [&](const std::string& sourceText, const std::string& lineText,
                        const std::string& message) {
        const Location where = locate(parseNumber(sourceText), parseNumber(lineText));
        const std::string name = where.piece >= 0 && where.piece < static_cast<long>(names_.size())
                                     ? names_[static_cast<std::size_t>(where.piece)]
                                     : "source " + sourceText;
        std::string result = name + ":" + std::to_string(where.line) + ": " + message;
        const std::string code = lineOf(where);
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

}  // namespace shadergen
