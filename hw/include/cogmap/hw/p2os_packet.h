#pragma once
/// P2OS packet framing (docs/robot-driver.md, design P2AT.md): `FA FB`, a count, the type or
/// command byte with its data, and a big-endian 16-bit checksum. Encoding of client commands
/// and a streaming decoder that resynchronises after corruption.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace cogmap::hw::p2os {

inline constexpr std::uint8_t kHeader0 = 0xFA;
inline constexpr std::uint8_t kHeader1 = 0xFB;
/// Largest count the decoder accepts: P2OS keeps whole packets under 200 bytes, so a larger
/// count is a corrupted count byte and is resynchronised at once instead of waited for.
inline constexpr std::size_t kMaxCount = 200;
/// Smallest count: the type byte and the two checksum bytes.
inline constexpr std::size_t kMinCount = 3;

/// Client command numbers (P2AT.md "Commands"); SYNC0-2 share the numbers of PULSE/OPEN/CLOSE.
enum class Command : std::uint8_t {
  kSync0 = 0,
  kSync1 = 1,
  kSync2 = 2,
  kPulse = 0,
  kOpen = 1,
  kClose = 2,
  kPolling = 3,  ///< string of sonar numbers 1-32: the firing sequence per array (ARCOS)
  kEnable = 4,
  kSetA = 5,
  kSetV = 6,
  kSetO = 7,
  kMove = 8,
  kRotate = 9,
  kSetRv = 10,
  kVel = 11,
  kHead = 12,
  kDHead = 13,
  kConfig = 18,
  kEncoder = 19,  ///< int: 0 stop, 1 one ENCODERpac, 2 one per SIP (as ARIA sends it)
  kRVel = 21,
  kSonar = 28,
  kStop = 29,
  kVel2 = 32,
  kIoRequest = 40,   ///< int: 0 stop, 1 one IOpac, 2 one per SIP (as ARIA sends it)
  kSonarCycle = 48,  ///< int, 2-120 ms per sonar disc (ARCOS)
  kHostBaud = 50,
  kEStop = 55,
};

/// Argument type bytes of client commands.
inline constexpr std::uint8_t kArgPositive = 0x3B;  ///< then |value| as u16 little-endian
inline constexpr std::uint8_t kArgNegative = 0x1B;  ///< then |value| as u16 little-endian
inline constexpr std::uint8_t kArgString = 0x2B;    ///< then a length byte and the characters

/// Robot packet types.
inline constexpr std::uint8_t kSipStopped = 0x32;
inline constexpr std::uint8_t kSipMoving = 0x33;
inline constexpr std::uint8_t kConfigReply = 0x20;
inline constexpr std::uint8_t kEncoderPacket = 0x90;  ///< ENCODERpac, the reply to ENCODER
inline constexpr std::uint8_t kIoPacket = 0xF0;       ///< IOpac, the reply to IOREQUEST
inline constexpr std::uint8_t kResetPacket = 0xFF;

/// Checksum of a packet body (type byte up to, not including, the checksum): big-endian 16-bit
/// words added modulo 2^16, an odd last byte XORed in.
std::uint16_t checksum(std::span<const std::uint8_t> body);

/// The whole packet for `body`: header, count, body, checksum. Throws std::invalid_argument
/// when the body is empty or the packet would exceed kMaxCount.
std::vector<std::uint8_t> frame(std::span<const std::uint8_t> body);

/// A command without argument (SYNC0-2, PULSE, OPEN, CLOSE, STOP, E_STOP).
std::vector<std::uint8_t> encode_command(Command cmd);
/// A command with an integer argument: 0x3B |v| for v >= 0, 0x1B |v| for v < 0. Throws
/// std::invalid_argument when |value| > 65535.
std::vector<std::uint8_t> encode_command(Command cmd, int value);
/// A command with a string argument: 0x2B, length, characters. Throws std::invalid_argument
/// when the string is longer than the packet allows.
std::vector<std::uint8_t> encode_command(Command cmd, std::string_view text);

