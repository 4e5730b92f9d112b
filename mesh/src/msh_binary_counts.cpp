// The counts of a binary .msh checked against the file's size before gmsh
// reads it: gmsh 4.8 allocates by a declared count first, so a header
// claiming 999,999,999,999 nodes ends in std::bad_alloc (or, for a count
// that fits in virtual memory, in the kernel's OOM killer). MSH 2 binary
// gives its totals as text lines; MSH 4.1 gives totals and block counts as
// 8-byte integers, which the walk reads and skips block by block.
#include <cstdint>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "msh_header.hpp"

namespace rockfdem::mesh::detail {
namespace {

// Smallest records: an MSH 2 node is an int tag and three doubles, an MSH 2
// element at least a number and one node (ints); an MSH 4.1 node an 8-byte
// tag and three doubles, an element an 8-byte tag and one node, a block
// header three ints and a count.
constexpr std::uint64_t kNode2 = 4 + 24, kElement2 = 8, kNode4 = 8 + 24, kElement4 = 16,
                        kBlock4 = 12 + 8;

// Nodes per element of the MSH element types a 2D mesh holds; 0: unknown
// (the walk stops and leaves the file to gmsh's own checks).
std::uint64_t nodes_of_type(int type) {
  switch (type) {
    case 15:
      return 1;  // point
    case 1:
      return 2;  // line
    case 2:
    case 8:
      return 3;  // triangle, 3-node line
    case 3:
    case 4:
      return 4;  // quadrangle, tetrahedron
    case 9:
      return 6;  // 6-node triangle
    case 10:
    case 16:
      return 9;  // 9-node quadrangle (16: 8-node)
    default:
      return 0;
  }
}

class BinaryScan {
 public:
  explicit BinaryScan(const std::string& path) : in_(path, std::ios::binary) {
    in_.seekg(0, std::ios::end);
    size_ = in_ ? std::uint64_t(in_.tellg()) : 0;
    in_.seekg(0);
  }

  std::optional<std::string> first_problem() {
    if (!binary_header()) return std::nullopt;
    std::string line;
    while (!problem_ && !stopped_ && std::getline(in_, line)) {
      while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
      if (line == "$Nodes")
        version_ >= 4 ? blocks("$Nodes", "nodes", kNode4) : text_total("$Nodes", "nodes", kNode2);
      else if (line == "$Elements")
        version_ >= 4 ? blocks("$Elements", "elements", kElement4)
                      : text_total("$Elements", "elements", kElement2);
    }
    return problem_;
  }

 private:
  // "$MeshFormat", "VERSION 1 8" and the binary int 1 in this machine's
  // byte order; false for anything else.
  bool binary_header() {
    std::string line;
    if (!std::getline(in_, line) || line.rfind("$MeshFormat", 0) != 0) return false;
    if (!std::getline(in_, line)) return false;
    int file_type = 0, data_size = 0;
    std::istringstream(line) >> version_ >> file_type >> data_size;
    int one = 0;
    return file_type == 1 && data_size == 8 && get(one) && one == 1;
  }

  template <class T>
  bool get(T& v) {
    in_.read(reinterpret_cast<char*>(&v), sizeof v);
    return bool(in_);
  }

  std::uint64_t left() {
    const auto at = in_.tellg();
    return at < 0 ? 0 : size_ - std::uint64_t(at);
  }

  bool fits(const std::string& where, std::uint64_t n, const std::string& what,
            std::uint64_t per_item) {
    problem_ = count_beyond(where, n, what, left(), per_item);
    return !problem_;
  }

  // MSH 2: the section's total on a text line; gmsh answers a bad one.
  void text_total(const std::string& name, const std::string& what, std::uint64_t per_item) {
    std::string line;
    std::uint64_t n = 0;
    if (std::getline(in_, line) && std::istringstream(line) >> n)
      fits("the " + name + " section", n, what, per_item);
  }

  // MSH 4.1: blocks, total, min and max tag; then each block's header
  // (dimension, entity, parametric flag or element type, count) and records.
  void blocks(const std::string& name, const std::string& what, std::uint64_t per_item) {
    const std::string where = "the " + name + " section";
    std::uint64_t n_blocks = 0, total = 0, min_tag = 0, max_tag = 0, sum = 0;
    if (!get(n_blocks) || !get(total) || !get(min_tag) || !get(max_tag)) return stop();
    if (!fits(where, n_blocks, "blocks", kBlock4) || !fits(where, total, what, per_item)) return;
    for (std::uint64_t b = 0; b < n_blocks && !problem_; ++b) {
      int dim = 0, entity = 0, kind = 0;
      std::uint64_t n = 0;
      if (!get(dim) || !get(entity) || !get(kind) || !get(n)) return stop();
      const std::uint64_t record = record_bytes(per_item == kNode4, dim, kind);
      if (record == 0) return stop();
      if (!fits("block " + std::to_string(b + 1) + " of " + where, n, what, record)) return;
      in_.seekg(std::streamoff(n * record), std::ios::cur);
      sum += n;
    }
    if (!problem_ && sum != total)
      problem_ = where + " declares " + std::to_string(total) + " " + what + ", but its " +
                 std::to_string(n_blocks) + " blocks hold " + std::to_string(sum) +
                 "; the count must be the sum of the blocks' counts";
  }

  // Bytes of one record: a node's tag, coordinates and (parametric) its
  // entity's dimension in parameters; an element's tag and nodes. 0: unknown.
  static std::uint64_t record_bytes(bool nodes, int dim, int kind) {
    if (nodes) return kNode4 + (kind != 0 && dim > 0 && dim <= 3 ? 8 * std::uint64_t(dim) : 0);
    const std::uint64_t k = nodes_of_type(kind);
    return k == 0 ? 0 : 8 * (1 + k);
  }

  void stop() { stopped_ = true; }

  std::ifstream in_;
  std::uint64_t size_ = 0;
  double version_ = 0;
  bool stopped_ = false;
  std::optional<std::string> problem_;
};

}  // namespace

std::optional<std::string> binary_count_beyond_file(const std::string& path) {
  return BinaryScan(path).first_problem();
}

}  // namespace rockfdem::mesh::detail
