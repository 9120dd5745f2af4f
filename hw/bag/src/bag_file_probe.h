#pragma once
/// What a bag file's own first record says about its length (ROS bag format 2.0: the line
/// `#ROSBAG V2.0`, then the bag header record whose `index_pos` field is the byte where the
/// index begins). rosbag_storage reports a cut-off file as "wanted 4 bytes, read 0 bytes"; this
/// turns it into the byte offsets a user can act on. Plain C++, no ROS headers.

#include <filesystem>
#include <optional>
#include <string>

namespace cogmap::hw::bag {

/// A sentence naming the file's length and where its header puts the index when the file ends
/// before that (or before its own header record); nullopt when the header reads and the index
/// lies within the file, or the file is not a bag at all.
std::optional<std::string> describe_truncation(const std::filesystem::path& path);

}  // namespace cogmap::hw::bag
