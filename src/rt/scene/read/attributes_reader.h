// The Attributes file (manual 2.3), or the same block inline in the .scn with -Df: a count, then
// one attribute per $ line: r g b [pow tpow] e a d s t ref|refR refG refB thetaR nR thetaT nT
// index.
#pragma once

#include <vector>

#include "rt/core/diagnostics.h"
#include "rt/scene/attribute.h"
#include "rt/scene/read/dialect.h"
#include "rt/scene/read/item_stream.h"

namespace rt {

/// Reads a whole Attributes file. Index numbers are identifiers: duplicates are an error.
std::vector<Attribute> read_attributes_file(const SourceText& source, const ReaderDialect& dialect,
                                            Diagnostics& diagnostics);

/// Reads the -Df block from the .scn: the count item, then one attribute per following $ line.
std::vector<Attribute> read_inline_attributes(ItemStream& scn, const ReaderDialect& dialect,
                                              Diagnostics& diagnostics);

/// Reads one attribute line; words after the last number are its description.
Attribute read_attribute_line(const SourceText& source, const DollarLine& line,
                              const ReaderDialect& dialect, Diagnostics& diagnostics);

}  // namespace rt
