#pragma once
// rosbag_storage trusts a bag's index: an index data record that names a connection no
// connection record declares is dropped without a word (the topic looked empty: "no sonar
// topic"), an offset past its chunk is read past the chunk's buffer, a chunk named twice is read
// twice, a chunk header's size is allocated as it stands. check_bag_index reads the layout and the
// index with its own bounded reader (bag_index.h), then unpacks every chunk and checks that each
// message the index lists is a message data record of that connection, listed once, and that
// the index lists every message of the chunk. Compiled into the ROS bag plugin (it unpacks bz2
// and lz4 chunks with the libraries rosbag uses), called before rosbag opens the bag.

#include <string>

namespace cogmap::hw::bag {

/// Throws BagReadError saying what disagrees and where: the record's byte (and a chunk's byte
/// and the offset in its data), and for a message its topic and index in the topic as
/// read_streams counts them. Returns for a bag whose index agrees with its records, and for a
/// file it leaves to rosbag (read_bag_index says which).
void check_bag_index(const std::string& path);

}  // namespace cogmap::hw::bag
