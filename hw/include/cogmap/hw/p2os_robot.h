#pragma once
/// A Pioneer P2-AT over the P2OS protocol, behind the mapper's seam. One background thread
/// owns the byte stream: it handshakes, decodes SIPs into frames, sends the motion command and
/// the keep-alive, and reconnects after silence or a controller reset. Nothing else touches the
/// stream, so commands never race with the keep-alive.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "cogmap/hw/byte_stream.h"
#include "cogmap/hw/odometry_unwrap.h"
#include "cogmap/hw/p2os_packet.h"
#include "cogmap/hw/p2os_sip.h"
#include "cogmap/mapper/seam/robot.h"

namespace cogmap::hw {

/// Where SensorFrame::time_s comes from.
enum class FrameClock {
  kHost,      ///< host steady clock, seconds since the connection (real robots)
  kSipCount,  ///< sip_period_s per SIP received (a server running faster than real time)
};

/// Timeouts and clocks of P2osRobot; defaults suit a real P2-AT (P2AT.md "Connection"). The
/// handshake's limits follow ARIA's ArRobot::asyncConnectHandler (docs/robot-driver.md,
/// "Handshake timings"), so a robot or bridge that ARIA connects to connects here too.
struct P2osRobotOptions {
  /// Wait per SYNC echo; ARIA waits 1 s for each (receivePacket(1000)). A slow link (a radio
  /// modem, a network-serial bridge) answering after 500 ms never connected.
  std::chrono::milliseconds sync_reply_timeout{1000};
  /// SYNC0-2 rounds that may end without a complete exchange; ARIA gives up when more than 10
  /// SYNCs went unanswered.
  int sync_attempts = 11;
  /// Rounds while nothing at all has come back (no packet framed, only silence or noise);
  /// ARIA gives up after 6 unanswered SYNCs when none was ever answered (retries 5), so a
  /// port with no robot fails in about 6 s.
  int silent_sync_attempts = 6;
  /// The whole handshake (every attempt) ends within this, whatever the peer sends: a peer
  /// echoing the wrong packet type forever once kept `drive` waiting with no end. ARIA's
  /// blockingConnect "can take up to 30 seconds"; 11 rounds of three slow replies could
  /// take 33 s. `drive` lowers it to --duration.
  std::chrono::milliseconds handshake_timeout{30000};
  std::chrono::milliseconds keepalive_period{200};     ///< < 0.5 s (watchdog ~2 s, P2AT.md)
  std::chrono::milliseconds silence_timeout{2000};     ///< no SIP this long: reconnect
  std::chrono::milliseconds reconnect_give_up{30000};  ///< reconnecting longer: disconnected
  std::chrono::milliseconds frame_wait{30000};         ///< next_frame() waits at most this
  /// A packet still incomplete this long after it began is abandoned, so the whole packets
  /// behind it are read: a controller that resets while sending a SIP sends the truncated SIP,
  /// then the reset packet, then nothing until the next SYNC0. The largest packet (203 bytes)
  /// takes 211 ms at 9600 baud; ARIA gives up after 100 ms without data.
  std::chrono::milliseconds partial_packet_timeout{500};
  FrameClock clock = FrameClock::kHost;
  double sip_period_s = 0.1;            ///< for FrameClock::kSipCount
  std::size_t max_queued_frames = 600;  ///< oldest dropped beyond this (a minute of SIPs)
  /// Progress and warnings ("connected to ...", "reconnecting ..."); may be empty.
  std::function<void(const std::string&)> log;
};

/// Why a P2OS session (or its handshake) ended, so a caller can tell bad input from a failed
/// run (docs/cli.md: `drive` exits 2 for kBadBytes, 1 for the others).
enum class P2osFailureKind {
  kNone,  ///< still connected, or ended by shutdown() or the caller
  /// Nothing usable came back: silence, the peer closed, an I/O error, a reconnection that
  /// gave up, or packets that decode but never answer (a wrong-type echo, a loopback).
  kLink,
  /// Bytes kept arriving but did not decode: every handshake attempt got only undecodable
  /// bytes or an unreadable SYNC2 reply, or SIPs arrived with valid checksums but an impossible
  /// layout, or no SIP decoded while the bytes in their place were dropped. The message names
  /// the stream offsets.
  kBadBytes,
  /// SYNC2 named a robot the driver does not support (or a different model on reconnection).
  kUnsupportedRobot,
};

/// The constructor's handshake failure: a StreamError (callers that catch that still work)
/// that also says which kind, so `drive` can map undecodable bytes to exit 2.
class P2osHandshakeError : public StreamError {
 public:
  P2osHandshakeError(const std::string& what, P2osFailureKind kind)
      : StreamError(what), kind_(kind) {}
  P2osFailureKind kind() const { return kind_; }

