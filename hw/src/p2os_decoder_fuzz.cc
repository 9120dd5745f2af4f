// libFuzzer entry: any bytes through the packet decoder and the SIP/SYNC2/CONFIG decoders must
// neither crash nor loop (built with clang only; see hw/CMakeLists.txt).
#include <cstddef>
#include <cstdint>

#include "cogmap/hw/p2os_packet.h"
#include "cogmap/hw/p2os_sip.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace cogmap::hw::p2os;
  PacketDecoder decoder;
  // Split the input in two feeds so partial-packet paths are exercised too.
  const std::size_t half = size / 2;
  decoder.feed({data, half});
  for (int pass = 0; pass < 2; ++pass) {
    while (auto packet = decoder.next()) {
      try {
        if (is_sip(packet->type())) (void)encode_sip(decode_sip(packet->body));
        if (packet->type() == 2) (void)decode_sync2(packet->body);
      } catch (const DecodeError&) {
      }
      if (packet->type() == kConfigReply) (void)decode_config(packet->body);
    }
    decoder.feed({data + half, size - half});
  }
  // The sender stops: whatever is held is abandoned packet by packet until nothing is left.
  while (decoder.abandon_partial()) {
    while (decoder.next()) {
    }
  }
  return 0;
}
