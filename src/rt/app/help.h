// What the program says about its switches, all rendered from the switch table: the brief list
// of bare `rt` (as the manual's 2.1 promises), `rt --help`, and docs/switches.md.
#pragma once

#include <string>

#include "rt/app/switch_table.h"

namespace rt {

/// Bare `rt`: one line per switch, like the original's summary, and how to run it.
std::string usage_text();

/// `rt --help`: usage, the rules, every switch grouped by topic with its argument, and the long
/// options; switches not implemented yet are marked so.
std::string help_text();

/// docs/switches.md (tools/gen_switch_docs writes it; a test keeps it equal to this).
std::string switches_markdown();

/// `rt --version`: "rt 0.1.0 (CMU RayTracer 6.0 reimplementation)".
std::string version_text();

/// How a switch is written with its argument: "-Stg<m>", "-A<distance>,<constant>",
/// "-Wc <angle>", "--output FILE".
std::string synopsis(const SwitchSpec& spec);

/// The values its argument takes: "m > 0", "distance > 0, constant > 0"; empty if none.
std::string argument_text(const SwitchSpec& spec);

}  // namespace rt
