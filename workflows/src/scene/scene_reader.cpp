#include "scene/scene_reader.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "rockfdem/error.hpp"
#include "rockfdem/workflows/scene_schema.hpp"

namespace rockfdem::workflows::detail {
namespace {

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) out += (i ? ", " : "") + items[i];
  return out;
}

[[noreturn]] void fail(const std::string& message) { throw InputError(printable(message)); }

}  // namespace

namespace {

// Scene text past these bounds is refused before toml++ sees it: its
// parser recurses per nesting level and per dotted part (a 200 KB header
// [a.a.a...] of 50,000 parts overflows the stack), and a scene needs far
// less: its deepest key has 3 parts, its deepest value (a bolt fan's
// points) nests 2 brackets.
constexpr std::size_t kMaxSceneBytes = std::size_t(1) << 20;
constexpr std::size_t kMaxNesting = 32;
constexpr std::size_t kMaxKeyParts = 16;
constexpr std::size_t kMaxKeyLength = 256;

// A light TOML lexer: just enough to tell keys from values and strings and
// comments from brackets, braces and dots. What it cannot place is left to
// toml++, which answers it with its own message.
class SceneBounds {
 public:
  SceneBounds(const std::string& text, const std::string& source) : t_(text), source_(source) {}

  void check() {
    if (t_.size() > kMaxSceneBytes)
      fail(source_ + ": the scene holds " + std::to_string(t_.size()) +
           " bytes; allowed: at most " + std::to_string(kMaxSceneBytes) +
           " bytes (1 MiB) of scene text");
    while (i_ < t_.size()) step();
  }

 private:
  [[noreturn]] void exceed(const std::string& what) const {
    fail(source_ + ":" + std::to_string(line_) + ": " + what);
  }

  void step() {
    const char c = t_[i_];
    if (c == '#') {  // a comment runs to the end of the line
      while (i_ < t_.size() && t_[i_] != '\n') ++i_;
      return;
    }
    if (c == '\n') {
      ++line_;
      ++i_;
      if (open_.empty()) start_key();  // each top-level line starts a key or header
      return;
    }
    if (in_key_) return key_char(c);
    value_char(c);
  }

  void start_key() {
    in_key_ = true;
    header_ = false;
    parts_ = 0;
    in_segment_ = false;
  }

  void key_char(char c) {
    const bool bare = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
                      c == '_' || c == '-';
    if (bare) {
      if (!in_segment_) begin_segment();
      if (++segment_length_ > kMaxKeyLength) long_key(i_ + 1 - segment_length_);
      ++i_;
      return;
    }
    in_segment_ = false;
    if (c == '"' || c == '\'') {
      begin_segment();
      const std::size_t start = i_;
      skip_string();
      if (i_ - start > kMaxKeyLength + 2) long_key(start);
      return;
    }
    ++i_;
    if (c == '[' && open_.empty() && parts_ == 0 && !header_) {
      header_ = true;  // [table] or [[array of tables]]: a key follows
    } else if (c == ']' && header_) {
      in_key_ = false;  // the header is closed; only a comment may follow
      header_ = false;
    } else if (c == '=') {
      in_key_ = false;
    } else if (c == '}' && !open_.empty() && open_.back() == '{') {
      open_.pop_back();  // an empty inline table, {}
      in_key_ = false;
    }
  }

  void begin_segment() {
    in_segment_ = true;
    segment_length_ = 0;
    if (++parts_ > kMaxKeyParts)
      exceed("a key or table header of more than " + std::to_string(kMaxKeyParts) +
             " dotted parts; allowed: at most " + std::to_string(kMaxKeyParts) +
             " parts (a scene's deepest key, materials.rock.young, has 3)");
  }

  [[noreturn]] void long_key(std::size_t start) const {
    exceed("key '" + t_.substr(start, 40) + "...' is longer than " + std::to_string(kMaxKeyLength) +
           " characters; allowed: keys of at most " + std::to_string(kMaxKeyLength) +
           " characters");
  }

