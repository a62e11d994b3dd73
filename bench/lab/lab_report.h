// The lab's results as a text table (stdout) and as CSV.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "lab_measure.h"

namespace rt::lab {

void print_table_header(std::ostream& out);
void print_table_row(std::ostream& out, const Measurement& m);
/// Writes every measurement as CSV, one row each, with a header line. Throws IoError.
void write_csv(const std::string& file, const std::vector<Measurement>& results);

}  // namespace rt::lab
