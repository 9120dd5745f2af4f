// The layouts checked before roscpp_serialization decodes a message (message_layout.h), and
// the memory limit of the process that reads a bag (bag_isolation.h). Whole bags with damaged
// lengths: bag_message_length_test.cc.
#include "message_layout.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <new>

#include "bag_file_probe.h"
#include "bag_isolation.h"
#include "bag_test_helpers.h"
#include "ros_bag_reader.h"
#include "test_bag_writer.h"
#include "test_raw_bag.h"

namespace cogmap::hw::bag {
namespace {

namespace fs = std::filesystem;
using testing::expect_contains;

// ROS 1 serialization by hand: little-endian numbers, arrays and strings after their length.
struct Bytes {
  std::string b;
  Bytes& u32(std::uint32_t v) {
    for (int i = 0; i < 4; ++i) b += static_cast<char>((v >> (8 * i)) & 0xff);
    return *this;
  }
  Bytes& zeros(std::size_t n) {
    b.append(n, '\0');
    return *this;
  }
  Bytes& str(const std::string& s) {
    u32(static_cast<std::uint32_t>(s.size()));
    b += s;
    return *this;
  }
  Bytes& header(const std::string& frame) { return zeros(12).str(frame); }
};

// "" when the layout accepts the bytes, else the error.
std::string error_of(MessageLayout layout, const std::string& b) {
  try {
    check_message_layout(layout, reinterpret_cast<const std::uint8_t*>(b.data()), b.size());
  } catch (const BagReadError& e) {
    return e.what();
  }
  return "";
}

// A PointCloud of one point and two channels of one value each; `values1` is what the second
// channel's length says.
std::string cloud_with_channels(std::uint32_t values1 = 1) {
  return Bytes{}
      .header("sonar")
      .u32(1)
      .zeros(12)
      .u32(2)
      .str("intensity")
      .u32(1)
      .zeros(4)
      .str("range")
      .u32(values1)
      .zeros(4)
      .b;
}

TEST(MessageLayout, NestedArraysAreCheckedAndNamedByPath) {
  EXPECT_EQ(error_of(MessageLayout::kPointCloud, cloud_with_channels()), "");
  EXPECT_EQ(error_of(MessageLayout::kPointCloud, cloud_with_channels(1000)),
            "its channels[1].values array claims 1000 elements (4000 bytes) but the message "
            "holds only 4 more bytes: the message is damaged");
  std::string b = cloud_with_channels();
  b[4 + 8 + 4 + 5 + 4 + 12] = '\xff';  // the channels' length: 255 elements of at least 8 bytes
  EXPECT_EQ(error_of(MessageLayout::kPointCloud, b),
            "its channels array claims 255 elements (at least 2040 bytes) but the message holds "
            "only 38 more bytes: the message is damaged");
}

TEST(MessageLayout, PointCloud2FieldNamesAndFixedFields) {
  const auto cloud2 = [](std::uint32_t name1) {
    return Bytes{}
        .header("f")
        .zeros(8)
        .u32(2)
        .str("x")
        .zeros(9)
        .u32(name1)
        .b.append("y")
        .append(9, '\0')
        .append(9, '\0')  // is_bigendian, point_step, row_step
        .append(4, '\0')  // data: 0 bytes
        .append(1, '\0');
  };
  EXPECT_EQ(error_of(MessageLayout::kPointCloud2, cloud2(1)), "");
  EXPECT_EQ(error_of(MessageLayout::kPointCloud2, cloud2(100)),
            "its fields[1].name string claims 100 bytes but the message holds only 24 more bytes: "
            "the message is damaged");
  std::string cut = cloud2(1);
  cut.pop_back();
  EXPECT_EQ(error_of(MessageLayout::kPointCloud2, cut),
            "its is_dense needs 1 bytes but the message holds only 0 more bytes: the message is "
            "damaged");
}

TEST(MessageLayout, OdometryCutInsideItsPose) {
  const std::string odometry = Bytes{}.header("odom").str("base_link").zeros(344 + 336).b;
  EXPECT_EQ(error_of(MessageLayout::kOdometry, odometry), "");
  EXPECT_EQ(error_of(MessageLayout::kOdometry, odometry.substr(0, 33 + 100)),
            "its pose needs 344 bytes but the message holds only 100 more bytes: the message is "
            "damaged");
  EXPECT_EQ(error_of(MessageLayout::kOdometry, ""),
            "its header.seq and .stamp needs 12 bytes but the message holds only 0 more bytes: "
            "the message is damaged");
}

TEST(MessageLayout, BytesAfterTheLastFieldAreAcceptedAsRoscppAcceptsThem) {
  const std::string tf = Bytes{}.u32(1).header("odom").str("base_link").zeros(56).b;
  EXPECT_EQ(error_of(MessageLayout::kTfMessage, tf), "");
  EXPECT_EQ(error_of(MessageLayout::kTfMessage, tf + "extra"), "");
  EXPECT_EQ(error_of(MessageLayout::kTfMessage, Bytes{}.u32(0).b), "");
}

// Every message of each type as rosbag writes it reads, and every cut of it is refused.
TEST(MessageLayout, RosbagsOwnMessagesPassAndEveryCutIsRefused) {
  const fs::path path = testing::temp_bag("cogmap_message_layout_test", "all_types");
  {
    testing::TestBagWriter w(path.string());
    w.odometry("/pose", 10.0, 1.5, -2.0, 0.3);
    w.tf("/tf", 10.0, 1.0, 2.0, 0.1, "robot1/odom", "robot1/base_footprint");
    w.point_cloud("/cloud", 10.0, {{1, 2}, {3, 4}, {0, 0}});
    w.point_cloud2("/cloud2", 10.0, {{1, 2}, {3, 4}});
  }
  const testing::RawBag b(path.string());
  const std::pair<const char*, MessageLayout> topics[] = {{"/pose", MessageLayout::kOdometry},
                                                          {"/tf", MessageLayout::kTfMessage},
                                                          {"/cloud", MessageLayout::kPointCloud},
                                                          {"/cloud2", MessageLayout::kPointCloud2}};
  for (const auto& [topic, layout] : topics) {
    const std::uint32_t conn = b.connection(topic).u32("conn");
    std::size_t messages = 0;
    for (const std::size_t c : b.find(testing::kOpChunk)) {
      for (const auto& r : testing::parse_records(b.records[c].data)) {
        if (r.op() != testing::kOpMessageData || r.u32("conn") != conn) continue;
        ++messages;
        EXPECT_EQ(error_of(layout, r.data), "") << topic;
        for (std::size_t n = 0; n < r.data.size(); ++n) {
          expect_contains(error_of(layout, r.data.substr(0, n)), ": the message is damaged");
        }
      }
    }
    EXPECT_EQ(messages, 1u) << topic;
  }
}

TEST(BagReaderMemory, BudgetIsFourGiBPlusSixteenTimesTheContent) {
  EXPECT_EQ(reader_memory_budget(0), std::uint64_t{4} << 30);
  EXPECT_EQ(reader_memory_budget(211'000'000), (std::uint64_t{4} << 30) + 16 * 211'000'000ull);
  EXPECT_EQ(reader_memory_budget(~std::uint64_t{0} / 2), ~std::uint64_t{0});
}

TEST(BagReaderMemory, ContentCountsCompressedChunksUnpacked) {
  for (const auto c :
       {testing::Compression::kNone, testing::Compression::kBz2, testing::Compression::kLz4}) {
    const fs::path path = testing::temp_bag("cogmap_message_layout_test",
                                            "content" + std::to_string(static_cast<int>(c)));
    {
      testing::TestBagWriter w(path.string(), c, 4096);
      for (int k = 0; k < 200; ++k) w.odometry("/pose", 10.0 + 0.1 * k, 0, 0, 0);
    }
    std::uint64_t expected = fs::file_size(path);
    const testing::RawBag b(path.string());
    for (const std::size_t i : b.find(testing::kOpChunk)) {
      const auto& chunk = b.records[i];
      if (chunk.field("compression") != "none" && chunk.u32("size") > chunk.data.size()) {
        expected += chunk.u32("size") - chunk.data.size();
      }
    }
    if (c != testing::Compression::kNone) {
      EXPECT_GT(expected, fs::file_size(path) + 50'000);
    }
    EXPECT_EQ(bag_content_bytes(path), expected);
  }
  const fs::path text = testing::temp_bag("cogmap_message_layout_test", "text");
  std::ofstream(text) << "#ROSBAG V2.0\nnot a bag\n";
  EXPECT_EQ(bag_content_bytes(text), fs::file_size(text));
  EXPECT_EQ(bag_content_bytes(text.string() + ".missing"), 0u);
}

// In a child, as the bag reader does: past the limit an allocation throws std::bad_alloc
// (without it, 5 GiB untouched is granted by the kernel's overcommit); below it, it works.
TEST(BagReaderMemory, LimitTurnsAnAllocationPastItIntoBadAlloc) {
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const std::uint64_t budget = reader_memory_budget(1'000'000);
    if (limit_address_space(budget) == 0) ::_exit(77);  // a sanitizer build
    try {
      std::string small(64u << 20, 'x');
      char* volatile big = new char[budget + (std::uint64_t{1} << 30)];
      big[0] = small[0];
      ::_exit(1);
    } catch (const std::bad_alloc&) {
      ::_exit(0);
    }
  }
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  if (WEXITSTATUS(status) == 77) GTEST_SKIP() << "no limit in a sanitizer build";
  EXPECT_EQ(WEXITSTATUS(status), 0) << "1: the allocation past the limit was granted";
}

TEST(BagReaderMemory, OutOfMemorySaysWhereAndWhatTheLimitWas) {
  EXPECT_EQ(out_of_memory_message("topic /tf, message 3: ", std::uint64_t{9} << 29, 3482),
            "topic /tf, message 3: ran out of memory reading this message (the bag reader may "
            "map 4.5 GiB for this bag of 3482 bytes, more than an intact bag needs): a length in "
            "the bag is damaged");
  EXPECT_EQ(out_of_memory_message("", 0, 211'000'000),
            "ran out of memory reading the bag: a length in the bag is damaged (or the bag is too "
            "large for this machine)");
}

}  // namespace
}  // namespace cogmap::hw::bag
