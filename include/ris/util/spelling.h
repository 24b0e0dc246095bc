// "Did you mean ...?": the nearest of a set of names to a misspelt one.
//
// The distance is the optimal-string-alignment edit distance (insertions,
// deletions, substitutions and swaps of two neighbouring letters, each 1;
// Damerau 1964), taken without regard to case, as git's and CLI11's own
// suggestions are. A name is suggested only when it is near enough to be a
// slip, at most a third of the word's letters (and at least one) away, and
// nearer than every other name, so that "polarization" gives "polarisation"
// and "bat" gives nothing when both "cat" and "hat" are candidates.
//
// Example:
//   did_you_mean("simulat", {"simulate", "study"})  // " (did you mean \"simulate\"?)"
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ris {

// The edit distance described above.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate nearest to `word` when it is near enough and unique.
std::optional<std::string> nearest_name(std::string_view word,
                                        const std::vector<std::string>& candidates);

// " (did you mean \"x\"?)" for the nearest candidate, or "".
std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace ris
