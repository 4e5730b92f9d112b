// The options of `rockfdem sweep` and `rockfdem calibrate` on the shared
// command line: declared here so that cli.cpp only adds and reads them.
#pragma once

#include <boost/program_options.hpp>

#include "rockfdem/workflows/cli.hpp"

namespace rockfdem::workflows {

/// The study options, for the parser and the help text.
boost::program_options::options_description study_options();

/// Copies the study options into `cli.study`; throws InputError when one is
/// given to a command other than the one it belongs to.
void read_study_options(const boost::program_options::variables_map& vm, CommandLine& cli);

}  // namespace rockfdem::workflows
