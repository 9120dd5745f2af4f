#pragma once
/// Atomic file output: every result file is written to a temporary sibling and renamed into
/// place, so a crash or a full disk never leaves a half-written file under the final name.

#include <filesystem>
#include <string_view>

namespace cogmap::experiments {

/// Writes `content` to `path` atomically (temp file in the same directory, flush, rename).
/// Creates missing parent directories. Throws std::runtime_error naming the path on failure.
void write_file_atomic(const std::filesystem::path& path, std::string_view content);

}  // namespace cogmap::experiments
