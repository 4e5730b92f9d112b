// write_pvd: a ParaView collection that an XML parser accepts, listing the
// files and exact times in the order given.
#include <gtest/gtest.h>
#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLUtilities.h>

#include <cmath>
#include <cstdlib>

#include "rockfdem/coupling/vtk_writer.hpp"
#include "temp_dir.hpp"

namespace rockfdem::coupling {
namespace {

using testing::TempDir;

vtkSmartPointer<vtkXMLDataElement> parse(const std::string& path) {
  vtkSmartPointer<vtkXMLDataElement> root;
  root.TakeReference(vtkXMLUtilities::ReadElementFromFile(path.c_str()));
  return root;
}

TEST(Pvd, lists_files_and_exact_times_in_order_and_parses_as_xml) {
  const TempDir dir;
  PvdCollection pvd(dir.file("fdem.pvd"));
  // Not sorted on purpose: the writer keeps the caller's order.
  const std::vector<PvdEntry> want = {{0.0, "fdem_0000.vtu"},
                                      {0.1, "fdem_0001.vtu"},
                                      {1.0 / 3.0, "fdem_0002.vtu"},
                                      {0.25, "out dir/fdem & <3>.vtu"}};
  for (const PvdEntry& e : want) pvd.add(e.time, e.file);
  pvd.write();

  const auto root = parse(pvd.path());
  ASSERT_NE(root, nullptr) << "not well-formed XML";
  EXPECT_STREQ(root->GetName(), "VTKFile");
  EXPECT_STREQ(root->GetAttribute("type"), "Collection");
  ASSERT_EQ(root->GetNumberOfNestedElements(), 1);
  vtkXMLDataElement* collection = root->GetNestedElement(0);
  EXPECT_STREQ(collection->GetName(), "Collection");
  ASSERT_EQ(collection->GetNumberOfNestedElements(), static_cast<int>(want.size()));
  for (std::size_t i = 0; i < want.size(); ++i) {
    vtkXMLDataElement* ds = collection->GetNestedElement(static_cast<int>(i));
    EXPECT_STREQ(ds->GetName(), "DataSet");
    EXPECT_EQ(std::string(ds->GetAttribute("file")), want[i].file);
    EXPECT_EQ(std::strtod(ds->GetAttribute("timestep"), nullptr), want[i].time) << i;
  }
  EXPECT_EQ(dir.entries(), (std::set<std::string>{"fdem.pvd"}));
}

TEST(Pvd, rewriting_after_each_step_keeps_one_complete_file) {
  const TempDir dir;
  PvdCollection pvd(dir.file("fdem.pvd"));
  for (int step = 0; step < 5; ++step) {
    pvd.add(step * 0.5, "fdem_000" + std::to_string(step) + ".vtu");
    pvd.write();
    const auto root = parse(pvd.path());
    ASSERT_NE(root, nullptr);
    EXPECT_EQ(root->GetNestedElement(0)->GetNumberOfNestedElements(), step + 1);
  }
  EXPECT_EQ(dir.entries(), (std::set<std::string>{"fdem.pvd"}));
}

TEST(Pvd, bad_entries_and_paths_are_refused) {
  const TempDir dir;
  EXPECT_THROW(write_pvd({{0.0, ""}}, dir.file("a.pvd")), std::invalid_argument);
  EXPECT_THROW(write_pvd({{std::nan(""), "a.vtu"}}, dir.file("a.pvd")), std::invalid_argument);
  const std::string missing = dir.file("no/such/dir/a.pvd");
  try {
    write_pvd({{0.0, "a.vtu"}}, missing);
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
  EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace rockfdem::coupling
