#pragma once
// rosbag_storage trusts a bag's index: a corrupt offset makes it read past its buffers and
// crash (seen with seeded corruption in bag_corrupt_test). So every call into it runs in a
// child process; a crash there becomes an error naming the topic and message it was reading,
// and the parent never sees half a result. Call it before the process starts other threads.

#include <cstddef>
#include <string>

#include "bag_topics.h"
#include "cogmap/hw/bag_import.h"
#include "ros_bag_reader.h"

namespace cogmap::hw::bag {

/// What the child read: the topics chosen and their streams.
struct BagContents {
  TopicChoice choice;
  Streams streams;
};

/// Lists the topics, chooses them (choose_topics) and reads both streams, in a child process;
/// a sonar message of more than `max_transducers` values (the robot model's sonars) ends the
/// reading there. Throws std::runtime_error with the child's message (BagReadError's or
/// choose_topics'), or "topic T, message K: the ROS bag library crashed (signal N) ..." when
/// the child died.
BagContents read_bag_isolated(const std::string& path, const BagImportOptions& options,
                              std::size_t max_transducers);

}  // namespace cogmap::hw::bag
