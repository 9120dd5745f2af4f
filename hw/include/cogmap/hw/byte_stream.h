#pragma once
/// The byte transport under the P2OS codec: a serial port, a TCP socket, a pseudo-terminal or
/// an in-memory pipe. The protocol code sees only this interface, so it is tested without
/// hardware (docs/robot-driver.md).

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>

namespace cogmap::hw {

/// An I/O failure of a transport: the message names the device and the system error.
class StreamError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The peer closed the connection (EOF, hang-up); a subclass so callers can reconnect.
class StreamClosed : public StreamError {
 public:
  using StreamError::StreamError;
};

/// A bidirectional byte link with bounded blocking (serial port, socket, pty, memory).
class ByteStream {
 public:
  virtual ~ByteStream() = default;

  /// Writes every byte or throws StreamError (StreamClosed when the peer is gone). Blocks at
  /// most `kWriteTimeout` in total.
  virtual void write(std::span<const std::uint8_t> bytes) = 0;

  /// Reads what is available, waiting at most `timeout` for the first byte. Returns the count
  /// read, 0 on timeout. Throws StreamClosed at EOF and StreamError on failure.
  virtual std::size_t read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) = 0;

  /// The device or address, for error messages.
  virtual std::string name() const = 0;

  /// False when a write would block now because the peer has stopped reading (a pty or
  /// socket whose buffer is full); true otherwise, and whenever the transport cannot tell.
  /// The robot-side server asks before dropping a client that sends nothing: Player's and
  /// ROS's p2os send no command while idle yet read every SIP.
  virtual bool accepts_writes() { return true; }

  /// Upper bound on one write() call: a stuck port must not hang the control loop.
  static constexpr std::chrono::milliseconds kWriteTimeout{2000};
};

/// Two connected in-memory streams (what one writes the other reads), thread-safe, for tests.
/// Closing (destroying) one end makes reads on the other throw StreamClosed once drained.
std::pair<std::unique_ptr<ByteStream>, std::unique_ptr<ByteStream>> make_memory_pair();

}  // namespace cogmap::hw
