#pragma once
/// Robot-to-client P2OS packets: the standard SIP (server information packet), the SYNC
/// replies, the CONFIG reply, the encoder and IO packets and the reset packet; and the
/// per-model conversion factors.

#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace cogmap::hw::p2os {

/// A packet whose checksum was fine but whose content does not parse; the message names the
/// byte offset inside the packet body and the field.
class DecodeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// One sonar reading inside a SIP, raw units.
struct SipSonar {
  std::uint8_t number = 0;  ///< transducer, 0-based
  std::uint16_t range = 0;  ///< raw range units (see ConversionFactors::sonar_mm_per_unit)
};

/// The standard SIP, raw units as sent (P2AT.md "Standard SIP").
struct Sip {
  bool moving = false;           ///< type 0x33 (moving); any other SIP type is "stopped"
  std::uint16_t x_pos = 0;       ///< XPOS, 15 bits used, wraps
  std::uint16_t y_pos = 0;       ///< YPOS, 15 bits used, wraps
  std::int16_t th_pos = 0;       ///< THPOS, 4096 per turn
  std::int16_t l_vel = 0;        ///< left wheel velocity, mm/s x velocity factor
  std::int16_t r_vel = 0;        ///< right wheel velocity
  std::uint8_t battery = 0;      ///< volts x 10
  std::uint8_t stall_left = 0;   ///< low STALL_AND_BUMPERS byte: bit 0 left wheels stalled
  std::uint8_t stall_right = 0;  ///< high byte: bit 0 right wheels stalled
  std::int16_t control = 0;      ///< heading setpoint (server angle units)
  std::uint16_t flags = 0;       ///< bit 0 motors on, bits 1-4 sonar arrays on, bit 5 e-stop
  std::uint8_t compass = 0;
  std::vector<SipSonar> sonars;  ///< the transducers fired since the last SIP
  std::uint8_t grip_state = 0;
  std::uint8_t anport = 0;
  std::uint8_t analog = 0;
  std::uint8_t digin = 0;
  std::uint8_t digout = 0;
  // Optional tail: present only when the packet carries the bytes.
  std::optional<std::uint16_t> battery_x10;  ///< volts x 10, 16 bits
  std::optional<std::uint8_t> charge_state;
  std::optional<std::int16_t> rot_vel;  ///< 0.1 deg/s
  std::optional<std::uint16_t> fault_flags;
  std::vector<std::uint8_t> extra;  ///< newer fields after the known tail, undecoded

  bool left_stalled() const { return (stall_left & 1) != 0; }
  bool right_stalled() const { return (stall_right & 1) != 0; }
  bool motors_enabled() const { return (flags & 1) != 0; }
};

/// True for a standard SIP packet type: 0x3S with S the motor status, 0x32 (stopped) and 0x33
/// (moving) from P2OS/ARCOS, and 0x30, 0x31, 0x34 as Player's and ROS's p2os drivers also
/// accept them; the layout is the same.
inline bool is_sip(std::uint8_t type) { return type >= 0x30 && type <= 0x34; }

/// Decodes a SIP body (type byte first, checksum removed). Throws DecodeError naming the body
/// offset and the field when the packet is too short or the sonar count runs past the end.
Sip decode_sip(std::span<const std::uint8_t> body);
/// Encodes a SIP body (type byte first), including the tail fields that are set.
std::vector<std::uint8_t> encode_sip(const Sip& sip);

/// The robot's identity, from the SYNC2 reply.
struct RobotIdentity {
  std::string name;      ///< e.g. "MyRobot"
  std::string klass;     ///< "Pioneer"
  std::string subclass;  ///< "p2at", "p2at8", "p2at8+"
};

/// Decodes a SYNC2 reply body: 0x02 then three NUL-terminated strings (a missing final NUL is
/// tolerated). Throws DecodeError when fewer than three strings are present.
RobotIdentity decode_sync2(std::span<const std::uint8_t> body);
/// Encodes a SYNC2 reply body.
std::vector<std::uint8_t> encode_sync2(const RobotIdentity& id);

/// The CONFIG reply (0x20): firmware strings up to the first non-text field, plus raw bytes.
/// Layouts differ across firmware versions, so only the leading strings are decoded.
struct ConfigReply {
  std::string robot_type;         ///< first string
  std::string subtype;            ///< second string
  std::string serial_number;      ///< third string
  std::vector<std::uint8_t> raw;  ///< the whole body after the type byte
};
/// Decodes what it safely can of a CONFIG reply; never throws for short bodies (strings missing
/// are left empty).
ConfigReply decode_config(std::span<const std::uint8_t> body);

/// ENCODERpac (0x90), the reply to ENCODER (#19): each side's wheel encoder count, signed 32-bit
/// little-endian, left then right, as ARIA's ArRobot::processEncoderPacket reads it.
struct EncoderCounts {
  std::int32_t left = 0;
  std::int32_t right = 0;
};
/// Encodes an ENCODERpac body (type byte first).
std::vector<std::uint8_t> encode_encoder_packet(const EncoderCounts& counts);
/// Decodes an ENCODERpac body; throws DecodeError (naming the field) when it is too short.
EncoderCounts decode_encoder_packet(std::span<const std::uint8_t> body);

/// IOpac (0xF0), the reply to IOREQUEST (#40), as ARIA's ArRobot::processIOPacket reads it: a
/// count and that many digital input bytes, a count and the digital output bytes, a count and
/// that many analog readings (u16 little-endian, 10-bit A/D).
struct IoReport {
  std::vector<std::uint8_t> digital_in;
  std::vector<std::uint8_t> digital_out;
  std::vector<std::uint16_t> analog;
};
/// Encodes an IOpac body (type byte first). Throws std::invalid_argument for more than 255
/// entries in a list.
std::vector<std::uint8_t> encode_io_packet(const IoReport& report);
/// Decodes an IOpac body; throws DecodeError (naming the field) when a list runs past the end.
IoReport decode_io_packet(std::span<const std::uint8_t> body);

/// Raw-unit to SI conversion for one robot subclass (P2AT.md "Conversion").
struct ConversionFactors {
  double distance_mm_per_unit = 1.32;
  double angle_rad_per_unit = 0.0015339807878856412;  ///< 2π / 4096
  double velocity_mmps_per_unit = 1.0;
  double sonar_mm_per_unit = 0.268;
};

/// Factors (ARIA's params/<subclass>.p) for p2at, p2at8, p2at8+, p3at, p3at-sh, p3dx, p3dx-sh,
/// p2dx, p2de, p2d8, p2d8+ and peoplebot-sh (case-insensitive); std::nullopt otherwise.
std::optional<ConversionFactors> conversion_for_subclass(const std::string& subclass);

}  // namespace cogmap::hw::p2os
