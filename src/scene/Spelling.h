#pragma once
// How near two words are in spelling, for the "did you mean" of a misspelt scene keyword
// (scene/SceneParser) and of a misspelt command-line option (app/CommandLine): one helper,
// here at floor 0 where both can reach it.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace scene {

// The number of single-character insertions, deletions and substitutions that turn one word
// into the other (Levenshtein).
std::size_t editDistance(const std::string& a, const std::string& b);

// The words a "did you mean" may offer: at most this many edits from what was written.
constexpr std::size_t kMostEditsSuggested = 2;

// The candidate nearest to `word` within kMostEditsSuggested edits (the first of equals), or
// nothing where none is that near or `word` is a candidate itself.
std::optional<std::string> nearestWord(const std::string& word,
                                       const std::vector<std::string>& candidates);

}  // namespace scene
