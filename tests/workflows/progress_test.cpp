// Progress lines on stderr: at most one a second while a stage runs, and
// its last line once.
#include "run/progress.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

namespace {

std::string text_of(std::FILE* f) {
  std::rewind(f);
  std::string out;
  for (int c = std::fgetc(f); c != EOF; c = std::fgetc(f)) out += char(c);
  return out;
}

long lines(const std::string& s) { return long(std::count(s.begin(), s.end(), '\n')); }

}  // namespace

// An update more than a second after the start prints its step; the stage
// then ends at that same step, and finish must not print it again.
TEST(Progress, last_line_of_a_stage_is_printed_once) {
  std::FILE* out = std::tmpfile();
  ASSERT_NE(out, nullptr);
  rockfdem::workflows::Progress p("equilibrium", 200, false, out);
  p.update(100, 0.5);  // within the first second: silent
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  p.update(200, 1.0);
  p.finish(200, 1.0);
  const std::string printed = text_of(out);
  EXPECT_EQ(lines(printed), 1) << printed;
  EXPECT_NE(printed.find("[equilibrium] step 200/200"), std::string::npos) << printed;
  std::fclose(out);
}

// A stage that ends between updates prints its last step at the end.
TEST(Progress, finish_prints_the_last_step_when_no_update_did) {
  std::FILE* out = std::tmpfile();
  ASSERT_NE(out, nullptr);
  rockfdem::workflows::Progress p("lining", 0, false, out);
  p.finish(0, 0.0);
  rockfdem::workflows::Progress quiet("lining", 0, true, out);
  quiet.finish(0, 0.0);
  const std::string printed = text_of(out);
  EXPECT_EQ(lines(printed), 1) << printed;
  EXPECT_NE(printed.find("[lining] step 0/0"), std::string::npos) << printed;
  std::fclose(out);
}