/// One received packet.
struct Packet {
  std::vector<std::uint8_t> body;  ///< type byte and data, checksum removed (never empty)
  std::uint64_t offset = 0;        ///< stream offset of its 0xFA header byte
  std::uint8_t type() const { return body.front(); }
};

/// Bytes the decoder discarded, for diagnostics.
struct DropEvent {
  std::uint64_t offset = 0;  ///< stream offset of the first discarded byte
  std::size_t count = 0;     ///< consecutive bytes discarded
  std::string reason;        ///< "no header", "bad count 2", "bad checksum 0x1234 != 0x11b4"
};

/// Streaming decoder: feed() any bytes, next() returns whole valid packets. After a bad byte,
/// count or checksum it discards one byte and scans for the next `FA FB`, so a valid packet
/// following garbage is always found. Memory stays bounded by the largest packet, provided
/// next() is called after every feed(). A packet cut short waits for its missing bytes until
/// abandon_partial() is called (P2osRobot does after `partial_packet_timeout` of quiet).
class PacketDecoder {
 public:
  /// Appends received bytes.
  void feed(std::span<const std::uint8_t> bytes);
  /// The next valid packet, or empty when more bytes are needed.
  std::optional<Packet> next();

  /// Total bytes discarded so far.
  std::uint64_t dropped_bytes() const { return dropped_bytes_; }
  /// The most recent discard events (at most kMaxEvents; older ones are forgotten).
  const std::deque<DropEvent>& drops() const { return drops_; }
  /// Stream offset of the next byte to be fed.
  std::uint64_t offset() const { return base_offset_ + buffer_.size(); }
  /// Forgets buffered bytes (after a reconnect); offsets keep counting.
  void clear();
  /// Bytes held after next() returned empty: the start of a packet not yet complete.
  std::size_t buffered() const { return buffer_.size(); }
  /// Stream offset of the first byte held.
  std::uint64_t front_offset() const { return base_offset_; }
  /// Gives up on the incomplete packet at the front (its sender stopped in the middle: a
  /// controller reset while sending a SIP, a count byte corrupted upwards): drops its header
  /// byte, recorded as a drop event, so next() scans on and finds any whole packet among the
  /// bytes behind it. StalledPacketGuard decides when. Returns false when nothing is held.
  bool abandon_partial();

  static constexpr std::size_t kMaxEvents = 64;

 private:
  void drop(std::size_t n, const std::string& reason);

  std::deque<std::uint8_t> buffer_;
  std::uint64_t base_offset_ = 0;  // stream offset of buffer_.front()
  std::uint64_t dropped_bytes_ = 0;
  std::deque<DropEvent> drops_;
};

/// Decides when an incomplete packet has waited long enough: a packet that has stayed at the
/// front of the decoder, incomplete, for `limit` is abandoned (ARIA gives up on a packet after
/// 100 ms without data). Without it, the bytes behind a packet that was cut off (or whose count
/// byte was corrupted upwards) waited until up to 203 bytes had piled up: a reset packet that
/// followed a truncated SIP was never read, and every command behind a corrupted count was
/// held back for seconds. Use: drain next(), then call check(); if it returns true, drain again.
class StalledPacketGuard {
 public:
  using Clock = std::chrono::steady_clock;
  explicit StalledPacketGuard(std::chrono::milliseconds limit) : limit_(limit) {}
  /// Abandons the front packet when it has been incomplete for `limit`; true when it did.
  bool check(PacketDecoder& decoder, Clock::time_point now);
  /// How long a read may wait before check() is due; `wait` when nothing is pending.
  std::chrono::milliseconds cap(const PacketDecoder& decoder, Clock::time_point now,
                                std::chrono::milliseconds wait) const;
  /// Forgets the packet being timed (after PacketDecoder::clear()).
  void reset() { timing_ = false; }

 private:
  std::chrono::milliseconds limit_;
  bool timing_ = false;
  std::uint64_t front_ = 0;  // decoder front offset being timed
  Clock::time_point since_;  // when that front was first seen incomplete
};

}  // namespace cogmap::hw::p2os
