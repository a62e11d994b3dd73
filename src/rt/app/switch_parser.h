// The command line `rt SCENE [switches]` read against the switch table (switch_table.h).
//
// Rules, as the manual's section 2.1 and Appendix give them:
// - exactly one SCENE, the one argument not starting with '-', kept as given (with or without
//   .scn); none at all prints the usage (show_usage), and --help / --version need no scene;
// - switches in any order; the longest spelling wins ("-dsp" over "-ds", "-Stg1.0" is -Stg);
// - numbers are glued ("-m2.0", "-A40.0,1.0"); -Wc and the integer switches (-L -tv -od -ol -ss)
//   also take the next argument when nothing is glued ("-Wc 0.7", "-L 250");
// - a switch given twice is an error (only --output repeats), as are two switches of one
//   exclusive group (-S, -C, -P, -W), and -O1 with any other switch;
// - every argument is checked fully, and every usage error reported, before a switch this release
//   does not implement is refused with NotImplementedError.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "rt/app/options.h"
#include "rt/app/switch_table.h"

namespace rt {

/// Options from the arguments (argv without argv[0]). Throws UsageError (one line, naming the
/// switch) or NotImplementedError ("-Sg: Phong with geometric attenuation is not implemented yet").
Options parse_command_line(const std::vector<std::string>& args);

/// The row whose spelling (or alias) is the longest prefix of a short switch such as "-Stg1.0",
/// or the row a long option ("--output", "--seed=3") names exactly; nullptr if none.
const SwitchSpec* match_switch(std::string_view argument);

}  // namespace rt
