// What an ASCII .msh file says about itself, read without gmsh. gmsh keeps
// the last of two nodes given one tag without a word, so the only trace of
// such a file is that it declares more nodes than gmsh ends up holding.
#include "msh_header.hpp"

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

}  // namespace rockfdem::mesh::detail
