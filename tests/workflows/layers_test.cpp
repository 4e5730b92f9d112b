// workflows/src as one-way layers (docs/workflow.md): the record at the
// bottom, then the stages, the outputs that observe them, the run that
// decides, and the command line on top. A folder includes its own and the
// layers below it, never one above, so each can be read (and tested)
// without those above. The includes are read from the sources themselves.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// Bottom first: scene/ reads the file, record/ keeps the run's record,
// stages/ change the model, outputs/ write what happened, run/ drives
// them, commands/ and study/ are the command line.
const std::vector<std::string> kLayers = {"scene", "record",   "stages", "outputs",
                                          "run",   "commands", "study"};

long layer_of(const std::string& folder) {
  const auto it = std::find(kLayers.begin(), kLayers.end(), folder);
  return it == kLayers.end() ? -1 : long(it - kLayers.begin());
}

// "path: folder/header" for each include of a layer above the file's own.
std::vector<std::string> upward_includes(const fs::path& src) {
  const std::regex local(R"(^\s*#\s*include\s+"([a-z_]+)/([^"]+)\")");
  std::vector<std::string> found;
  for (const std::string& folder : kLayers) {
    for (const auto& entry : fs::directory_iterator(src / folder)) {
      std::ifstream in(entry.path());
      std::string line;
      std::smatch m;
      while (std::getline(in, line))
        if (std::regex_search(line, m, local) && layer_of(m[1]) > layer_of(folder))
          found.push_back(folder + "/" + entry.path().filename().string() + ": " + m[1].str() +
                          "/" + m[2].str());
    }
  }
  return found;
}

TEST(WorkflowsLayers, no_folder_includes_one_above_it) {
  const fs::path src = fs::path(ROCKFDEM_SOURCE_DIR) / "workflows" / "src";
  // Every folder of src/ is a layer here, so a new one must be placed.
  for (const auto& entry : fs::directory_iterator(src)) {
    if (!entry.is_directory()) continue;
    EXPECT_GE(layer_of(entry.path().filename().string()), 0)
        << entry.path() << " is in no layer of kLayers";
  }
  const std::vector<std::string> up = upward_includes(src);
  std::string list;
  for (const std::string& u : up) list += "\n  " + u;
  EXPECT_TRUE(up.empty()) << "includes of a layer above:" << list;
}

// The one error type every library throws sits beside them all, not in
// fdem/, which the mesh and in-situ libraries below it would then need.
TEST(WorkflowsLayers, the_error_header_is_in_no_library_folder) {
  const fs::path root(ROCKFDEM_SOURCE_DIR);
  EXPECT_TRUE(fs::exists(root / "common/include/rockfdem/error.hpp"));
  for (const char* library : {"mesh", "insitu", "fdem", "coupling", "workflows"})
    EXPECT_FALSE(fs::exists(root / library / "include/rockfdem/error.hpp")) << library;
}

}  // namespace
