// Private: the help each subcommand prints for `rockfdem COMMAND --help`.
#pragma once

#include <boost/program_options/options_description.hpp>
#include <string>

namespace rockfdem::workflows {

/// The help of `command`: synopsis, what it does and writes, the options it
/// takes (picked from `options`, the global list) and an example. Empty for
/// a command without its own help.
std::string subcommand_help(const std::string& command,
                            const boost::program_options::options_description& options);

}  // namespace rockfdem::workflows
