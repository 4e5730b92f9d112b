// The in-situ tests need the MPI runtime for PETSc's AMG, created once per
// process before any test runs: hence a main of our own.
#include <gtest/gtest.h>

#include "rockfdem/insitu/insitu.hpp"

int main(int argc, char** argv) {
  rockfdem::insitu::ScopedParallelInit parallel(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
