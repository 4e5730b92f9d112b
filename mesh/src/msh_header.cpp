// What an ASCII .msh file says about itself, read without gmsh. gmsh keeps
// the last of two nodes given one tag without a word, so the only trace of
// such a file is that it declares more nodes than gmsh ends up holding.
#include "msh_header.hpp"

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace rockfdem::mesh::detail {

std::optional<std::size_t> declared_node_count(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  double version = 0;
  int file_type = -1;
  while (std::getline(in, line)) {
    if (line.rfind("$MeshFormat", 0) == 0) {
      if (!std::getline(in, line)) return std::nullopt;
      std::istringstream(line) >> version >> file_type;
      if (file_type != 0) return std::nullopt;  // binary: counts are not text
    } else if (line.rfind("$Nodes", 0) == 0) {
      if (!std::getline(in, line) || file_type != 0) return std::nullopt;
      std::istringstream header(line);
      std::size_t first = 0, second = 0;
      header >> first;
      if (version < 4) return first;  // MSH 2: the node count
      if (header >> second) return second;  // MSH 4: blocks, nodes, min, max tag
      return std::nullopt;
    }
  }
  return std::nullopt;
}

bool starts_as_msh(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!std::getline(in, line)) return false;
  return line.rfind("$MeshFormat", 0) == 0 || line.rfind("$NOD", 0) == 0;
}

std::optional<std::string> tag_out_of_int_range(const std::string& path) {
  std::ifstream in(path);
  std::string line, token;
  bool in_tags = false;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    if (line.rfind("$MeshFormat", 0) == 0) {
      if (!std::getline(in, line)) return std::nullopt;
      ++number;
      double version = 0;
      int file_type = -1;
      std::istringstream(line) >> version >> file_type;
      if (file_type != 0) return std::nullopt;  // binary: numbers are not text
    } else if (line.rfind("$Elements", 0) == 0 || line.rfind("$Periodic", 0) == 0) {
      in_tags = true;
    } else if (line.rfind("$End", 0) == 0) {
      in_tags = false;
    } else if (in_tags) {
      std::istringstream words(line);
      while (words >> token) {
        char* end = nullptr;
        errno = 0;
        const long long v = std::strtoll(token.c_str(), &end, 10);
        if (*end != '\0') continue;  // not an integer: gmsh's own checks answer it
        if (errno == ERANGE || v < 0 || v > INT_MAX)
          return "line " + std::to_string(number) + ": '" + token + "'";
      }
    }
  }
  return std::nullopt;
}

}  // namespace rockfdem::mesh::detail
