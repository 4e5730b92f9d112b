// A user's own .msh file as a tunnel model: the same default stages as a
// generated tunnel, and a file that `check` reads and refuses like `run`.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_runner.hpp"

namespace fs = std::filesystem;
using namespace rockfdem::test;

// Without [[stages]] a mesh with a lining zone gets its lining installed
// before the core is removed, as a generated tunnel does (workflow.md,
// Stages); the ring's bond to the rock is the 48 crack elements of the
// circle (measured on restart_support's mesh), all intact when installed.
TEST(MshScene, default_stages_install_the_lining_of_a_lined_mesh) {
  const fs::path dir = scratch("msh-lined");
  const fs::path scene = msh_scene(dir);
  const Result r =
      run("run " + scene.string() + " -q --set output.vtk=false -o " + (dir / "out").string());
  ASSERT_EQ(r.code, 0) << r.output;
  const nlohmann::json j = read_json(dir / "out" / "summary.json");
  const nlohmann::json& stages = j["fdem"]["stages"];
  ASSERT_EQ(stages.size(), 3u) << stages.dump();
  EXPECT_EQ(stages[0]["kind"], "lining");
  EXPECT_EQ(stages[1]["kind"], "remove_core");
  EXPECT_EQ(stages[2]["kind"], "equilibrium");
  EXPECT_EQ(stages[0]["changes"]["interface_cracks"], j["lining"]["interface_cracks"]);
  EXPECT_GT(j["lining"]["interface_cracks"].get<long>(), 20);
  // No open-hole comparison with a lining; the continuum counterpart has the
  // ring, installed at the hand-off's alpha as the lining stage does.
  EXPECT_FALSE(j.contains("comparison"));
  const nlohmann::json& c = j["continuum_comparison"];
  EXPECT_EQ(c["model"], "elastic") << j.dump();
  EXPECT_EQ(c["lining_alpha"], j["insitu"]["alpha"].back()) << c.dump();
  EXPECT_TRUE(fs::exists(dir / "out" / "continuum_profiles.csv"));
  // check's h / l_ch is the run's, from the file's elements (restart_support
  // meshes its fracture zone at 0.4 m), not from mesh.size_near's default
  // 0.5 m, which a .msh model does not use.
  const double h = j["resolution"]["h_m"].get<double>();
  EXPECT_GT(h, 0.3);
  EXPECT_LT(h, 0.45);
  const Result checked = run("check " + scene.string());
  ASSERT_EQ(checked.code, 0) << checked.output;
  char said[64];
  std::snprintf(said, sizeof said, "(h = %.3g m,", h);
  EXPECT_NE(checked.output.find(said), std::string::npos) << said << "\n" << checked.output;
  fs::remove_all(dir);
}

// `check` reads the mesh: exact counts for a good file; a file that is not
// a mesh, an unknown group or fracture group, or a mesh without the box's
// edges is refused with exit 2 and one line, as `run` refuses it.
TEST(MshScene, check_reads_the_mesh_file_and_refuses_a_bad_one) {
  const fs::path dir = scratch("msh-check");
  const fs::path scene = msh_scene(dir);
  const Result good = run("check " + scene.string());
  ASSERT_EQ(good.code, 0) << good.output;
  const nlohmann::json meshed = read_json(dir / "mesh" / "summary.json");
  EXPECT_NE(good.output.find("triangles (meshed):         " +
                             std::to_string(meshed["counts"]["triangles"].get<long>())),
            std::string::npos)
      << good.output;
  EXPECT_NE(good.output.find("peak memory (bound)"), std::string::npos) << good.output;

  std::ofstream(dir / "junk.msh") << "not a mesh\n";
  const std::pair<std::string, std::string> bad[] = {{"msh.file=junk.msh", "$MeshFormat"},
                                                     {"msh.file=mesh", "msh.file"},
                                                     {"msh.fracture_group=nope", "'nope'"},
                                                     {"msh.zones={Rock=\"rock\"}", "'Rock'"},
                                                     {"msh.edges={left=\"left\"}", "msh.edges"}};
  for (const auto& [set, expect] : bad) {
    for (const char* cmd : {"check", "run"}) {
      const Result r = run(std::string(cmd) + " " + scene.string() + " --set '" + set + "' -o " +
                           (dir / "bad").string());
      EXPECT_EQ(r.code, 2) << cmd << " " << set << ": " << r.output;
      EXPECT_NE(r.output.find(expect), std::string::npos) << cmd << " " << set << ": " << r.output;
      EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
      EXPECT_EQ(r.output.find("valid"), std::string::npos) << r.output;
      EXPECT_FALSE(fs::exists(dir / "bad")) << cmd << " " << set;
    }
  }
  fs::remove_all(dir);
}

