#pragma once
/// The ASR and ASR-graph file formats: JSON, version 1 (docs/asr-format.md lists every field).
/// Writers print doubles with 17 significant digits, so a round trip is bit-exact. Readers
/// validate everything and throw std::runtime_error naming the file and the field path.

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

#include "cogmap/mapper/asr/asr.h"
#include "cogmap/mapper/graph/asr_graph.h"

namespace cogmap::mapper::io {

/// The value of "format" in an ASR file.
inline constexpr std::string_view kAsrFormat = "cogmap-asr";
/// The value of "format" in an ASR graph file.
inline constexpr std::string_view kAsrGraphFormat = "cogmap-asr-graph";
/// The only version these readers accept.
inline constexpr int kFormatVersion = 1;

/// One ASR as JSON text (pretty-printed, trailing newline). Throws std::invalid_argument naming
/// the field when a number is not finite (JSON cannot hold NaN or infinity).
std::string asr_to_json_text(const Asr& asr);

/// Parses and validates one ASR. `file` names the source in error messages
/// (e.g. "asrs/003.json: walls[2][5]: expected [x, y] numbers").
Asr asr_from_json_text(std::string_view text, const std::string& file);

/// The room graph as JSON text: {"format", "version", "nodes": [{id, pose, reference_point}],
/// "edges": [{from, to, exit_index, exit}]}; positions in the world frame, metres.
std::string asr_graph_to_json_text(const AsrGraph& graph);

/// Parses and validates a room graph; errors name `file` and the field path.
AsrGraph asr_graph_from_json_text(std::string_view text, const std::string& file);

/// How far write_file_atomic goes to make a file last. Both replace the file whole or not at
/// all (temp file, rename), so a reader, or a process restarted after kill -9, sees the old file
/// or the new one; they differ only when the machine itself stops (power loss, kernel crash).
enum class Durability {
  /// fsync the file, rename, fsync the directory: on disk when the call returns. For what cannot
  /// be redone: a real robot's rooms (`drive`), a replay.
  kSynced,
  /// rename only; the kernel writes the data back in its own time, and a power cut may lose the
  /// last files written. For simulated runs, which their seed redoes bit for bit
  /// (docs/performance.md "Durability").
  kAtomic,
};

/// Writes asr_graph.json atomically (temp file, fsync, rename, fsync of the directory; the
/// fsyncs only for Durability::kSynced).
void write_asr_graph_json(const AsrGraph& graph, const std::filesystem::path& path,
                          Durability durability = Durability::kSynced);

/// Reads a file written by write_asr_graph_json.
AsrGraph read_asr_graph_json(const std::filesystem::path& path);

/// Replaces `path` with `content` so that a crash at any moment leaves either the old file or
/// the new one, never a mix: write a temp file in the same directory, fsync it, rename it over
/// `path`, fsync the directory (both fsyncs only for Durability::kSynced). Missing parent
/// directories are created. Temp names are unique per process and call, so threads may write
/// side by side. Throws std::runtime_error naming the path on any failure.
void write_file_atomic(const std::filesystem::path& path, std::string_view content,
                       Durability durability = Durability::kSynced);

/// Receives one piece of a file's content.
using ChunkSink = std::function<void(std::string_view)>;
/// write_file_atomic for content made piece by piece: `produce` hands each piece to the sink
/// as it is made, so a large file (a long run's trajectory) never sits whole in memory. If
/// `produce` throws, the temp file is removed and `path` is left as it was.
void write_file_atomic_chunks(const std::filesystem::path& path,
                              const std::function<void(const ChunkSink&)>& produce,
                              Durability durability = Durability::kSynced);

/// True for the name of a temporary file this module or the PNG writer makes:
/// ".<name>.tmp-<pid>-<n>" or ".<name>.tmp.<pid>.<n>".
bool is_temp_file_name(const std::string& file_name);

/// Removes the temporary files an interrupted writer (kill -9, power loss) left in `dir`
/// (not recursive). Only names matching is_temp_file_name are touched. Returns how many were
/// removed. Call it only while no other writer works in `dir` (the run directory lock).
std::size_t remove_stale_temp_files(const std::filesystem::path& dir);

/// Reads a whole file; throws std::runtime_error naming the path when it cannot.
std::string read_file(const std::filesystem::path& path);

}  // namespace cogmap::mapper::io
