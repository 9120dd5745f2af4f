#pragma once
// rosbag_storage trusts a bag's index: a corrupt offset makes it read past its buffers and
// crash (seen with seeded corruption in bag_corrupt_test). So every call into it runs in a
// child process; a crash there becomes an error naming the topic and message it was reading,
// and the parent never sees half a result. Call it before the process starts other threads.
// The child's address space is capped (limit_address_space): a length inside the bag that the
// checks before rosbag miss cannot make it take the machine's memory, and running out is an
// error naming the file and the message, not a bare "std::bad_alloc".

#include <cstddef>
#include <cstdint>
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
/// the child died, or "topic T, message K: ran out of memory ..." (out_of_memory_message).
BagContents read_bag_isolated(const std::string& path, const BagImportOptions& options,
                              std::size_t max_transducers);

/// The address space the child may map beyond what it inherits, for a bag of `content_bytes`
/// (bag_content_bytes: its size, compressed chunks counted unpacked): 4 GiB plus 16 times that,
/// which no intact bag's import reaches (bag_isolation.cc says why).
std::uint64_t reader_memory_budget(std::uint64_t content_bytes);

/// Caps this process's address space (RLIMIT_AS, soft limit) at what it maps now plus
/// `budget`, so that an allocation beyond it throws std::bad_alloc. Returns the limit now in
/// effect (a lower one set before is kept), or 0 when there is none: in a build with
/// AddressSanitizer (or ThreadSanitizer, MemorySanitizer), whose shadow memory reserves
/// terabytes of address space, no cap is set. For the child process only.
std::uint64_t limit_address_space(std::uint64_t budget);

/// False in a sanitizer build, where limit_address_space sets no limit.
bool reader_memory_is_limited();

/// The child's error for a std::bad_alloc: `where` ("topic T, message K: " or "") and what
/// the limit was: "topic T, message K: ran out of memory reading this message (the bag reader
/// may map 4.0 GiB for this bag of 3482 bytes, more than an intact bag needs): a length in the
/// bag is damaged"; with no limit, "...: a length in the bag is damaged (or the bag is too large
/// for this machine)".
std::string out_of_memory_message(const std::string& where, std::uint64_t limit,
                                  std::uint64_t content_bytes);

}  // namespace cogmap::hw::bag
