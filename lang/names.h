/// @file lang/names.h
/// @brief "Did you mean" suggestions for misspelt names.
#pragma once

#include <string>
#include <vector>

namespace kerf {

/// Levenshtein distance between two words.
int editDistance(const std::string& a, const std::string& b);

/// The candidate closest to `name` if it is close enough to be a likely typo (at most a
/// third of the letters wrong, and at least one right); empty otherwise.
std::string closestName(const std::string& name, const std::vector<std::string>& candidates);

/// "did you mean 'x'?" for the closest candidate, or empty.
std::string didYouMean(const std::string& name, const std::vector<std::string>& candidates);

/// "a, b, c": the candidates separated by commas.
std::string joinNames(const std::vector<std::string>& names);

}  // namespace kerf
