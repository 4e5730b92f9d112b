// atomic_write_text / AtomicFile: complete files only, no temp files left.
#include "rockfdem/coupling/atomic_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <sstream>

#include "temp_dir.hpp"

namespace rockfdem::coupling {
namespace {

using testing::TempDir;

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(AtomicFile, write_text_creates_then_replaces_the_file) {
  const TempDir dir;
  const std::string path = dir.file("history.csv");
  atomic_write_text(path, "step,time\n");
  EXPECT_EQ(read_text(path), "step,time\n");
  const std::string big(1 << 20, 'x');  // more than one write() may take
  atomic_write_text(path, big);
  EXPECT_EQ(read_text(path), big);
  EXPECT_EQ(dir.entries(), (std::set<std::string>{"history.csv"}));
}

TEST(AtomicFile, new_file_gets_ordinary_permissions) {
  const TempDir dir;
  atomic_write_text(dir.file("summary.json"), "{}");
  struct stat st {};
  ASSERT_EQ(::stat(dir.file("summary.json").c_str(), &st), 0);
  const mode_t mask = ::umask(0);  // read the umask (the test is single-threaded)
  ::umask(mask);
  EXPECT_EQ(st.st_mode & 0777, 0666 & ~mask) << "mode " << std::oct << st.st_mode;
}

TEST(AtomicFile, missing_directory_throws_naming_the_path) {
  const TempDir dir;
  const std::string path = dir.file("nope/summary.json");
  try {
    atomic_write_text(path, "{}");
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(AtomicFile, uncommitted_temp_file_is_removed_and_target_untouched) {
  const TempDir dir;
  const std::string path = dir.file("mesh.png");
  atomic_write_text(path, "old");
  {
    AtomicFile file(path);
    EXPECT_EQ(file.temp_path().substr(file.temp_path().size() - 4), ".png");
    std::ofstream(file.temp_path()) << "half-written";
    EXPECT_EQ(dir.entries().size(), 2u);
    // leaves scope without commit(): as when a writer throws
  }
  EXPECT_EQ(dir.entries(), (std::set<std::string>{"mesh.png"}));
  EXPECT_EQ(read_text(path), "old");
}

TEST(AtomicFile, commit_moves_the_temp_file_onto_the_target) {
  const TempDir dir;
  const std::string path = dir.file("mesh.png");
  AtomicFile file(path);
  std::ofstream(file.temp_path()) << "new";
  file.commit();
  EXPECT_EQ(read_text(path), "new");
  EXPECT_EQ(dir.entries(), (std::set<std::string>{"mesh.png"}));
}

}  // namespace
}  // namespace rockfdem::coupling
