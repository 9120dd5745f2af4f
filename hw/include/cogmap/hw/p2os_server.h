#pragma once
/// The robot side of P2OS, for `cogmap serve` and tests: it answers SYNC0-2 as a P2-AT,
/// obeys OPEN/CLOSE/ENABLE/SONAR/VEL/RVEL/VEL2/STOP/E_STOP, and streams a SIP every cycle
/// built from the frames of the mapper::Robot it drives (the simulator, or a test model),
/// followed by the encoder and IO packets a client asked for (ENCODER, IOREQUEST).
/// hw does not depend on the simulator: the caller hands in any Robot.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cogmap/hw/byte_stream.h"
#include "cogmap/hw/p2os_packet.h"
#include "cogmap/hw/p2os_sip.h"
#include "cogmap/mapper/seam/robot.h"

namespace cogmap::hw {

/// What the served robot claims to be and how fast it runs.
struct P2osServerOptions {
  p2os::RobotIdentity identity{"cogmap-sim", "Pioneer", "p2at"};
  /// Wall-clock time between SIPs; each SIP advances the body one next_frame() (whose own
  /// cycle is 100 ms of simulated time). Smaller values run faster than real time.
  std::chrono::milliseconds cycle{100};
  /// The robot stops when no command arrives for this long while open (P2OS watchdog).
  std::chrono::milliseconds watchdog{2000};
  /// An open client silent this long whose link also stops taking bytes (ByteStream::
  /// accepts_writes()) is gone (crashed without CLOSE): the server closes and waits for a new
  /// handshake, so SIPs do not pile up in a link nobody reads. A silent client that still
  /// reads keeps its SIPs, as on a real controller (an idle p2os client sends nothing).
  std::chrono::milliseconds client_timeout{10000};
  /// A client packet still incomplete this long after it began is abandoned, so the commands
  /// behind it are read (as P2osRobot does with the robot's packets).
  std::chrono::milliseconds partial_packet_timeout{500};
  /// Position counters at power-up: a controller left running holds any value (tests use
  /// values near 0x7FFF to exercise the wrap).
  std::uint16_t initial_x_count = 0;
  std::uint16_t initial_y_count = 0;
  /// Where a client's SONAR_CYCLE (#48, milliseconds, 2-120) goes: the body's sonar. Empty:
  /// the command is accepted and ignored. May throw std::invalid_argument (logged, ignored).
  std::function<void(int cycle_ms)> set_sonar_cycle_ms;
  /// Where a client's POLLING (#3) goes, one call per re-sequenced array (array a holds
  /// transducers 8a..8a+7, 0-based here). May throw std::invalid_argument (logged, ignored).
  std::function<void(int array, const std::vector<int>& sequence)> set_sonar_polling;
  /// Progress messages ("client synced", "watchdog stop"); may be empty.
  std::function<void(const std::string&)> log;
};

/// Counters, for tests.
struct P2osServerStats {
  std::uint64_t sips_sent = 0;
  std::uint64_t commands = 0;  ///< valid client packets after sync
  std::uint64_t watchdog_stops = 0;
  std::uint64_t client_timeouts = 0;  ///< open clients dropped after client_timeout
  std::uint64_t syncs = 0;            ///< completed handshakes
  std::uint64_t bad_bytes = 0;        ///< discarded by the decoder
  std::uint64_t encoder_packets = 0;  ///< ENCODERpacs sent (ENCODER 1 or 2)
  std::uint64_t io_packets = 0;       ///< IOpacs sent (IOREQUEST 1 or 2)
};

/// The robot side of one P2OS link; run() serves until stopped or the client hangs up.
class P2osServer {
 public:
  /// `stream` is the robot's end of the link; `body` moves and senses. Neither is owned.
  P2osServer(ByteStream& stream, mapper::Robot& body, P2osServerOptions options = {});

  /// Serves until `stop` becomes true, the body ends (next_frame() empty) or the client hangs
  /// up (StreamClosed, returned normally). Other stream errors propagate.
  void run(const std::atomic<bool>& stop);

  /// Thread-safe: makes the server send a controller reset packet (0xFF) at the next cycle,
  /// forget the sync and restart its position counters at zero (as a real controller does).
  void request_reset() { reset_requested_ = true; }

  /// Counters so far; thread-safe.
  P2osServerStats stats() const {
    std::lock_guard lock(stats_mutex_);
    return stats_;
  }

 private:
  /// What ENCODER and IOREQUEST asked for: nothing, one packet after the next SIP, or one
  /// after every SIP (arguments 0, 1, 2 and above).
  enum class Stream { kOff, kOnce, kEverySip };
  static Stream stream_request(std::optional<int> arg);

  void handle(const p2os::Packet& packet);
  void step_and_send_sip();
  void count_wheel_travel(const mapper::Pose2& from, const mapper::Pose2& to);
  void send_requested_packets();  // after a SIP: the encoder and IO packets asked for
  void set_motion(double v_mps, double w_radps);

  ByteStream& stream_;
  mapper::Robot& body_;
  P2osServerOptions options_;
  p2os::ConversionFactors factors_;
  p2os::PacketDecoder decoder_;
  int sync_step_ = 0;  // next SYNC expected; 3 = synced
  bool open_ = false;
  bool motors_ = false;
  bool sonar_on_ = true;
  double v_mps_ = 0.0, w_radps_ = 0.0;
  std::chrono::steady_clock::time_point last_command_;
  mapper::Pose2 origin_;  // body odometry at the last reset: the counters' zero
  mapper::Pose2 last_odometry_;
  bool have_odometry_ = false;
  // Each side's wheel travel since power-up or a reset, mm: the encoders count it whether a
  // client is open or not, and SETO does not clear it (it restarts the position counters).
  double left_wheel_mm_ = 0.0, right_wheel_mm_ = 0.0;
  Stream encoder_stream_ = Stream::kOff;
  Stream io_stream_ = Stream::kOff;
  std::atomic<bool> reset_requested_{false};
  mutable std::mutex stats_mutex_;  // stats() is read from other threads while run() counts
  P2osServerStats stats_;
};

/// The CONFIGpac body (type 0x20 first) the server sends for CONFIG (#18): identity, the
/// model's speed and acceleration limits (mm/s, deg/s), the watchdog and SIP cycle, in the
/// field order ARIA's ArRobotConfigPacketReader reads.
std::vector<std::uint8_t> config_reply_body(const p2os::RobotIdentity& identity,
                                            const mapper::RobotGeometry& geometry,
                                            std::chrono::milliseconds watchdog,
                                            std::chrono::milliseconds cycle);

/// Decodes an integer command argument (0x3B / 0x1B and two bytes); empty when absent.
std::optional<int> command_int_argument(const p2os::Packet& packet);

/// Decodes a string command argument (0x2B, a length byte, the characters; a NUL ends it
/// early); empty when absent or when the length runs past the packet.
std::optional<std::string> command_string_argument(const p2os::Packet& packet);

/// Splits a POLLING string (sonar numbers 1-32, ARCOS manual) into per-array sequences of
/// 0-based transducer indices: numbers 1-8 go to array 0, 9-16 to array 1, and so on, in
/// order; only arrays that appear are listed. Empty when a number is outside 1-32 or an array
/// would get more than 16 entries (the command is then ignored).
std::optional<std::vector<std::pair<int, std::vector<int>>>> split_polling(
    const std::string& numbers);

}  // namespace cogmap::hw