  void value_char(char c) {
    if (c == '"' || c == '\'') return skip_string();
    ++i_;
    if (c == '[' || c == '{') {
      open_.push_back(c);
      if (open_.size() > kMaxNesting)
        exceed("brackets and braces nest more than " + std::to_string(kMaxNesting) +
               " levels deep; allowed: at most " + std::to_string(kMaxNesting) +
               " levels (a scene's values nest at most 2)");
      if (c == '{') start_key();
    } else if ((c == ']' || c == '}') && !open_.empty()) {
      open_.pop_back();
    } else if (c == ',' && !open_.empty() && open_.back() == '{') {
      start_key();  // the next key of an inline table
    }
  }

  // Skips a basic ("..."), literal ('...') or multi-line ("""...""",
  // '\'\'...\'\'\') string starting at i_, counting its lines.
  void skip_string() {
    const char q = t_[i_];
    const bool multi = t_.compare(i_, 3, std::string(3, q)) == 0;
    i_ += multi ? 3 : 1;
    while (i_ < t_.size()) {
      const char c = t_[i_];
      if (c == '\\' && q == '"') {
        if (i_ + 1 < t_.size() && t_[i_ + 1] == '\n') ++line_;
        i_ += 2;
        continue;
      }
      if (c == '\n') {
        ++line_;
        if (!multi) return;  // an unterminated string: toml++ says so
      }
      if (c == q && (!multi || t_.compare(i_, 3, std::string(3, q)) == 0)) {
        i_ += multi ? 3 : 1;
        return;
      }
      ++i_;
    }
  }

  const std::string& t_;
  const std::string& source_;
  std::size_t i_ = 0, line_ = 1;
  std::vector<char> open_;  // '[' arrays and '{' inline tables around i_
  bool in_key_ = true, header_ = false, in_segment_ = false;
  std::size_t parts_ = 0, segment_length_ = 0;
};

}  // namespace

void check_scene_bounds(const std::string& text, const std::string& source) {
  SceneBounds(text, source).check();
}

// "stages[2].kind" -> "stages[].kind": array-of-table indices do not matter to the schema.
std::string normalise(const std::string& path) {
  std::string out;
  for (std::size_t i = 0; i < path.size(); ++i) {
    out += path[i];
    if (path[i] == '[') {
      while (i + 1 < path.size() && path[i + 1] != ']') ++i;
    }
  }
  return out;
}

namespace {

// Parse the right-hand side of --set as a TOML value; bare words become strings
// so `--set tunnel.shape=circular` needs no shell quoting.
toml::table parse_override_value(const std::string& key, const std::string& value) {
  try {
    return toml::parse("v = " + value);
  } catch (const toml::parse_error&) {
    toml::table t;
    t.insert("v", value);
    (void)key;
    return t;
  }
}

// "3]" -> 3: the digits of an array index and its closing bracket, nothing
// else; anything else (or a number past any array's size) is no index.
std::size_t table_index(const std::string& rest) {
  constexpr std::size_t kNoIndex = std::size_t(-1);
  if (rest.size() < 2 || rest.size() > 10 || rest.back() != ']') return kNoIndex;
  std::size_t index = 0;
  for (std::size_t i = 0; i + 1 < rest.size(); ++i) {
    if (rest[i] < '0' || rest[i] > '9') return kNoIndex;
    index = index * 10 + std::size_t(rest[i] - '0');
  }
  return index;
}

// One step down a --set path: "name" is a table (made if missing),
// "name[i]" the i-th table of an existing array of tables.
toml::table* descend(const std::string& text, toml::table& table, const std::string& part) {
  const auto bracket = part.find('[');
  if (bracket == std::string::npos) {
    auto [it, inserted] = table.insert(part, toml::table{});
    (void)inserted;
    if (toml::table* t = it->second.as_table()) return t;
    fail("--set " + text + ": '" + part + "' is not a table");
  }
  const std::string name = part.substr(0, bracket);
  toml::array* list = table[name].as_array();
  const std::size_t n = list ? list->size() : 0;
  const std::size_t index = table_index(part.substr(bracket + 1));
  if (index >= n || !(*list)[index].is_table())
    fail("--set " + text + ": '" + part + "' is not one of the scene's " + std::to_string(n) +
         " entries of [[" + name + "]]; allowed: " +
         (n ? name + "[0] to " + name + "[" + std::to_string(n - 1) + "]"
            : "none (the scene has no [[" + name + "]] to change)"));
  return (*list)[index].as_table();
}

void apply_override(RawScene& scene, const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) fail("--set " + text + ": expected section.key=value");
  const std::string path = text.substr(0, eq);
  const std::string value = text.substr(eq + 1);
  // TOML would read a line break as the end of the value and the rest as
  // further keys, dropped without a word: one --set gives one value.
  if (value.find_first_of("\n\r") != std::string::npos)
    fail(scene.source + ": --set " + text + ": the value holds a line break; allowed: a " +
         "value on one line (one --set per key)");
  if (!find_key(normalise(path)))
    fail("--set " + text + ": unknown key '" + path +
         "'; see docs/scene-reference.md for the keys");
  check_scene_bounds("v = " + value, "--set " + text);
  toml::table parsed = parse_override_value(path, value);
  toml::table* table = &scene.root;
  std::size_t start = 0;
  for (auto dot = path.find('.'); dot != std::string::npos; dot = path.find('.', start)) {
    const std::string part = path.substr(start, dot - start);
    table = descend(text, *table, part);
    start = dot + 1;
  }
  table->insert_or_assign(path.substr(start), std::move(*parsed.get("v")));
  scene.override_text[path] = text;
}

