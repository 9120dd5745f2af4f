// P2osRobot's handshake (docs/robot-driver.md "Connection"): SYNC0-2 with retries, the
// robot's identity, OPEN, the sonar polling, ENABLE; and why it failed when it does.
#include <algorithm>
#include <string>

#include "cogmap/hw/p2os_robot.h"
#include "cogmap/mapper/seam/robot_models.h"
#include "p2os_text.h"

namespace cogmap::hw {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

namespace {

// What arrived from stream offset `from` on without forming a packet, with the decoder's latest
// discard: the offsets let a user find the bytes in a capture of the link.
std::string undecodable_since(const p2os::PacketDecoder& decoder, std::uint64_t from) {
  const std::uint64_t to = decoder.offset();
  std::string text = std::to_string(to - from) + " bytes arrived (stream offsets " +
                     std::to_string(from) + "-" + std::to_string(to - 1) +
                     ") and none formed a packet";
  if (!decoder.drops().empty()) {
    const p2os::DropEvent& d = decoder.drops().back();
    if (d.offset + d.count > from) {
      text += "; the last discard: " + p2os_text::describe(d);
    }
  }
  return text;
}
}  // namespace

bool P2osRobot::handshake(Clock::time_point deadline) {
  using p2os::Command;
  decoder_.clear();
  stall_guard_.reset();
  const auto started = Clock::now();
  const auto give_up = std::min(deadline, started + options_.handshake_timeout);
  int attempts = 0;
  std::string last_problem;  // why the latest attempt did not finish, for the failure message
  // A packet of any kind came back: a robot is there, perhaps slow or confused, and gets all
  // sync_attempts; a port where nothing answers gets silent_sync_attempts (as ARIA does).
  bool answered = false;
  bool out_of_time = false;  // an attempt ran into give_up: no new one starts
  for (; attempts < options_.sync_attempts &&
         (answered || attempts < options_.silent_sync_attempts) && !out_of_time &&
         Clock::now() < give_up;
       ++attempts) {
    {
      std::lock_guard lock(mutex_);
      if (stopping_) break;
    }
    int step = 0;
    bool noted = false;  // last_problem already says what went wrong in this attempt
    send(p2os::encode_command(Command::kSync0));
    bool restart = false;
    // Each step has one deadline, however many other packets arrive meanwhile.
    auto step_deadline = std::min(give_up, Clock::now() + options_.sync_reply_timeout);
    std::uint64_t step_from = decoder_.offset();  // bytes fed from here on belong to this step
    bool step_packet = false;                     // a packet (of any type) framed in this step
    while (step < 3 && !restart) {
      const auto left = std::chrono::ceil<milliseconds>(step_deadline - Clock::now());
      const auto packet = left.count() > 0 ? read_packet(left) : std::nullopt;
      if (!packet) {
        const std::string no_reply = "no reply to SYNC" + std::to_string(step) + " within " +
                                     std::to_string(options_.sync_reply_timeout.count()) + " ms";
        if (!step_packet && decoder_.offset() > step_from) {
          // Not silence: bytes came, none framed (a wrong baud rate, a device that is no P2OS).
          last_problem = garbage_problem_ =
              no_reply + ": " + undecodable_since(decoder_, step_from);
          ++garbage_attempts_;
        } else {
          if (!noted) last_problem = no_reply;
          // Packets came, just not the reply: a P2OS peer is there. Silence counts for neither.
          if (step_packet) ++answered_attempts_;
        }
        restart = true;  // no echo in time: start again from SYNC0
        // Cut short by the overall bound: new attempts would each send a SYNC0 and wait for
        // nothing in the last moments before give_up, and the message counted them.
        out_of_time = step_deadline >= give_up;
        break;
      }
      step_packet = answered = true;
      const std::uint8_t type = packet->type();
      if (p2os::is_sip(type)) {
        // The robot was left open by an earlier client: close it and sync from scratch.
        last_problem = "a SIP during sync at stream offset " + std::to_string(packet->offset) +
                       " (the robot was left open; CLOSE sent)";
        log(stream_->name() + ": SIP during sync, robot was left open: sending CLOSE");
        ++answered_attempts_;
        send(p2os::encode_command(Command::kClose));
        {
          std::lock_guard lock(mutex_);
          ++stats_.left_open_recoveries;
        }
        // Discard what is still in flight so a stale SIP does not trigger another CLOSE.
        const auto drain_until = std::min(give_up, Clock::now() + milliseconds(300));
        while (Clock::now() < drain_until) read_packet(milliseconds(50));
        decoder_.clear();
        restart = true;
        break;
      }
      if (type != step) continue;  // a stale echo of an earlier round
      if (step == 2 && packet->body.size() == 1) {
        // A SYNC2 without a single string: our own SYNC2 coming back over a link that echoes
        // what it is sent (the robot's reply, which carries the strings, follows it). Wait on.
        last_problem = "SYNC2 came back without name strings at stream offset " +
                       std::to_string(packet->offset) +
                       " (an echo of our own SYNC2: the link echoes what it is sent) and no "
                       "robot reply followed";
        noted = true;
        continue;
      }
      if (step == 2) {
        try {
          const p2os::RobotIdentity id = p2os::decode_sync2(packet->body);
          const auto factors = p2os::conversion_for_subclass(id.subclass);
          const mapper::RobotModel* model = mapper::find_robot_model(id.subclass);
          // The geometry is fixed for the robot's lifetime: a reconnection must find the same
          // kind of robot.
          const bool changed = !identity_.subclass.empty() && model &&
                               model->name != mapper::find_robot_model(identity_.subclass)->name;
          if (!factors || !model || changed) {
            std::lock_guard lock(mutex_);
            failure_kind_ = P2osFailureKind::kUnsupportedRobot;
            failure_ =
                "robot '" + p2os_text::printable(id.name) + "' is a " +
                p2os_text::printable(id.klass) + " '" + p2os_text::printable(id.subclass) + "', " +
                (changed
                     ? "not the " + p2os_text::printable(identity_.subclass) + " connected before"
                     : "not a known Pioneer (" + mapper::robot_model_names() +
                           " and their -sh/8+ variants)");
            return false;
          }
          geometry_ = model->geometry;  // sonar mounts and limits of the model SYNC2 names
          factors_ = *factors;
          odometry_.set_factors(factors_);
          std::lock_guard lock(mutex_);
          identity_ = id;
        } catch (const p2os::DecodeError& e) {
          last_problem = "bad SYNC2 reply at stream offset " + std::to_string(packet->offset) +
                         ": " + e.what();
          garbage_problem_ = last_problem;
          log(stream_->name() + ": " + last_problem);
          ++garbage_attempts_;  // framed and checksummed, but the reply itself is garbage
          restart = true;
          break;
        }
      }
      ++step;
      if (step < 3) send(p2os::encode_command(static_cast<Command>(step)));
      step_deadline = std::min(give_up, Clock::now() + options_.sync_reply_timeout);
      step_from = decoder_.offset();
      step_packet = false;
    }
    if (step == 3) {
      send(p2os::encode_command(Command::kOpen));
      send(p2os::encode_command(Command::kEnable, 1));
      send(p2os::encode_command(Command::kSonar, 1));
      last_sip_ = Clock::now();
      bad_since_sip_ = 0;
      std::lock_guard lock(mutex_);
      ++stats_.connections;
      motion_dirty_ = true;  // resend the motion in force before the reconnection
      log(stream_->name() + ": connected to " + p2os_text::printable(identity_.name) + " (" +
          p2os_text::printable(identity_.klass) + " " + p2os_text::printable(identity_.subclass) +
          ")");
      return true;
    }
  }
  std::lock_guard lock(mutex_);
  // A reconnection whose give-up time had already come (no attempt made): the failure of its
  // last handshake stands, with its reasons.
  if (attempts == 0 && !failure_.empty()) return false;
  const auto spent = std::chrono::duration_cast<milliseconds>(Clock::now() - started);
  const bool cut_by_deadline = deadline < started + options_.handshake_timeout;
  // Bad input when, since the link was (re)opened, only undecodable bytes came back (silence
  // aside): a robot that answered at all, even wrongly, or never sent a byte is a lost link.
  const bool bad_bytes = garbage_attempts_ > 0 && answered_attempts_ == 0;
  failure_kind_ = bad_bytes ? P2osFailureKind::kBadBytes : P2osFailureKind::kLink;
  if (bad_bytes) last_problem = garbage_problem_;  // the offsets, not a silent last attempt
  failure_ = "no complete SYNC0-2 exchange in " + std::to_string(attempts) + " attempts, " +
             std::to_string(spent.count()) + " ms (" +
             (cut_by_deadline ? "ended at the reconnection's give-up time; " : "") + "limits " +
             std::to_string(options_.sync_attempts) + " attempts, " +
             std::to_string(options_.silent_sync_attempts) + " while nothing answers, " +
             std::to_string(options_.handshake_timeout.count()) + " ms)";
  if (bad_bytes) failure_ += "; only bytes that do not decode as P2OS came back";
  if (!last_problem.empty()) failure_ += "; last: " + last_problem;
  return false;
}

}  // namespace cogmap::hw
