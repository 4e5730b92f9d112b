// The checkpoint's byte format, private to fdem/; it knows nothing of the
// engine (engine_checkpoint.cpp lists the members).
//
//   offset  bytes  field
//        0      8  magic "RFDEMCKP"
//        8      4  byte-order mark 0x01020304 (native order; a file from a
//                  machine of the other order is refused, not converted)
//       12      4  engine format version (kCheckpointVersion)
//       16      8  total length in bytes, checksum included
//       24      8  model fingerprint (Engine::model_fingerprint())
//       32      .  payload: sections, each a 4-byte tag and its members
//     L - 8     8  FNV-1a 64 of bytes [0, L - 8)
//
// Members are written by io(): arithmetic values, enums and padding-free
// records as their raw bytes; vectors as a 64-bit count and their elements;
// other records member by member through their fields() overload. Every
// archive (writer, reader, fingerprint) walks the same member lists, with
// three channels: state() is saved, model() goes into the fingerprint only,
// skip() into neither.
#pragma once

#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace rockfdem::fdem::detail {

/// Bump when a saved member is added, removed or reordered: older files are
/// then refused with a clear message instead of being misread.
constexpr std::uint32_t kCheckpointVersion = 23;  // 2: energy ledger; 3: contact updates;
                                                  // 4: mass scaling; 5: strength factors,
                                                  // kinetic damping; 6: joint friction;
                                                  // 7: compact engine arrays; 8: joint
                                                  // friction per joint element; 9: dead
                                                  // loads of the loaded nodes only; 10:
                                                  // contact topology from the slots;
                                                  // 11: boundary records' nodes listed;
                                                  // 12: no edge list in contact;
                                                  // 13: no component labels;
                                                  // 14: crack triangles from the slots;
                                                  // 15: node-loop sums hold the
                                                  // kinetic energy; 16: the last
                                                  // viscous stress in single precision;
                                                  // 17: no old pair lists in contact;
                                                  // 18: detection positions as shifts;
                                                  // 19: gather rows per pair entry;
                                                  // 20: broken counts by mode;
                                                  // 21: gather rows rebuilt on load;
                                                  // 22: model constants and damage
                                                  // in single precision; 23:
                                                  // appended pairs, the gather
                                                  // rebuilt on load
constexpr std::size_t kCheckpointHeaderBytes = 32;
constexpr std::size_t kCheckpointChecksumBytes = 8;

/// FNV-1a 64, fed incrementally.
class Fnv1a {
 public:
  void add(const void* data, std::size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    std::uint64_t h = h_;  // a local: the bytes may alias h_, which would pin it to memory
    for (std::size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 1099511628211ull;
    h_ = h;
  }
  std::uint64_t value() const { return h_; }

 private:
  std::uint64_t h_ = 1469598103934665603ull;
};

/// Types written as their bytes: no padding, so the bytes are the value
/// (has_unique_object_representations excludes floating point, hence the
/// arithmetic test).
template <class T>
constexpr bool kRawBytes =
    std::is_arithmetic_v<T> || std::is_enum_v<T> || std::has_unique_object_representations_v<T>;

// --- Member count of a record -----------------------------------------------
// The largest N for which T{x_1, ..., x_N} compiles, with x convertible to
// anything: the number of members (a C array counts once per element; the
// records must stay aggregates). The member lists assert it, so a member
// added to an engine record fails the build until it is listed as state,
// model or skip.

struct AnyMember {
  template <class T>
  operator T() const;  // declared only: used in unevaluated contexts
};

template <class T, class Seq, class = void>
struct BraceAccepts : std::false_type {};
template <class T, std::size_t... I>
struct BraceAccepts<T, std::index_sequence<I...>,
                    std::void_t<decltype(T{(void(I), AnyMember{})...})>> : std::true_type {};

template <class T, std::size_t N = 0>
constexpr std::size_t member_count() {
  if constexpr (BraceAccepts<T, std::make_index_sequence<N + 1>>::value) {
    return member_count<T, N + 1>();
  } else {
    return N;
  }
}

// --- io: one member through an archive --------------------------------------------

template <class Ar, class T>
void io(Ar& ar, T& x);
template <class Ar, class T, std::size_t N>
void io(Ar& ar, T (&x)[N]);
template <class Ar, class T>
void io(Ar& ar, std::vector<T>& v);

/// Every member of a record through io(), in declaration order: for records
/// whose members are all saved or all fingerprinted. The list must name
/// each member (checked against member_count).
template <class Ar, class Record, class... M>
void each_member(Ar& ar, const Record&, M&... m) {
  static_assert(sizeof...(M) == member_count<Record>(),
                "a record's member list misses a member: add it in engine_checkpoint.cpp");
  (io(ar, m), ...);
}

// --- Archives -----------------------------------------------------------------------

/// The channels of the member lists: the writer and the reader take state(),
/// the fingerprint takes model(), nobody takes skip().
template <class Archive, bool kState>
class Channels {
 public:
  template <class T>
  void state([[maybe_unused]] T& x) {
    if constexpr (kState) io(self(), x);
  }
  template <class T>
  void model([[maybe_unused]] T& x) {
    if constexpr (!kState) io(self(), x);
  }
  template <class T>
  void skip(T&) {}

