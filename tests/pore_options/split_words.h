#pragma once
// A command line's words, split on blanks as LIGGGHTS splits them (the parser tests' input).
#include <sstream>
#include <string>
#include <vector>

inline std::vector<std::string> split(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}
