#pragma once
// Scripted P2OS peers for the driver tests: small state machines on the robot end of an
// in-memory link that differ from `cogmap serve` (other SIP type bytes, sonar counts, packets
// interleaved, byte-at-a-time writes, garbage, an echoing link, odd SYNC2 replies, resets).

#include <atomic>
#include <cmath>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>

#include "cogmap/hw/p2os_robot.h"
#include "cogmap/hw/p2os_server.h"
#include "test_streams.h"

namespace cogmap::hw::testing {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;

// A SIP body (type byte first) in the standard layout with the given counters and sonars.
inline Bytes sip_body(std::uint8_t type, std::uint16_t x, std::uint16_t y, std::int16_t th,
                      const std::vector<p2os::SipSonar>& sonars, bool tail = true) {
  p2os::Sip s;
  s.x_pos = x;
  s.y_pos = y;
  s.th_pos = th;
  s.flags = 1;
  s.sonars = sonars;
  if (tail) {
    s.battery_x10 = 130;
    s.charge_state = 0;
    s.rot_vel = 0;
  }
  Bytes body = p2os::encode_sip(s);
  body[0] = type;
  return body;
}

// What a scripted peer does; every hook may be left empty.
struct PeerScript {
  /// The reply to SYNC2 (body, type byte 2 first).
  Bytes sync2_body = p2os::encode_sync2({"peer", "Pioneer", "p2at"});
  /// The body of the n-th SIP since OPEN (n from 0).
  std::function<Bytes(std::uint64_t n)> sip;
  /// Raw bytes written before the n-th SIP (other packets, garbage).
  std::function<Bytes(std::uint64_t n)> before_sip;
  /// Called for the n-th SIP instead of sending it; returns true when it took over the link
  /// (wrote what it wanted); the peer then goes back to waiting for SYNC0.
  std::function<bool(std::uint64_t n, ByteStream& link)> reset_at;
  /// Every write is split into pieces of this many bytes (0: whole), `piece_pause` apart.
  std::size_t piece = 0;
  std::chrono::milliseconds piece_pause{0};
  std::chrono::milliseconds period{25};  ///< between SIPs (4x real time)
  /// A SYNC0 while open starts a new handshake (a real P2OS takes it for a PULSE).
  bool resync_when_open = false;
  /// Every SIP goes out with a wrong checksum (a line that corrupts each one).
  bool bad_sip_checksum = false;
  /// Each SYNC reply goes out this long after its SYNC arrived (a slow bridge or radio).
  std::chrono::milliseconds sync_delay{0};
  /// The robot was left open by an earlier client: SIPs stream before any handshake.
  bool start_open = false;
  /// A SYNC0 while open is echoed but the SIP stream goes on until CLOSE (firmware that
  /// answers SYNC0 in any state).
  bool echo_sync0_while_open = false;
};

// A P2OS robot as a state machine: SYNC0-2 echoed in order (SYNC2 answered with the script's
// body), OPEN starts the SIP stream, CLOSE stops it, a SYNC0 restarts the handshake.
class ScriptedPeer {
 public:
  ScriptedPeer(std::unique_ptr<ByteStream> link, PeerScript script)
      : link_(std::move(link)), script_(std::move(script)) {
    thread_ = std::thread([this] { run(); });
  }
  ~ScriptedPeer() {
    stop_ = true;
    thread_.join();
  }
  std::uint64_t sips_sent() const { return sips_; }
  int opens() const { return opens_; }
  int sync0s() const { return sync0s_; }  ///< SYNC0s received while closed

