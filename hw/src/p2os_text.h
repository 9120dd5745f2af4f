#pragma once
// Text for the P2OS driver's messages, shared by the handshake and the session
// (p2os_handshake.cc, p2os_robot.cc).

#include <string>

#include "cogmap/hw/p2os_packet.h"

namespace cogmap::hw::p2os_text {

// Peer-supplied text (SYNC2 strings) for a message: control and non-ASCII bytes as \xNN, so a
// robot name cannot move the cursor or clear the user's terminal.
inline std::string printable(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const auto b = static_cast<unsigned char>(c);
    if (b >= 0x20 && b < 0x7F && b != '\\') {
      out.push_back(c);
    } else {
      static constexpr char kHex[] = "0123456789abcdef";
      out += "\\x";
      out.push_back(kHex[b >> 4]);
      out.push_back(kHex[b & 0xF]);
    }
  }
  return out;
}

// A decoder discard as "N bytes at stream offsets A-B: reason". Runs of bytes without a header
// merge into one event, so its start can lie well before the bytes that were just read.
inline std::string describe(const p2os::DropEvent& d) {
  if (d.count == 1) return "1 byte at stream offset " + std::to_string(d.offset) + ": " + d.reason;
  return std::to_string(d.count) + " bytes at stream offsets " + std::to_string(d.offset) + "-" +
         std::to_string(d.offset + d.count - 1) + ": " + d.reason;
}

}  // namespace cogmap::hw::p2os_text
