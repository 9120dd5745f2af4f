// SIP, SYNC2, CONFIG, encoder and IO packet bodies: little-endian fields read with bounds checks.
#include "cogmap/hw/p2os_sip.h"

#include "cogmap/hw/p2os_packet.h"

#include <algorithm>
#include <cctype>

namespace cogmap::hw::p2os {
namespace {

// Bounds-checked little-endian reader over a packet body; errors name the offset and field.
// Offsets count from the type byte (offset 0), as Packet::body holds it.
class Reader {
 public:
  Reader(std::span<const std::uint8_t> body, std::size_t start, const char* packet = "SIP")
      : body_(body), pos_(start), packet_(packet) {}
  std::size_t remaining() const { return body_.size() - pos_; }
  std::size_t pos() const { return pos_; }
  std::uint8_t u8(const char* field) {
    need(1, field);
    return body_[pos_++];
  }
  std::uint16_t u16(const char* field) {
    need(2, field);
    const std::uint16_t v = static_cast<std::uint16_t>(body_[pos_] | (body_[pos_ + 1] << 8));
    pos_ += 2;
    return v;
  }
  std::int16_t i16(const char* field) { return static_cast<std::int16_t>(u16(field)); }
  std::int32_t i32(const char* field) {
    need(4, field);
    std::uint32_t v = 0;
    for (int i = 3; i >= 0; --i) v = (v << 8) | body_[pos_ + static_cast<std::size_t>(i)];
    pos_ += 4;
    return static_cast<std::int32_t>(v);
  }
  std::span<const std::uint8_t> rest() { return body_.subspan(pos_); }

 private:
  void need(std::size_t n, const char* field) {
    if (remaining() < n) {
      throw DecodeError(std::string(packet_) + " too short: field " + std::string(field) +
                        " at body offset " + std::to_string(pos_) + " needs " + std::to_string(n) +
                        " bytes, " + std::to_string(remaining()) + " left of " +
                        std::to_string(body_.size()));
    }
  }
  std::span<const std::uint8_t> body_;
  std::size_t pos_ = 0;
  const char* packet_;  // named in errors
};

class Writer {
 public:
  void u8(std::uint8_t v) { out_.push_back(v); }
  void u16(std::uint16_t v) {
    out_.push_back(static_cast<std::uint8_t>(v & 0xFF));
    out_.push_back(static_cast<std::uint8_t>(v >> 8));
  }
  void i16(std::int16_t v) { u16(static_cast<std::uint16_t>(v)); }
  void i32(std::int32_t v) {
    const auto bits = static_cast<std::uint32_t>(v);
    for (int i = 0; i < 4; ++i) out_.push_back(static_cast<std::uint8_t>(bits >> (8 * i)));
  }
  std::vector<std::uint8_t> take() { return std::move(out_); }

