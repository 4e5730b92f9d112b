// What an ASCII .msh file says about itself, read without gmsh. gmsh keeps
// the last of two nodes given one tag without a word, so the only trace of
// such a file is that it declares more nodes than gmsh ends up holding.
#include "msh_header.hpp"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>

namespace rockfdem::mesh::detail {
namespace {

// One line of at most kLineBytes (the rest of a longer one is skipped
// unread into memory); false at the end of the file.
bool bounded_line(std::istream& in, std::string& line) {
  line.clear();
  int ch = 0;
  bool any = false;
  while ((ch = in.get()) != std::char_traits<char>::eof()) {
    any = true;
    if (ch == '\n') return true;
    if (line.size() < kLineBytes) line.push_back(char(ch));
  }
  return any;
}

}  // namespace

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
      if (version < 4) return first;        // MSH 2: the node count
      if (header >> second) return second;  // MSH 4: blocks, nodes, min, max tag
      return std::nullopt;
    }
  }
  return std::nullopt;
}

// The first bytes only: a file with no line break in its first gigabytes
// (a sparse 3 GB file of zeros) was read whole as its "first line".
bool starts_as_msh(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char head[kHeadBytes];
  in.read(head, sizeof head);
  const std::string start(head, std::size_t(in.gcount()));
  return start.rfind("$MeshFormat", 0) == 0 || start.rfind("$NOD", 0) == 0;
}

std::optional<std::string> text_after_last_section(const std::string& path, std::uint64_t size) {
  std::ifstream in(path, std::ios::binary);
  const std::uint64_t n = std::min<std::uint64_t>(size, kTailBytes);
  std::string tail(n, '\0');
  in.seekg(std::streamoff(size - n));
  in.read(tail.data(), std::streamsize(n));
  tail.resize(std::size_t(in.gcount()));
  // The last line that starts with "$End" ("$ENDELM" in MSH 1).
  for (std::size_t at = tail.size(); at > 0;) {
    const std::size_t found = tail.rfind('$', at - 1);
    if (found == std::string::npos) break;
    at = found;
    const bool line_start = found > 0 ? tail[found - 1] == '\n' : n == size;
    if (!line_start || (tail.compare(found, 4, "$End") != 0 && tail.compare(found, 4, "$END") != 0))
      continue;
    const std::size_t line_end = std::min(tail.find('\n', found), tail.size());
    if (tail.find_first_not_of(" \t\r\n", line_end) == std::string::npos) return std::nullopt;
    return "holds " + std::to_string(tail.size() - line_end) +
           " bytes after its last section's end line (" +
           tail.substr(found, std::min<std::size_t>(40, line_end - found)) + ")";
  }
  return "does not end with a section's end line ($End...): its last " + std::to_string(n) +
         " bytes hold none";
}

