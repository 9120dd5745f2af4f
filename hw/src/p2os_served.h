#pragma once
// A P2osServer on a thread over an in-memory link, and the client-side reads the server tests
// share (p2os_server_test.cc, p2os_server_streams_test.cc).

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <optional>
#include <thread>
#include <vector>

#include "cogmap/hw/p2os_server.h"
#include "test_streams.h"

namespace cogmap::hw::testing {

// Reads packets from `link` until one of `type` arrives (or 2 s pass).
inline std::optional<p2os::Packet> await(ByteStream& link, p2os::PacketDecoder& d,
                                         std::uint8_t type) {
  using namespace std::chrono_literals;
  const auto end = std::chrono::steady_clock::now() + 2s;
  std::uint8_t buf[256];
  while (std::chrono::steady_clock::now() < end) {
    while (auto p = d.next()) {
      if (p->type() == type) return p;
    }
    const std::size_t n = link.read(buf, 20ms);
    d.feed({buf, n});
  }
  return std::nullopt;
}

// Reads packets for `span`, returning their type bytes in order.
inline std::vector<std::uint8_t> types_for(ByteStream& link, p2os::PacketDecoder& d,
                                           std::chrono::milliseconds span) {
  using namespace std::chrono_literals;
  std::vector<std::uint8_t> types;
  const auto end = std::chrono::steady_clock::now() + span;
  std::uint8_t buf[512];
  while (std::chrono::steady_clock::now() < end) {
    d.feed({buf, link.read(buf, 10ms)});
    while (auto p = d.next()) types.push_back(p->type());
  }
  return types;
}

// The server on its own thread, driving a KinematicBody; `client` is the test's end.
struct Served {
  std::unique_ptr<ByteStream> robot_end, client;
  std::unique_ptr<BackedUpStream> link;  // the server's view of robot_end
  KinematicBody body;
  std::unique_ptr<P2osServer> server;
  std::atomic<bool> stop{false};
  std::thread thread;
  p2os::PacketDecoder decoder;

  explicit Served(P2osServerOptions options = {}) {
    auto pair = make_memory_pair();
    robot_end = std::move(pair.first);
    client = std::move(pair.second);
    link = std::make_unique<BackedUpStream>(*robot_end);
    server = std::make_unique<P2osServer>(*link, body, options);
    thread = std::thread([this] { server->run(stop); });
  }
  ~Served() {
    stop = true;
    thread.join();
  }
  // SYNC0-2, OPEN and ENABLE 1, as a client connects.
  void open() {
    using p2os::Command;
    client->write(p2os::encode_command(Command::kSync0));
    ASSERT_TRUE(await(*client, decoder, 0));
    client->write(p2os::encode_command(Command::kSync1));
    ASSERT_TRUE(await(*client, decoder, 1));
    client->write(p2os::encode_command(Command::kSync2));
    const auto id = await(*client, decoder, 2);
    ASSERT_TRUE(id);
    EXPECT_EQ(p2os::decode_sync2(id->body).subclass, "p2at");
    client->write(p2os::encode_command(Command::kOpen));
    client->write(p2os::encode_command(Command::kEnable, 1));
  }
};

}  // namespace cogmap::hw::testing
