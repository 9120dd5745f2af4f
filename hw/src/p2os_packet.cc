// P2OS framing, checksum, command encoding and the resynchronising decoder.
#include "cogmap/hw/p2os_packet.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace cogmap::hw::p2os {

std::uint16_t checksum(std::span<const std::uint8_t> body) {
  std::uint32_t c = 0;
  std::size_t i = 0;
  for (; i + 1 < body.size(); i += 2) {
    c = (c + ((static_cast<std::uint32_t>(body[i]) << 8) | body[i + 1])) & 0xFFFF;
  }
  if (i < body.size()) c ^= body[i];
  return static_cast<std::uint16_t>(c);
}

std::vector<std::uint8_t> frame(std::span<const std::uint8_t> body) {
  if (body.empty()) throw std::invalid_argument("P2OS packet body is empty");
  const std::size_t count = body.size() + 2;
  if (count > kMaxCount) {
    throw std::invalid_argument("P2OS packet body of " + std::to_string(body.size()) +
                                " bytes exceeds the count limit");
  }
  std::vector<std::uint8_t> out;
  out.reserve(count + 3);
  out.push_back(kHeader0);
  out.push_back(kHeader1);
  out.push_back(static_cast<std::uint8_t>(count));
  out.insert(out.end(), body.begin(), body.end());
  const std::uint16_t c = checksum(body);
  out.push_back(static_cast<std::uint8_t>(c >> 8));
  out.push_back(static_cast<std::uint8_t>(c & 0xFF));
  return out;
}

std::vector<std::uint8_t> encode_command(Command cmd) {
  const std::uint8_t body[] = {static_cast<std::uint8_t>(cmd)};
  return frame(body);
}

std::vector<std::uint8_t> encode_command(Command cmd, int value) {
  const unsigned magnitude = static_cast<unsigned>(std::abs(static_cast<long>(value)));
  if (magnitude > 0xFFFF) {
    throw std::invalid_argument("P2OS command " + std::to_string(static_cast<int>(cmd)) +
                                " argument " + std::to_string(value) + " exceeds 16 bits");
  }
  const std::uint8_t body[] = {
      static_cast<std::uint8_t>(cmd), value < 0 ? kArgNegative : kArgPositive,
      static_cast<std::uint8_t>(magnitude & 0xFF), static_cast<std::uint8_t>(magnitude >> 8)};
  return frame(body);
}

std::vector<std::uint8_t> encode_command(Command cmd, std::string_view text) {
  // Body: command, 0x2B, length, characters; the count adds 2 checksum bytes.
  if (text.size() + 3 + 2 > kMaxCount) {
    throw std::invalid_argument("P2OS string argument of " + std::to_string(text.size()) +
                                " characters is too long");
  }
  std::vector<std::uint8_t> body = {static_cast<std::uint8_t>(cmd), kArgString,
                                    static_cast<std::uint8_t>(text.size())};
  body.insert(body.end(), text.begin(), text.end());
  return frame(body);
}

void PacketDecoder::feed(std::span<const std::uint8_t> bytes) {
  buffer_.insert(buffer_.end(), bytes.begin(), bytes.end());
}

void PacketDecoder::clear() {
  base_offset_ += buffer_.size();
  buffer_.clear();
}

bool PacketDecoder::abandon_partial() {
  if (buffer_.empty()) return false;
  std::string why = "incomplete packet abandoned";
  if (buffer_.size() >= 3) {
    why += ": count " + std::to_string(buffer_[2]) + ", " + std::to_string(buffer_.size()) +
           " of " + std::to_string(buffer_[2] + 3) + " bytes";
  }
  drop(1, why);
  return true;
}

void PacketDecoder::drop(std::size_t n, const std::string& reason) {
  // Consecutive single-byte drops while hunting for a header merge into one event.
  if (!drops_.empty() && drops_.back().reason == reason &&
      drops_.back().offset + drops_.back().count == base_offset_) {
    drops_.back().count += n;
  } else {
    drops_.push_back({base_offset_, n, reason});
    if (drops_.size() > kMaxEvents) drops_.pop_front();
  }
  buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(n));
  base_offset_ += n;
  dropped_bytes_ += n;
}

std::optional<Packet> PacketDecoder::next() {
  for (;;) {
    if (buffer_.empty()) return std::nullopt;
    if (buffer_[0] != kHeader0) {
      drop(1, "no header");
      continue;
    }
    if (buffer_.size() < 2) return std::nullopt;
    if (buffer_[1] != kHeader1) {
      drop(1, "no header");
      continue;
    }
    if (buffer_.size() < 3) return std::nullopt;
    const std::size_t count = buffer_[2];
    if (count < kMinCount || count > kMaxCount) {
      drop(1, "bad count " + std::to_string(count));
      continue;
    }
    if (buffer_.size() < count + 3) return std::nullopt;
    std::vector<std::uint8_t> body(buffer_.begin() + 3, buffer_.begin() + 3 + (count - 2));
    const std::uint16_t expected =
        static_cast<std::uint16_t>((buffer_[count + 1] << 8) | buffer_[count + 2]);
    const std::uint16_t actual = checksum(body);
    if (actual != expected) {
      char why[64];
      std::snprintf(why, sizeof why, "bad checksum 0x%04x != 0x%04x", actual, expected);
      // Drop only the header byte: a real packet may start inside the corrupted one.
      drop(1, why);
      continue;
    }
    Packet packet{std::move(body), base_offset_};
    buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(count + 3));
    base_offset_ += count + 3;
    return packet;
  }
}

bool StalledPacketGuard::check(PacketDecoder& decoder, Clock::time_point now) {
  if (decoder.buffered() == 0) {
    timing_ = false;
    return false;
  }
  if (!timing_ || decoder.front_offset() != front_) {
    timing_ = true;
    front_ = decoder.front_offset();
    since_ = now;
    return false;
  }
  if (now - since_ < limit_) return false;
  decoder.abandon_partial();
  timing_ = false;  // whatever is at the front now is timed afresh
  return true;
}

std::chrono::milliseconds StalledPacketGuard::cap(const PacketDecoder& decoder,
                                                  Clock::time_point now,
                                                  std::chrono::milliseconds wait) const {
  if (decoder.buffered() == 0) return wait;
  if (!timing_ || decoder.front_offset() != front_) return std::min(wait, limit_);
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(since_ + limit_ - now);
  return std::clamp(left + std::chrono::milliseconds(1), std::chrono::milliseconds(0), wait);
}

}  // namespace cogmap::hw::p2os
