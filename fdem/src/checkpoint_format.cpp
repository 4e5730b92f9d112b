// Checkpoint framing: header, checksum and the checks on reading (see
// checkpoint_format.hpp for the layout).
#include "checkpoint_format.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <istream>
#include <ostream>

#include "rockfdem/error.hpp"

namespace rockfdem::fdem::detail {
namespace {

constexpr char kMagic[8] = {'R', 'F', 'D', 'E', 'M', 'C', 'K', 'P'};
constexpr std::uint32_t kByteOrderMark = 0x01020304u;

template <class T>
T read_at(const std::string& file, std::size_t offset) {
  T v;
  std::memcpy(&v, file.data() + offset, sizeof v);
  return v;
}

[[noreturn]] void truncated(std::size_t at, const std::string& expected) {
  throw InputError("fdem: checkpoint is truncated at byte " + std::to_string(at) + expected +
                   "; write it again (a save interrupted, or a partial copy?)");
}

[[noreturn]] void corrupt(const std::string& what) {
  throw InputError("fdem: checkpoint is corrupt: " + what +
                   "; the file was damaged or modified, use another checkpoint");
}

/// Appends up to `n` bytes of `in` to `file`, in chunks so that a corrupt
/// length does not allocate it all at once; returns false when it ran out.
bool append(std::istream& in, std::size_t n, std::string& file) {
  constexpr std::size_t kChunk = std::size_t(1) << 20;
  while (n > 0) {
    const std::size_t want = std::min(n, kChunk), old = file.size();
    file.resize(old + want);
    in.read(&file[old], static_cast<std::streamsize>(want));
    const auto got = static_cast<std::size_t>(in.gcount());
    file.resize(old + got);
    if (got < want) return false;
    n -= got;
  }
  return true;
}

}  // namespace

void ReadCursor::raw(void* p, std::size_t n) {
  if (n > end_ - pos_) truncated(end_, " (a member needs " + std::to_string(n) + " bytes there)");
  if (p != nullptr) std::memcpy(p, file_.data() + pos_, n);
  pos_ += n;
}

void ReadCursor::count(std::uint64_t& n, std::size_t min_element_bytes) {
  const std::size_t at = pos_;
  raw(&n, sizeof n);
  if (n > (end_ - pos_) / min_element_bytes)
    corrupt("a length of " + std::to_string(n) + " at byte " + std::to_string(at) +
            " exceeds the rest of the file");
}

void ReadCursor::tag(const char (&t)[5]) {
  const std::size_t at = pos_;
  char got[4];
  raw(got, 4);
  if (std::memcmp(got, t, 4) != 0)
    corrupt("section '" + std::string(t) + "' expected at byte " + std::to_string(at) +
            ", found '" + std::string(got, 4) + "'");
}

void ReadCursor::finish() const {
  if (pos_ != end_)
    corrupt(std::to_string(end_ - pos_) + " unread bytes after the last section at byte " +
            std::to_string(pos_));
}

CheckpointWriter::CheckpointWriter(std::ostream& out, std::uint64_t fingerprint,
                                   std::uint64_t payload_bytes)
    : out_(out) {
  const std::uint64_t total = kCheckpointHeaderBytes + payload_bytes + kCheckpointChecksumBytes;
  raw(kMagic, sizeof kMagic);
  raw(&kByteOrderMark, sizeof kByteOrderMark);
  raw(&kCheckpointVersion, sizeof kCheckpointVersion);
  raw(&total, sizeof total);
  raw(&fingerprint, sizeof fingerprint);
}

void CheckpointWriter::raw(const void* p, std::size_t n) {
  sum_.add(p, n);
  out_.write(static_cast<const char*>(p), static_cast<std::streamsize>(n));
}

void CheckpointWriter::finish() {
  const std::uint64_t checksum = sum_.value();
  out_.write(reinterpret_cast<const char*>(&checksum), sizeof checksum);
  if (!out_) throw InputError("fdem: writing the checkpoint failed (disk full or stream closed?)");
}

std::string read_checkpoint(std::istream& in) {
  std::string file;
  const std::string header_size =
      " (the header has " + std::to_string(kCheckpointHeaderBytes) + " bytes)";
  // Magic: a short file that starts like one is truncated, anything else is
  // not a checkpoint.
  const bool whole_magic = append(in, sizeof kMagic, file);
  if (file.compare(0, file.size(), kMagic, file.size()) != 0)
    throw InputError(
        "fdem: not a rockfdem engine checkpoint (its first bytes are not \"RFDEMCKP\")");
  if (!whole_magic) truncated(file.size(), header_size);
  if (!append(in, kCheckpointHeaderBytes - sizeof kMagic, file))
    truncated(file.size(), header_size);
  if (read_at<std::uint32_t>(file, 8) != kByteOrderMark)
    throw InputError(
        "fdem: checkpoint was written on a machine of the other byte order; this "
        "build reads its native order only, restart there");
  const auto version = read_at<std::uint32_t>(file, 12);
  if (version != kCheckpointVersion)
    throw InputError("fdem: checkpoint was written by engine format version " +
                     std::to_string(version) + "; this build reads " +
                     std::to_string(kCheckpointVersion) + ". Restart with the build that wrote it");
  const auto total = read_at<std::uint64_t>(file, 16);
  if (total < kCheckpointHeaderBytes + kCheckpointChecksumBytes)
    corrupt("its length field says " + std::to_string(total) + " bytes");
  if (!append(in, total - kCheckpointHeaderBytes, file))
    truncated(file.size(), " (expected " + std::to_string(total) + " bytes)");
  Fnv1a sum;
  sum.add(file.data(), total - kCheckpointChecksumBytes);
  if (sum.value() != read_at<std::uint64_t>(file, total - kCheckpointChecksumBytes))
    corrupt("its checksum does not match its contents");
  return file;
}

std::uint64_t checkpoint_fingerprint(const std::string& file) {
  return read_at<std::uint64_t>(file, 24);
}

std::string hex64(std::uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

}  // namespace rockfdem::fdem::detail
