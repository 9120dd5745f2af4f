// SONAR_CYCLE (#48) and POLLING (#3) on the robot side: decoding, the split of sonar numbers
// 1-32 into arrays (ARCOS manual), and the relay to the body's sonar.
#include <gtest/gtest.h>

#include <mutex>
#include <thread>

#include "cogmap/hw/p2os_server.h"
#include "test_streams.h"

namespace cogmap::hw {
namespace {

using namespace std::chrono_literals;
using p2os::Command;

p2os::Packet packet_of(const std::vector<std::uint8_t>& wire) {
  p2os::PacketDecoder d;
  d.feed(wire);
  auto p = d.next();
  EXPECT_TRUE(p.has_value());
  return *p;
}

TEST(P2osSonarCommands, StringArgumentDecodes) {
  const auto p = packet_of(p2os::encode_command(Command::kPolling, std::string("\x01\x02\x09")));
  EXPECT_EQ(command_string_argument(p), std::string("\x01\x02\x09"));
  // An integer argument is not a string.
  EXPECT_FALSE(command_string_argument(packet_of(p2os::encode_command(Command::kSonar, 1))));
  // A length running past the packet is refused, not read beyond it.
  p2os::Packet bad;
  bad.body = {3, p2os::kArgString, 5, 1, 2};
  EXPECT_FALSE(command_string_argument(bad));
}

TEST(P2osSonarCommands, PollingNumbersSplitIntoArrays) {
  // ARCOS: 1-8 array one, 9-16 array two; order kept, repeats allowed, 1-based on the wire.
  const auto a = split_polling(std::string("\x01\x09\x02\x01\x10", 5));
  ASSERT_TRUE(a);
  ASSERT_EQ(a->size(), 2u);
  EXPECT_EQ((*a)[0].first, 0);
  EXPECT_EQ((*a)[0].second, (std::vector<int>{0, 1, 0}));
  EXPECT_EQ((*a)[1].first, 1);
  EXPECT_EQ((*a)[1].second, (std::vector<int>{8, 15}));
  EXPECT_FALSE(split_polling(std::string("\x21")));      // 33
  EXPECT_FALSE(split_polling(std::string(17, '\x01')));  // 17 entries for one array
  EXPECT_TRUE(split_polling(std::string(16, '\x01')));
}

TEST(P2osSonarCommands, ServerRelaysCycleAndPollingToTheBody) {
  std::mutex m;
  std::vector<int> cycles;
  std::vector<std::pair<int, std::vector<int>>> pollings;
  P2osServerOptions options;
  options.set_sonar_cycle_ms = [&](int ms) {
    std::lock_guard lock(m);
    cycles.push_back(ms);
  };
  options.set_sonar_polling = [&](int array, const std::vector<int>& seq) {
    std::lock_guard lock(m);
    pollings.emplace_back(array, seq);
  };
  auto [robot_end, client] = make_memory_pair();
  testing::KinematicBody body;
  P2osServer server(*robot_end, body, options);
  std::atomic<bool> stop{false};
  std::thread thread([&] { server.run(stop); });
  client->write(p2os::encode_command(Command::kSync0));
  client->write(p2os::encode_command(Command::kSync1));
  client->write(p2os::encode_command(Command::kSync2));
  std::this_thread::sleep_for(200ms);
  client->write(p2os::encode_command(Command::kOpen));
  client->write(p2os::encode_command(Command::kSonarCycle, 25));
  client->write(p2os::encode_command(Command::kSonarCycle, 121));  // out of range: ignored
  client->write(p2os::encode_command(Command::kPolling, std::string("\x03\x04\x0b")));
  std::this_thread::sleep_for(300ms);
  stop = true;
  thread.join();
  std::lock_guard lock(m);
  EXPECT_EQ(cycles, (std::vector<int>{25}));
  ASSERT_EQ(pollings.size(), 2u);
  EXPECT_EQ(pollings[0], (std::pair<int, std::vector<int>>{0, {2, 3}}));
  EXPECT_EQ(pollings[1], (std::pair<int, std::vector<int>>{1, {10}}));
}

}  // namespace
}  // namespace cogmap::hw
