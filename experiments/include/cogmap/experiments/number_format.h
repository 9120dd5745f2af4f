#pragma once
/// Deterministic number text for result files: the shortest decimal that reads back as the
/// same double, independent of locale, so equal runs give byte-identical files.

#include <string>

namespace cogmap::experiments {

/// Shortest round-trip representation ("0.1", "1e-07", "nan", "inf").
std::string format_double(double value);

/// Appends format_double(value) to `out` without a string of its own (the CSV writers format
/// ~10 numbers a frame).
void append_double(std::string& out, double value);

}  // namespace cogmap::experiments