 private:
  P2osFailureKind kind_;
};

/// Connection counters, for the run report and tests.
struct P2osStats {
  std::uint64_t sips = 0;            ///< SIPs decoded
  std::uint64_t bad_sips = 0;        ///< valid checksum but undecodable (the first few logged)
  std::uint64_t dropped_bytes = 0;   ///< discarded by the packet decoder
  std::uint64_t dropped_frames = 0;  ///< frames discarded because the queue was full
  std::uint64_t unknown_sonars = 0;  ///< readings of sonar numbers beyond the geometry (dropped;
                                     ///< the first is logged with its stream offset)
  int connections = 0;               ///< successful handshakes (1 + reconnections)
  int left_open_recoveries = 0;      ///< SIPs seen during sync, CLOSE sent
  int resets = 0;                    ///< 0xFF reset packets received
};

/// mapper::Robot over P2OS; thread-safe between the caller and its own I/O thread.
class P2osRobot final : public mapper::Robot {
 public:
  /// Handshakes over `stream` (SYNC0-2, OPEN, ENABLE 1, SONAR 1) and starts the I/O thread.
  /// The SYNC2 subclass picks the geometry (mapper::find_robot_model) and the conversion
  /// factors. Throws P2osHandshakeError (a StreamError) when the robot does not answer, answers
  /// with bytes that do not decode, or names a subclass that is not a known Pioneer (the
  /// message names the device and what was received; kind() says which).
  P2osRobot(std::unique_ptr<ByteStream> stream, P2osRobotOptions options = {});
  /// Shuts down cleanly (SONAR 0, STOP, CLOSE) if not done already.
  ~P2osRobot() override;
  P2osRobot(const P2osRobot&) = delete;
  P2osRobot& operator=(const P2osRobot&) = delete;

  const mapper::RobotGeometry& geometry() const override { return geometry_; }
  /// The next SIP as a frame; waits at most options.frame_wait. Empty once the connection is
  /// lost for good (reconnection gave up, stream closed) or after shutdown().
  std::optional<mapper::SensorFrame> next_frame() override;
  /// VEL (mm/s) and RVEL (deg/s), clamped to the geometry's limits; resent as keep-alive.
  void command(const mapper::VelocityCommand& cmd) override;
  void stop() override;

  /// Sends SONAR 0, STOP, CLOSE and stops the I/O thread; idempotent.
  void shutdown();

  /// What the robot said in SYNC2.
  p2os::RobotIdentity identity() const;
  P2osStats stats() const;
  /// Why the connection ended (empty while connected). Among the reasons: no SIP could be
  /// decoded for silence_timeout while undecodable ones kept arriving (the message names the
  /// field, body offset and stream offset of the last), which no reconnection can cure; and
  /// next_frame() waiting frame_wait in vain (a peer that handshakes but sends no SIP).
  std::string failure() const;
  /// The kind of failure() (kNone when it is empty).
  P2osFailureKind failure_kind() const;

 private:
  void io_loop();
  // On the I/O thread (or the constructor before it starts). Ends by `deadline` at the latest
  // (a reconnection's give-up time) as well as by options_.handshake_timeout.
  bool handshake(std::chrono::steady_clock::time_point deadline =
                     std::chrono::steady_clock::time_point::max());
  void send(const std::vector<std::uint8_t>& packet);
  std::optional<p2os::Packet> read_packet(std::chrono::milliseconds timeout);
  void receive(std::chrono::milliseconds timeout);  // stream -> decoder, abandons cut packets
  void note_drops();  // the decoder's discards -> stats_ and last_drop_
  void handle_sip(const p2os::Packet& packet);
  void reject_sip(const p2os::Packet& packet, const std::string& why);  // counted, logged
  void send_motion();
  void log(const std::string& message) const;

  std::unique_ptr<ByteStream> stream_;
  P2osRobotOptions options_;
  mapper::RobotGeometry geometry_;
  p2os::PacketDecoder decoder_;
  p2os::StalledPacketGuard stall_guard_;
  OdometryUnwrapper odometry_;
  p2os::ConversionFactors factors_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_sip_;
  std::chrono::steady_clock::time_point last_sent_;
  std::uint64_t sip_count_ = 0;
  // The last SIP made a frame of: a SIP whose odometry moved further from it than the robot
  // can drive (LogLimits, as a log's frames are held) is undecodable, not a frame.
  bool have_accepted_ = false;
  double accepted_time_s_ = 0.0;
  mapper::Point2 accepted_xy_{0.0, 0.0};
  // Undecodable SIPs since the last good one: a peer whose every SIP fails to parse is not
  // silent, and reconnecting cannot help, so the session ends with the reason.
  std::uint64_t bad_since_sip_ = 0;
  std::chrono::steady_clock::time_point last_bad_sip_;
  bool reported_unknown_sonar_ = false;
  // Handshake attempts since the link was opened or lost, by how they ended: on bytes that did
  // not decode (or an unreadable SYNC2 reply), or on packets that were no answer (a wrong-type
  // echo, our own SYNC2, a left-open robot's SIP). Silent attempts count for neither.
  int garbage_attempts_ = 0;
  int answered_attempts_ = 0;
  std::string garbage_problem_;  // the latest of the garbage attempts, with its offsets

  mutable std::mutex mutex_;         // guards everything below
  std::string last_bad_sip_reason_;  // also read by next_frame() for its message
  std::condition_variable cv_;
  std::deque<mapper::SensorFrame> frames_;
  mapper::VelocityCommand motion_;
  bool motion_dirty_ = false;
  bool stopping_ = false;
  bool finished_ = false;
  std::string failure_;
  P2osFailureKind failure_kind_ = P2osFailureKind::kNone;  // why failure_ is set
  std::string wait_expired_;  // next_frame() ended the session: no frame within frame_wait
  P2osFailureKind wait_expired_kind_ = P2osFailureKind::kNone;
  p2os::DropEvent last_drop_;  // the decoder's latest discard, for wait_expired_'s message
  p2os::RobotIdentity identity_;
  P2osStats stats_;
  std::thread thread_;
};

}  // namespace cogmap::hw
