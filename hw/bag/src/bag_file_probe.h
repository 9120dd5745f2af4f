#pragma once
/// What a bag file's own first record says about its length (ROS bag format 2.0: the line
/// `#ROSBAG V2.0`, then the bag header record whose `index_pos` field is the byte where the
/// index begins). rosbag_storage reports a cut-off file as "wanted 4 bytes, read 0 bytes"; this
/// turns it into the byte offsets a user can act on. Plain C++, no ROS headers.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace cogmap::hw::bag {

/// A sentence naming the file's length and where its header puts the index when the file ends
/// before that (or before its own header record); nullopt when the header reads and the index
/// lies within the file, or the file is not a bag at all.
std::optional<std::string> describe_truncation(const std::filesystem::path& path);

/// What a bag's records take once its chunks are unpacked: the file's size, plus for each bz2 or
/// lz4 chunk between the bag header record and the index what its header says it unpacks to
/// (at most kMaxChunkBytes) beyond the bytes it takes in the file. The records are read with
/// their lengths checked (bag_records.h, headers only); the count ends at the first record that
/// does not read (the index check says what is wrong with it). The file's size alone for a file
/// that is no format 2.0 bag, 0 for one that cannot be read. bag_isolation.cc bounds the memory
/// of the process that reads the bag by it.
std::uint64_t bag_content_bytes(const std::filesystem::path& path);

}  // namespace cogmap::hw::bag