bool is_finite_number(const toml::node& n) {
  if (n.is_integer()) return true;
  return n.is_floating_point() && std::isfinite(n.as_floating_point()->get());
}

double as_double(const toml::node& n) {
  return n.is_integer() ? double(n.as_integer()->get()) : n.as_floating_point()->get();
}

bool in_range(const KeySpec& k, double v) {
  if (k.min_open ? !(v > k.min) : !(v >= k.min)) return false;
  if (k.max_open ? !(v < k.max) : !(v <= k.max)) return false;
  return true;
}

std::string choice_list(const KeySpec& k) {
  std::string out = "one of ";
  for (std::size_t i = 0; i < k.choices.size(); ++i)
    out += (i ? ", \"" : "\"") + k.choices[i] + '"';
  return out;
}

bool is_choice(const KeySpec& k, const toml::node& n) {
  if (!n.is_string()) return false;
  for (const std::string& c : k.choices)
    if (c == n.as_string()->get()) return true;
  return false;
}

void check_value(const RawScene& s, const KeySpec& k, const std::string& path,
                 const toml::node& n) {
  switch (k.type) {
    case KeyType::kBool:
      if (!n.is_boolean()) fail_key(s, path, &n, "wrong type");
      return;
    case KeyType::kString:
      if (!n.is_string()) fail_key(s, path, &n, "wrong type");
      return;
    case KeyType::kChoice:
      if (!is_choice(k, n)) fail_key(s, path, &n, "not one of the choices");
      return;
    case KeyType::kStringMap:
      if (!n.is_table()) fail_key(s, path, &n, "wrong type");
      for (auto&& [name, v] : *n.as_table())
        if (!is_choice(k, v))
          fail_key(s, path + "." + std::string(name.str()), &v,
                   "not one of the choices; allowed: " + choice_list(k));
      return;
    case KeyType::kStringArray:
      if (!n.is_array()) fail_key(s, path, &n, "wrong type");
      for (auto&& v : *n.as_array())
        if (!v.is_string() || v.as_string()->get().empty())
          fail_key(s, path, &n, "element " + node_text(v) + " is not a non-empty string");
      return;
    case KeyType::kNumberArray:
      if (!n.is_array() || n.as_array()->empty()) fail_key(s, path, &n, "wrong type");
      for (auto&& v : *n.as_array())
        if (!is_finite_number(v) || !in_range(k, as_double(v)))
          fail_key(s, path, &n, "element " + node_text(v) + " out of range");
      return;
    case KeyType::kInteger:
      if (!n.is_integer()) fail_key(s, path, &n, "wrong type");
      if (!in_range(k, as_double(n))) fail_key(s, path, &n, "out of range");
      return;
    case KeyType::kNumber:
      if (!n.is_number()) fail_key(s, path, &n, "wrong type");
      if (!is_finite_number(n) || !in_range(k, as_double(n))) fail_key(s, path, &n, "out of range");
      return;
  }
}

void check_table(const RawScene& s, const toml::table& table, const std::string& prefix);