std::optional<std::uint64_t> declared_items(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  double version = 0;
  std::uint64_t items = 0;
  int found = 0;
  while (found < 2 && bounded_line(in, line)) {
    const bool nodes = line.rfind("$Nodes", 0) == 0 || line.rfind("$NOD", 0) == 0;
    const bool elements = line.rfind("$Elements", 0) == 0 || line.rfind("$ELM", 0) == 0;
    if (line.rfind("$MeshFormat", 0) == 0) {
      int file_type = -1;
      if (!bounded_line(in, line)) return std::nullopt;
      std::istringstream(line) >> version >> file_type;
      if (file_type != 0) return std::nullopt;  // binary: counts are not text
    } else if (nodes || elements) {
      if (!bounded_line(in, line)) return std::nullopt;
      std::istringstream header(line);
      std::uint64_t first = 0, second = 0;
      if (!(header >> first)) return std::nullopt;
      if (version >= 4 && !(header >> second)) return std::nullopt;
      items += version >= 4 ? second : first;  // MSH 4: blocks, items, min, max tag
      ++found;
    }
  }
  return found == 2 ? std::optional<std::uint64_t>(items) : std::nullopt;
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

std::optional<std::string> count_beyond(const std::string& where, std::uint64_t n,
                                        const std::string& what, std::uint64_t bytes,
                                        std::uint64_t per_item) {
  if (n <= bytes / per_item) return std::nullopt;
  return where + " declares " + std::to_string(n) + " " + what + ", but the " +
         std::to_string(bytes) + " bytes after it can hold at most " +
         std::to_string(bytes / per_item) + " (each takes at least " + std::to_string(per_item) +
         " bytes); the count must be the number of " + what + " the section lists";
}

namespace {

// Every node, element or entity takes at least 2 bytes of text: a digit and
// a separator. A count above (bytes left) / 2 cannot be what the file holds.
constexpr std::uint64_t kMinBytesPerItem = 2;

// Scans the counts of an ASCII .msh (count_beyond_file).
class CountScan {
 public:
  explicit CountScan(const std::string& path) : in_(path, std::ios::binary) {
    in_.seekg(0, std::ios::end);
    size_ = in_ ? std::uint64_t(in_.tellg()) : 0;
    in_.seekg(0);
  }

  std::optional<std::string> first_problem() {
    std::string line;
    while (!problem_ && std::getline(in_, line)) {
      while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
      if (line.rfind("$MeshFormat", 0) == 0) {
        if (!std::getline(in_, line)) return std::nullopt;
        int file_type = -1;
        std::istringstream(line) >> version_ >> file_type;
        if (file_type != 0) return std::nullopt;  // binary: counts are not text
      } else if (line == "$Nodes" || line == "$NOD") {
        section("$Nodes", "nodes", version_ >= 4 ? 4 : 0, &CountScan::skip_node_block);
      } else if (line == "$Elements" || line == "$ELM") {
        section("$Elements", "elements", version_ >= 4 ? 4 : 0, &CountScan::skip_element_block);
      } else if (line == "$Entities") {
        entities();
      }
    }
    return problem_;
  }

 private:
  using BlockSkip = bool (CountScan::*)(const std::string (&)[4], std::uint64_t n);

  std::uint64_t left() {
    const auto at = in_.tellg();
    return at < 0 ? 0 : size_ - std::uint64_t(at);
  }

  // A count token: false (and no count) when it is not a whole number,
  // which gmsh's own reader answers.
  bool count_of(const std::string& token, const std::string& where, const std::string& what,
                std::uint64_t& n) {
    if (token.empty()) return false;
    if (token[0] == '-' && token.size() > 1 &&
        token.find_first_not_of("0123456789", 1) == std::string::npos) {
      problem_ = where + " declares " + token + " " + what +
                 "; a count must be a whole number of 0 or more";
      return false;
    }
    if (token.find_first_not_of("0123456789") != std::string::npos) return false;
    errno = 0;
    n = std::strtoull(token.c_str(), nullptr, 10);
    if (errno == ERANGE) n = std::numeric_limits<std::uint64_t>::max();
    return true;
  }

  // Whether `n` items fit the bytes after the current position.
  bool fits(const std::string& where, std::uint64_t n, const std::string& what) {
    problem_ = count_beyond(where, n, what, left(), kMinBytesPerItem);
    return !problem_;
  }

  // A $Nodes or $Elements section: MSH 1 and 2 give the total alone; MSH 4
  // the number of blocks and the total, then each block's count in its
  // header, which the walk checks and adds up.
  void section(const std::string& name, const std::string& what, int header_words, BlockSkip skip) {
    std::string line;
    if (!std::getline(in_, line)) return;
    const std::string where = "the " + name + " section";
    std::istringstream words(line);
    std::string first, second;
    words >> first >> second;
    std::uint64_t n_blocks = 0, total = 0;
    if (header_words == 0) {  // MSH 1 and 2: the total
      if (count_of(first, where, what, total)) fits(where, total, what);
      return;
    }
    if (!count_of(first, where, "blocks", n_blocks) || !count_of(second, where, what, total))
      return;
    if (!fits(where, n_blocks, "blocks") || !fits(where, total, what)) return;
    std::uint64_t sum = 0;
    for (std::uint64_t b = 0; b < n_blocks; ++b) {
      std::string head[4];
      for (std::string& w : head) in_ >> w;
      std::uint64_t n = 0;
      const std::string block = "block " + std::to_string(b + 1) + " of " + where;
      if (!in_ || !count_of(head[3], block, what, n)) return;  // gmsh answers a malformed block
      if (!fits(block, n, what)) return;
      sum += n;
      if (!(this->*skip)(head, n)) return;
    }
    if (sum != total)
      problem_ = where + " declares " + std::to_string(total) + " " + what + ", but its " +
                 std::to_string(n_blocks) + " blocks hold " + std::to_string(sum) +
                 "; the count must be the sum of the blocks' counts";
  }

  // A node block: n tags and n coordinate triples (with the entity's
  // dimension in parametric coordinates more), read as gmsh reads them, by
  // token.
  bool skip_node_block(const std::string (&head)[4], std::uint64_t n) {
    // MSH 4.1: dim tag parametric n; MSH 4.0: tag dim parametric n.
    const std::string& dim = version_ >= 4.1 ? head[0] : head[1];
    const int extra = head[2] != "0" ? std::atoi(dim.c_str()) : 0;
    const std::uint64_t per_node = 4 + std::uint64_t(std::max(0, std::min(extra, 3)));
    std::string token;
    for (std::uint64_t k = 0; k < n * per_node; ++k)
      if (!(in_ >> token)) return false;
    return true;
  }

  // An element block: one line per element, as gmsh reads them.
  bool skip_element_block(const std::string (&)[4], std::uint64_t n) {
    std::string line;
    std::getline(in_, line);  // the rest of the block's header line
    for (std::uint64_t k = 0; k < n; ++k)
      if (!std::getline(in_, line)) return false;
    return true;
  }

  // MSH 4: the numbers of points, curves, surfaces and volumes.
  void entities() {
    std::string line;
    if (!std::getline(in_, line)) return;
    std::istringstream words(line);
    static const char* const kinds[4] = {"points", "curves", "surfaces", "volumes"};
    for (const char* kind : kinds) {
      std::string token;
      std::uint64_t n = 0;
      const std::string what = std::string("entity ") + kind;
      if (!(words >> token) || !count_of(token, "the $Entities section", what, n)) return;
      if (!fits("the $Entities section", n, what)) return;
    }
  }

  std::ifstream in_;
  std::uint64_t size_ = 0;
  double version_ = 0;
  std::optional<std::string> problem_;
};

}  // namespace

std::optional<std::string> count_beyond_file(const std::string& path) {
  if (auto text = CountScan(path).first_problem()) return text;
  return binary_count_beyond_file(path);
}

}  // namespace rockfdem::mesh::detail