 private:
  std::vector<std::uint8_t> out_;
};

// Splits NUL-terminated strings after the type byte; a trailing unterminated run counts too.
std::vector<std::string> c_strings(std::span<const std::uint8_t> data, std::size_t max) {
  std::vector<std::string> out;
  std::string current;
  bool open = false;
  for (std::uint8_t b : data) {
    if (out.size() == max) break;
    if (b == 0) {
      out.push_back(current);
      current.clear();
      open = false;
    } else {
      current.push_back(static_cast<char>(b));
      open = true;
    }
  }
  if (open && out.size() < max) out.push_back(current);
  return out;
}

}  // namespace

Sip decode_sip(std::span<const std::uint8_t> body) {
  if (body.empty() || !is_sip(body[0])) {
    throw DecodeError("not a SIP: type byte " +
                      (body.empty() ? std::string("missing") : std::to_string(body[0])));
  }
  Reader r(body, 1);
  Sip s;
  s.moving = body[0] == 0x33;
  s.x_pos = r.u16("XPOS");
  s.y_pos = r.u16("YPOS");
  s.th_pos = r.i16("THPOS");
  s.l_vel = r.i16("L VEL");
  s.r_vel = r.i16("R VEL");
  s.battery = r.u8("BATTERY");
  s.stall_left = r.u8("STALL_AND_BUMPERS (low)");
  s.stall_right = r.u8("STALL_AND_BUMPERS (high)");
  s.control = r.i16("CONTROL");
  s.flags = r.u16("FLAGS");
  s.compass = r.u8("COMPASS");
  const std::uint8_t n = r.u8("SONAR COUNT");
  s.sonars.reserve(n);
  for (std::uint8_t i = 0; i < n; ++i) {
    SipSonar sonar;
    sonar.number = r.u8("SONAR number");
    sonar.range = r.u16("SONAR range");
    s.sonars.push_back(sonar);
  }
  s.grip_state = r.u8("GRIP_STATE");
  s.anport = r.u8("ANPORT");
  s.analog = r.u8("ANALOG");
  s.digin = r.u8("DIGIN");
  s.digout = r.u8("DIGOUT");
  // The tail: each field only when its bytes are all there (older firmware stops earlier).
  // Fields are positional, so a later one is read only after every earlier one.
  if (r.remaining() >= 2) {
    s.battery_x10 = r.u16("BATTERYX10");
    if (r.remaining() >= 1) {
      s.charge_state = r.u8("CHARGESTATE");
      if (r.remaining() >= 2) {
        s.rot_vel = r.i16("ROTVEL");
        if (r.remaining() >= 2) s.fault_flags = r.u16("FAULTFLAGS");
      }
    }
  }
  const auto rest = r.rest();
  s.extra.assign(rest.begin(), rest.end());
  return s;
}

std::vector<std::uint8_t> encode_sip(const Sip& s) {
  Writer w;
  w.u8(s.moving ? kSipMoving : kSipStopped);
  w.u16(s.x_pos);
  w.u16(s.y_pos);
  w.i16(s.th_pos);
  w.i16(s.l_vel);
  w.i16(s.r_vel);
  w.u8(s.battery);
  w.u8(s.stall_left);
  w.u8(s.stall_right);
  w.i16(s.control);
  w.u16(s.flags);
  w.u8(s.compass);
  w.u8(static_cast<std::uint8_t>(std::min<std::size_t>(s.sonars.size(), 255)));
  for (std::size_t i = 0; i < std::min<std::size_t>(s.sonars.size(), 255); ++i) {
    w.u8(s.sonars[i].number);
    w.u16(s.sonars[i].range);
  }
  w.u8(s.grip_state);
  w.u8(s.anport);
  w.u8(s.analog);
  w.u8(s.digin);
  w.u8(s.digout);
  // Tail fields are positional: a later one is only written when the earlier ones are.
  if (s.battery_x10) {
    w.u16(*s.battery_x10);
    if (s.charge_state) {
      w.u8(*s.charge_state);
      if (s.rot_vel) {
        w.i16(*s.rot_vel);
        if (s.fault_flags) w.u16(*s.fault_flags);
      }
    }
  }
  std::vector<std::uint8_t> out = w.take();
  out.insert(out.end(), s.extra.begin(), s.extra.end());
  return out;
}

RobotIdentity decode_sync2(std::span<const std::uint8_t> body) {
  if (body.empty() || body[0] != 2) throw DecodeError("not a SYNC2 reply");
  const auto strings = c_strings(body.subspan(1), 3);
  if (strings.size() < 3) {
    throw DecodeError("SYNC2 reply carries " + std::to_string(strings.size()) +
                      " of 3 strings (name, class, subclass) in " + std::to_string(body.size()) +
                      " bytes");
  }
  return {strings[0], strings[1], strings[2]};
}

std::vector<std::uint8_t> encode_sync2(const RobotIdentity& id) {
  std::vector<std::uint8_t> body = {2};
  for (const std::string* s : {&id.name, &id.klass, &id.subclass}) {
    body.insert(body.end(), s->begin(), s->end());
    body.push_back(0);
  }
  return body;
}

ConfigReply decode_config(std::span<const std::uint8_t> body) {
  ConfigReply c;
  if (body.size() > 1) c.raw.assign(body.begin() + 1, body.end());
  // Only printable NUL-terminated strings are trusted: stop at the first non-text byte.
  std::vector<std::string> strings;
  std::string current;
  for (std::size_t i = 1; i < body.size() && strings.size() < 3; ++i) {
    const std::uint8_t b = body[i];
    if (b == 0) {
      strings.push_back(current);
      current.clear();
    } else if (std::isprint(b)) {
      current.push_back(static_cast<char>(b));
    } else {
      break;
    }
  }
  if (strings.size() > 0) c.robot_type = strings[0];
  if (strings.size() > 1) c.subtype = strings[1];
  if (strings.size() > 2) c.serial_number = strings[2];
  return c;
}

std::vector<std::uint8_t> encode_encoder_packet(const EncoderCounts& counts) {
  Writer w;
  w.u8(kEncoderPacket);
  w.i32(counts.left);
  w.i32(counts.right);
  return w.take();
}

EncoderCounts decode_encoder_packet(std::span<const std::uint8_t> body) {
  if (body.empty() || body[0] != kEncoderPacket) throw DecodeError("not an encoder packet");
  Reader r(body, 1, "encoder packet");
  EncoderCounts c;
  c.left = r.i32("LEFT ENCODER");
  c.right = r.i32("RIGHT ENCODER");
  return c;
}

std::vector<std::uint8_t> encode_io_packet(const IoReport& report) {
  if (report.digital_in.size() > 255 || report.digital_out.size() > 255 ||
      report.analog.size() > 255) {
    throw std::invalid_argument("IO packet: a list of more than 255 entries has no count byte");
  }
  Writer w;
  w.u8(kIoPacket);
  w.u8(static_cast<std::uint8_t>(report.digital_in.size()));
  for (const std::uint8_t b : report.digital_in) w.u8(b);
  w.u8(static_cast<std::uint8_t>(report.digital_out.size()));
  for (const std::uint8_t b : report.digital_out) w.u8(b);
  w.u8(static_cast<std::uint8_t>(report.analog.size()));
  for (const std::uint16_t v : report.analog) w.u16(v);
  return w.take();
}

IoReport decode_io_packet(std::span<const std::uint8_t> body) {
  if (body.empty() || body[0] != kIoPacket) throw DecodeError("not an IO packet");
  Reader r(body, 1, "IO packet");
  IoReport io;
  io.digital_in.resize(r.u8("DIGIN COUNT"));
  for (std::uint8_t& b : io.digital_in) b = r.u8("DIGIN");
  io.digital_out.resize(r.u8("DIGOUT COUNT"));
  for (std::uint8_t& b : io.digital_out) b = r.u8("DIGOUT");
  io.analog.resize(r.u8("ANALOG COUNT"));
  for (std::uint16_t& v : io.analog) v = r.u16("ANALOG");
  return io;
}

std::optional<ConversionFactors> conversion_for_subclass(const std::string& subclass) {
  std::string s = subclass;
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  // DistConvFactor and RangeConvFactor of ARIA's params/<subclass>.p; every one of these has
  // AngleConvFactor 2π/4096 and VelConvFactor 1.0 (the defaults of ConversionFactors).
  struct Entry {
    const char* subclass;
    double distance_mm_per_unit, sonar_mm_per_unit;
  };
  static constexpr Entry kTable[] = {
      {"p2at", 1.32, 0.268}, {"p2at8", 1.32, 1.0},  {"p2at8+", 0.465, 1.0},
      {"p3at", 0.465, 1.0},  {"p3at-sh", 1.0, 1.0}, {"p3dx", 0.485, 1.0},
      {"p3dx-sh", 1.0, 1.0}, {"p2dx", 0.84, 0.268}, {"p2de", 0.969, 0.268},
      {"p2d8", 0.485, 1.0},  {"p2d8+", 0.485, 1.0}, {"peoplebot-sh", 1.0, 1.0},
  };
  ConversionFactors f;
  const Entry* found = nullptr;
  for (const Entry& e : kTable) {
    if (s == e.subclass) found = &e;
  }
  if (!found) return std::nullopt;
  f.distance_mm_per_unit = found->distance_mm_per_unit;
  f.sonar_mm_per_unit = found->sonar_mm_per_unit;
  return f;
}

}  // namespace cogmap::hw::p2os