 private:
  void send(const Bytes& bytes) {
    if (script_.piece == 0) {
      link_->write(bytes);
      return;
    }
    for (std::size_t i = 0; i < bytes.size(); i += script_.piece) {
      const std::size_t n = std::min(script_.piece, bytes.size() - i);
      link_->write(std::span(bytes).subspan(i, n));
      if (script_.piece_pause.count() > 0) std::this_thread::sleep_for(script_.piece_pause);
    }
  }
  void run() {
    p2os::PacketDecoder decoder;
    std::uint8_t buf[256];
    int step = 0;
    bool open = script_.start_open;
    auto next_sip = std::chrono::steady_clock::now();
    const auto reply = [this](const Bytes& bytes) {
      if (script_.sync_delay.count() > 0) std::this_thread::sleep_for(script_.sync_delay);
      send(bytes);
    };
    try {
      while (!stop_) {
        const std::size_t n = link_->read(buf, 5ms);
        decoder.feed({buf, n});
        while (auto p = decoder.next()) {
          const std::uint8_t cmd = p->type();
          if (!open) {
            if (cmd == 0 && p->body.size() == 1) {
              ++sync0s_;
              reply(p2os::encode_command(p2os::Command::kSync0));
              step = 1;
            } else if (step == 1 && cmd == 1 && p->body.size() == 1) {
              reply(p2os::encode_command(p2os::Command::kSync1));
              step = 2;
            } else if (step == 2 && cmd == 2 && p->body.size() == 1) {
              reply(p2os::frame(script_.sync2_body));
              step = 3;
            } else if (step == 3 && cmd == 1) {
              open = true;
              ++opens_;
              next_sip = std::chrono::steady_clock::now();
            }
          } else if (cmd == 2) {
            open = false;
            step = 0;
          } else if (cmd == 0 && p->body.size() == 1 && script_.echo_sync0_while_open) {
            send(p2os::encode_command(p2os::Command::kSync0));
          } else if (cmd == 0 && p->body.size() == 1 && script_.resync_when_open) {
            open = false;
            send(p2os::encode_command(p2os::Command::kSync0));
            step = 1;
          }
        }
        if (open && script_.sip && std::chrono::steady_clock::now() >= next_sip) {
          next_sip += script_.period;
          const std::uint64_t k = sips_;
          if (script_.reset_at && script_.reset_at(k, *link_)) {
            open = false;
            step = 0;
            ++sips_;
            continue;
          }
          if (script_.before_sip) send(script_.before_sip(k));
          Bytes packet = p2os::frame(script_.sip(k));
          if (script_.bad_sip_checksum) packet.back() ^= 0x5A;
          send(packet);
          ++sips_;
        }
      }
    } catch (const StreamError&) {
      // the client end is gone
    }
  }

  std::unique_ptr<ByteStream> link_;
  PeerScript script_;
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> sips_{0};
  std::atomic<int> opens_{0};
  std::atomic<int> sync0s_{0};
  std::thread thread_;
};

// Wraps the client's end of a link that echoes every byte the client sends (a half-duplex
// radio modem, an RS-485 adapter, a terminal left in echo mode): the echo arrives first.
class EchoingLink final : public ByteStream {
 public:
  explicit EchoingLink(std::unique_ptr<ByteStream> inner) : inner_(std::move(inner)) {}
  void write(std::span<const std::uint8_t> bytes) override {
    {
      std::lock_guard lock(mutex_);
      echo_.insert(echo_.end(), bytes.begin(), bytes.end());
    }
    inner_->write(bytes);
  }
  std::size_t read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) override {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
      {
        std::lock_guard lock(mutex_);
        if (!echo_.empty()) {
          const std::size_t n = std::min(buffer.size(), echo_.size());
          std::copy_n(echo_.begin(), n, buffer.begin());
          echo_.erase(echo_.begin(), echo_.begin() + static_cast<std::ptrdiff_t>(n));
          return n;
        }
      }
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
          deadline - std::chrono::steady_clock::now());
      if (left.count() <= 0) return 0;
      const std::size_t n = inner_->read(buffer, std::min(left, std::chrono::milliseconds(5)));
      if (n > 0) return n;
    }
  }
  std::string name() const override { return "echoing:" + inner_->name(); }

 private:
  std::unique_ptr<ByteStream> inner_;
  std::mutex mutex_;
  std::deque<std::uint8_t> echo_;
};

inline P2osRobotOptions quick_options(std::vector<std::string>* log = nullptr,
                                      std::mutex* log_mutex = nullptr) {
  P2osRobotOptions o;
  o.sync_reply_timeout = 300ms;
  o.handshake_timeout = 4000ms;
  o.silence_timeout = 1000ms;
  o.reconnect_give_up = 3000ms;
  o.frame_wait = 2000ms;
  if (log) {
    o.log = [log, log_mutex](const std::string& m) {
      std::lock_guard lock(*log_mutex);
      log->push_back(m);
    };
  }
  return o;
}

}  // namespace cogmap::hw::testing