void check_node(const RawScene& s, const std::string& path, const toml::node& n) {
  const std::string norm = normalise(path);
  if (const KeySpec* k = find_key(norm)) return check_value(s, *k, path, n);
  if (n.is_table() && is_known_section(norm)) return check_table(s, *n.as_table(), path);
  if (n.is_array_of_tables() && is_known_section(norm + "[]")) {
    std::size_t i = 0;
    for (auto&& item : *n.as_array())
      check_table(s, *item.as_table(), path + "[" + std::to_string(i++) + "]");
    return;
  }
  const auto dot = norm.rfind('.');
  const std::string section = dot == std::string::npos ? "" : norm.substr(0, dot);
  std::vector<std::string> allowed = keys_in_section(section);
  if (section.empty()) {
    for (const KeySpec& k : scene_schema()) {
      const std::string top = k.path.substr(0, k.path.find_first_of(".["));
      if (allowed.empty() || allowed.back() != top) allowed.push_back(top);
    }
  }
  fail_key(s, path, &n, "unknown key; allowed here: " + join(allowed));
}

void check_table(const RawScene& s, const toml::table& table, const std::string& prefix) {
  for (auto&& [key, node] : table) {
    const std::string path =
        prefix.empty() ? std::string(key.str()) : prefix + "." + std::string(key.str());
    check_node(s, path, node);
  }
}

}  // namespace

std::string number_text(double v) {
  // The shortest text that reads back as v, in plain notation where that
  // is as short (40, not 4e+01; 8.8, not 8.8000000000000007).
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

const std::pair<const std::string, std::string>* override_of(const RawScene& s,
                                                             const std::string& path) {
  for (const auto& set : s.override_text)
    if (path == set.first || path.rfind(set.first + ".", 0) == 0) return &set;
  return nullptr;
}

bool from_command_line(const RawScene& s, const std::string& path) {
  return override_of(s, path) != nullptr;
}

std::string node_text(const toml::node& node) {
  std::ostringstream out;
  node.visit([&](auto&& v) {
    if constexpr (toml::is_string<decltype(v)>)
      out << '"' << v.get() << '"';
    else if constexpr (toml::is_floating_point<decltype(v)>)
      out << number_text(v.get());
    else if constexpr (toml::is_table<decltype(v)>)
      out << "{...}";
    else if constexpr (toml::is_array<decltype(v)>)
      out << toml::toml_formatter{v, toml::format_flags::none};
    else
      out << v;
  });
  // One line, and short: the formatter breaks long arrays over lines.
  std::string text;
  for (const char c : out.str()) {
    const bool space = c == '\n' || c == '\r' || c == ' ' || c == '\t';
    if (!space || (!text.empty() && text.back() != ' ')) text += space ? ' ' : c;
  }
  constexpr std::size_t kShown = 120;
  if (text.size() > kShown) text = text.substr(0, kShown - 3) + "...";
  return text;
}

std::string key_message(const RawScene& s, const std::string& path, const toml::node* node,
                        const std::string& problem) {
  std::ostringstream msg;
  // A key set on the command line is blamed on its --set argument, which
  // already shows the value; the scene file has no line for it.
  const auto* set = override_of(s, path);
  if (set) msg << "--set " << set->second << ": ";
  if (!set || path != set->first) {
    if (!set) msg << s.source;
    if (!set && node && node->source().begin.line > 0) msg << ':' << node->source().begin.line;
    msg << (set ? "" : ": ") << "key '" << path << "'";
    if (node) msg << " = " << node_text(*node);
    msg << ": ";
  }
  msg << problem;
  return printable(msg.str());
}

void fail_key(const RawScene& s, const std::string& path, const toml::node* node,
              const std::string& problem) {
  std::string msg = key_message(s, path, node, problem);
  if (const KeySpec* k = find_key(normalise(path));
      k && problem.find("allowed") == std::string::npos)
    msg += printable("; allowed: " + describe_allowed(*k));
  throw InputError(msg);
}

RawScene read_raw_scene(const std::string& text, const std::string& source,
                        const std::vector<std::string>& overrides) {
  check_scene_bounds(text, source);
  RawScene scene;
  scene.source = source;
  try {
    scene.root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    std::ostringstream msg;
    msg << source << ':' << e.source().begin.line << ':' << e.source().begin.column
        << ": not valid TOML: " << e.description();
    throw InputError(printable(msg.str()));
  }
  for (const std::string& o : overrides) apply_override(scene, o);
  check_table(scene, scene.root, "");
  return scene;
}

}  // namespace rockfdem::workflows::detail
