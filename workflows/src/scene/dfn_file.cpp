// The DFN file reader: strict, so that a unit slip or a column too few is
// an error naming its line, not a joint somewhere else.
#include "scene/dfn_file.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "rockfdem/error.hpp"

namespace rockfdem::workflows {
namespace {

bool is_header(const std::string& line) {
  for (char c : line)
    if (std::isalpha(static_cast<unsigned char>(c)) && c != 'e' && c != 'E') return true;
  return false;
}

}  // namespace

std::vector<mesh::JointTrace> read_dfn_csv(const std::string& path, const std::string& key) {
  std::ifstream in(path);
  if (!in)
    throw InputError(path + " (key '" + key + "'): cannot open the DFN file; allowed: a CSV file " +
                     "of x0,y0,x1,y1 per trace, relative to the scene file");
  std::vector<mesh::JointTrace> out;
  std::string line;
  bool names = true;  // the first line that is not a comment may name the columns
  for (long n = 1; std::getline(in, line); ++n) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::size_t first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    const bool header = names && is_header(line);
    names = false;
    if (header) continue;
    const std::string at = path + ":" + std::to_string(n) + " (key '" + key + "'): ";
    std::stringstream cells(line);
    std::string cell;
    double v[4];
    int k = 0;
    while (std::getline(cells, cell, ',')) {
      char* end = nullptr;
      const double x = std::strtod(cell.c_str(), &end);
      const bool blank_rest = end && std::string(end).find_first_not_of(" \t") == std::string::npos;
      if (k >= 4 || end == cell.c_str() || !blank_rest || !std::isfinite(x))
        throw InputError(at + "value '" + cell + "' in \"" + line +
                         "\"; allowed: four finite numbers x0,y0,x1,y1 [m] per line");
      v[k++] = x;
    }
    if (k != 4)
      throw InputError(at + "\"" + line + "\" holds " + std::to_string(k) +
                       " values; allowed: four finite numbers x0,y0,x1,y1 [m] per line");
    if (v[0] == v[2] && v[1] == v[3])
      throw InputError(at + "\"" + line + "\" is a point; allowed: two distinct end points");
    if (out.size() == kMaxDfnTraces)
      throw InputError(at + "more than " + std::to_string(kMaxDfnTraces) +
                       " traces; allowed: at most that many");
    out.push_back({v[0], v[1], v[2], v[3]});
  }
  return out;
}

}  // namespace rockfdem::workflows
