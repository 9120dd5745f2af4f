#pragma once
/// Transports over POSIX file descriptors: serial ports (termios raw 8N1), TCP sockets and
/// pseudo-terminals. All reads and writes are bounded by poll() timeouts.

#include <chrono>
#include <memory>
#include <string>

#include "cogmap/hw/byte_stream.h"

namespace cogmap::hw {

/// A ByteStream over an owned file descriptor (closed on destruction).
class FdStream : public ByteStream {
 public:
  /// Takes ownership of `fd`; `name` names the device in errors.
  FdStream(int fd, std::string name);
  ~FdStream() override;
  FdStream(const FdStream&) = delete;
  FdStream& operator=(const FdStream&) = delete;

  void write(std::span<const std::uint8_t> bytes) override;
  std::size_t read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) override;
  std::string name() const override { return name_; }
  bool accepts_writes() override;

  /// The descriptor, for termios calls.
  int fd() const { return fd_; }

 private:
  int fd_;
  std::string name_;
  bool socket_;  // send(MSG_NOSIGNAL) for sockets: a vanished peer is an error, not SIGPIPE
};

/// Opens a serial device raw 8N1, no flow control, at `baud` (9600, 19200, 38400, 57600 or
/// 115200; anything else throws std::invalid_argument, as does a path that is not a terminal:
/// a regular file, /dev/null, a pipe). Throws StreamError naming the device when it cannot be
/// opened or configured.
std::unique_ptr<FdStream> open_serial_port(const std::string& device, int baud);

/// Sets raw 8N1 at `baud` on an open terminal descriptor (used for serial ports and ptys).
/// Throws std::invalid_argument for an unsupported rate, StreamError on failure.
void configure_raw_terminal(int fd, int baud, const std::string& name);

/// Connects to `host:port` (IPv4/IPv6, TCP_NODELAY), giving up after `timeout`. Throws
/// std::invalid_argument for a malformed address (a port that is not a number 0-65535),
/// StreamError when the connection fails.
std::unique_ptr<FdStream> connect_tcp(const std::string& host_port,
                                      std::chrono::milliseconds timeout);

/// A listening TCP socket, for the robot side (`cogmap serve --tcp`).
class TcpListener {
 public:
  /// Binds and listens on `host:port`; port 0 picks a free port. Throws std::invalid_argument
  /// for a malformed address, StreamError when it cannot listen.
  explicit TcpListener(const std::string& host_port);
  ~TcpListener();
  TcpListener(const TcpListener&) = delete;
  TcpListener& operator=(const TcpListener&) = delete;

  /// Waits at most `timeout` for a client; nullptr on timeout.
  std::unique_ptr<FdStream> accept(std::chrono::milliseconds timeout);
  /// The bound port (useful with port 0).
  int port() const { return port_; }

 private:
  int fd_;
  int port_;
  std::string name_;
};

/// A pseudo-terminal: the master end as a stream, and the slave's device path, which a client
/// opens like a serial port. The slave is held open by this side too, so the master does not
/// see a hang-up before the client opens it.
struct Pty {
  std::unique_ptr<FdStream> master;  ///< the robot side
  std::string slave_path;            ///< e.g. /dev/pts/3, for the client
  int slave_fd = -1;                 ///< kept open by the owner; closed on destruction
  Pty() = default;
  Pty(const Pty&) = delete;
  Pty& operator=(const Pty&) = delete;
  ~Pty();
};

/// Opens a raw pseudo-terminal pair. Throws StreamError.
std::unique_ptr<Pty> open_pty();

}  // namespace cogmap::hw