// The two files tests/fuzz/fuzz_msh found crashing gmsh 4.8's reader with
// SIGSEGV ended `rockfdem` by that signal (exit 139).
// gmsh now reads a user's .msh in a child process: each is exit 2 from
// check, run and mesh, one line naming the file and the signal, nothing
// written.
TEST(MshScene, a_file_that_crashes_gmsh_is_exit_2_naming_it_and_the_signal) {
  const fs::path dir = scratch("msh-crash");
  const fs::path scene = msh_scene(dir);
  for (const char* name : {"gmsh48_msh2_associate_entity.msh", "gmsh48_set_physical_name.msh"}) {
    fs::copy_file(std::string(ROCKFDEM_SOURCE_DIR) + "/tests/fuzz/refused/" + name, dir / name);
    for (const char* cmd : {"check", "run", "mesh"}) {
      const Result r = run(std::string(cmd) + " " + scene.string() + " --set msh.file=" + name +
                           " -o " + (dir / "out").string());
      EXPECT_EQ(r.code, 2) << cmd << " " << name << ": " << r.output;
      EXPECT_NE(
          r.output.find((dir / name).string() + ": gmsh crashed reading it (signal 11, SIGSEGV)"),
          std::string::npos)
          << cmd << " " << name << ": " << r.output;
      EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
      EXPECT_FALSE(fs::exists(dir / "out")) << cmd << " " << name;
    }
  }
  fs::remove_all(dir);
}

// Read in a child process, a user's mesh is the mesh the read in rockfdem's
// own process gave: counts and state hash of `rockfdem mesh` on the scene
// of msh_scene() as commit 309a1d7 (before the child process) gave them.
TEST(MshScene, a_users_mesh_reads_as_it_did_before_the_child_process) {
  const fs::path dir = scratch("msh-same");
  const fs::path scene = msh_scene(dir);
  const Result r = run("mesh " + scene.string() + " -q -o " + (dir / "out").string());
  ASSERT_EQ(r.code, 0) << r.output;
  const nlohmann::json j = read_json(dir / "out" / "summary.json");
  EXPECT_EQ(j["counts"]["nodes"], 932) << j.dump();
  EXPECT_EQ(j["counts"]["triangles"], 1830) << j.dump();
  EXPECT_EQ(j["state_hash"], "5a91bf51510a513a") << j.dump();
  fs::remove_all(dir);
}

// A physical group's name is the file's text: an ESC sequence in it (here
// one that would retitle the terminal and clear the screen) is shown as
// escapes in the one-line refusal, never sent raw.
TEST(MshScene, control_bytes_of_a_group_name_never_reach_the_terminal) {
  const fs::path dir = scratch("msh-esc");
  const fs::path scene = msh_scene(dir);
  std::ofstream(dir / "esc.msh") << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n"
                                    "2 7 \"gran\x1b]0;pwned\x07\x1b[2Jite\"\n$EndPhysicalNames\n"
                                    "$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n"
                                    "$Elements\n1\n1 2 2 7 1 1 2 3\n$EndElements\n";
  const Result r = run("check " + scene.string() + " --set msh.file=esc.msh");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("'gran\\x1b]0;pwned\\x07\\x1b[2Jite'"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find('\x1b'), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find('\x07'), std::string::npos) << r.output;
  fs::remove_all(dir);
}

// A user's mesh larger than the generated tunnels' default box (here 240 m)
// takes a monitor 70 m from the axis, which lies in its rock; a point
// outside every triangle of it is refused by name once the mesh is read.
TEST(MshScene, monitors_are_placed_in_the_users_mesh_not_a_default_box) {
  const fs::path dir = scratch("msh-big");
  fs::create_directories(dir);
  const Result meshed = run("mesh " + kTestDir +
                            "/restart_support.toml -q --set domain.width=240 --set "
                            "domain.height=240 --set mesh.size_far=20 -o " +
                            (dir / "mesh").string());
  ASSERT_EQ(meshed.code, 0) << meshed.output;
  const fs::path scene = msh_scene(dir / "unused");
  std::string text = read_text(scene);
  text.replace(text.find("mesh/mesh.msh"), std::string("mesh/mesh.msh").size(),
               (dir / "mesh" / "mesh.msh").string());
  std::ofstream(dir / "inside.toml") << text << "[[monitor]]\nname = \"far\"\nx = 70.0\ny = 0.0\n";
  const Result inside =
      run("run " + (dir / "inside.toml").string() +
          " -q --set output.vtk=false --set output.plots=false -o " + (dir / "out").string());
  ASSERT_EQ(inside.code, 0) << inside.output;
  EXPECT_TRUE(read_json(dir / "out" / "summary.json")["monitors"].contains("far"));
  std::ofstream(dir / "outside.toml")
      << text << "[[monitor]]\nname = \"far\"\nx = 130.0\ny = 0.0\n";
  const Result outside =
      run("run " + (dir / "outside.toml").string() + " -q -o " + (dir / "out2").string());
  EXPECT_EQ(outside.code, 2) << outside.output;
  EXPECT_NE(outside.output.find("lies in no triangle of the mesh"), std::string::npos)
      << outside.output;
  fs::remove_all(dir);
}