 private:
  Archive& self() { return static_cast<Archive&>(*this); }
};

/// Counts the bytes of the state members: the header's length field, so
/// that the writer can stream the payload without holding it.
class CheckpointSizer : public Channels<CheckpointSizer, true> {
 public:
  static constexpr bool kReading = false, kChecking = false;
  void raw(const void*, std::size_t n) { bytes_ += n; }
  void count(std::uint64_t& n, std::size_t) { raw(&n, sizeof n); }
  void tag(const char (&)[5]) { bytes_ += 4; }
  std::uint64_t bytes() const { return bytes_; }

 private:
  std::uint64_t bytes_ = 0;
};

/// Writes header, state members and checksum straight to a stream (a copy
/// of the payload would be as large as the engine's state).
class CheckpointWriter : public Channels<CheckpointWriter, true> {
 public:
  static constexpr bool kReading = false, kChecking = false;
  /// Writes the header; `payload_bytes` from a CheckpointSizer.
  CheckpointWriter(std::ostream& out, std::uint64_t fingerprint, std::uint64_t payload_bytes);
  void raw(const void* p, std::size_t n);
  void count(std::uint64_t& n, std::size_t) { raw(&n, sizeof n); }
  void tag(const char (&t)[5]) { raw(t, 4); }
  /// Writes the checksum; throws InputError if the stream failed.
  void finish();

 private:
  std::ostream& out_;
  Fnv1a sum_;
};

/// Where a reader stands in a file checked by read_checkpoint; throws
/// InputError naming the byte where something does not fit.
class ReadCursor {
 public:
  ReadCursor(const std::string& file, std::size_t begin, std::size_t end)
      : file_(file), pos_(begin), end_(end) {}
  /// Copies the next n bytes to p (nowhere when p is null).
  void raw(void* p, std::size_t n);
  /// Reads a vector length; refuses one that cannot fit in what is left.
  void count(std::uint64_t& n, std::size_t min_element_bytes);
  void tag(const char (&t)[5]);
  /// Throws unless the payload was read to its end.
  void finish() const;

 private:
  const std::string& file_;
  std::size_t pos_, end_;
};

/// Reads the state members back into the engine's own arrays.
class CheckpointReader : public Channels<CheckpointReader, true>, public ReadCursor {
 public:
  static constexpr bool kReading = true, kChecking = false;
  using ReadCursor::ReadCursor;
};

/// Walks the state members through the file without storing anything: run
/// before the reader, it finds every fault the reader could meet, so that
/// the reader can write into the engine in place and never stop halfway.
class CheckpointChecker : public Channels<CheckpointChecker, true>, public ReadCursor {
 public:
  static constexpr bool kReading = false, kChecking = true;
  using ReadCursor::ReadCursor;
  void raw(const void*, std::size_t n) { ReadCursor::raw(nullptr, n); }
};

/// Hashes the model members (the fingerprint).
class ModelHasher : public Channels<ModelHasher, false> {
 public:
  static constexpr bool kReading = false, kChecking = false;
  void raw(const void* p, std::size_t n) { fnv_.add(p, n); }
  void count(std::uint64_t& n, std::size_t) { raw(&n, sizeof n); }
  void tag(const char (&)[5]) {}
  std::uint64_t value() const { return fnv_.value(); }

 private:
  Fnv1a fnv_;
};

template <class Ar, class T>
void io(Ar& ar, T& x) {
  if constexpr (kRawBytes<T>) {
    ar.raw(&x, sizeof x);
  } else {
    fields(ar, x);  // a record: its member list (found by argument-dependent lookup)
  }
}

template <class Ar, class T, std::size_t N>
void io(Ar& ar, T (&x)[N]) {
  for (T& e : x) io(ar, e);
}

template <class Ar, class T>
void io(Ar& ar, std::vector<T>& v) {
  std::uint64_t n = v.size();
  ar.count(n, kRawBytes<T> ? sizeof(T) : 1);
  if constexpr (Ar::kChecking) {  // the elements' bytes, v left alone
    if constexpr (kRawBytes<T>) {
      ar.raw(nullptr, n * sizeof(T));  // count() bounded n by the bytes left
    } else {
      for (std::uint64_t i = 0; i < n; ++i) {
        T e{};
        io(ar, e);
      }
    }
    return;
  }
  if constexpr (Ar::kReading) v.resize(n);
  if constexpr (kRawBytes<T>) {
    if (n > 0) ar.raw(v.data(), n * sizeof(T));
  } else {
    for (T& e : v) io(ar, e);
  }
}

// --- Framing ------------------------------------------------------------------------

/// Reads one checkpoint (exactly its bytes) from `in` and checks magic, byte
/// order, version, length and checksum, in that order, throwing InputError
/// with the first that fails. Returns the whole file; its fingerprint is at
/// offset 24 (checkpoint_fingerprint).
std::string read_checkpoint(std::istream& in);
std::uint64_t checkpoint_fingerprint(const std::string& file);

/// 16 hex digits.
std::string hex64(std::uint64_t v);

}  // namespace rockfdem::fdem::detail
