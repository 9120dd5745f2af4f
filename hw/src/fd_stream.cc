// POSIX transports: poll()-bounded reads and writes on serial ports, sockets and ptys.
#include "cogmap/hw/fd_stream.h"

#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <pty.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace cogmap::hw {
namespace {

std::string sys_error(const std::string& what, const std::string& device) {
  return device + ": " + what + ": " + std::strerror(errno);
}

void set_nonblocking(int fd, const std::string& name) {
  const int flags = ::fcntl(fd, F_GETFL);
  if (flags < 0 || ::fcntl(fd, F_SETFL, flags | O_NONBLOCK) < 0) {
    throw StreamError(sys_error("fcntl(O_NONBLOCK)", name));
  }
}

speed_t baud_constant(int baud) {
  switch (baud) {
    case 9600:
      return B9600;
    case 19200:
      return B19200;
    case 38400:
      return B38400;
    case 57600:
      return B57600;
    case 115200:
      return B115200;
    default:
      throw std::invalid_argument("unsupported baud rate " + std::to_string(baud) +
                                  " (use 9600, 19200, 38400, 57600 or 115200)");
  }
}

// Splits "host:port"; the host may be a bracketed IPv6 address.
std::pair<std::string, std::string> split_host_port(const std::string& host_port) {
  const auto colon = host_port.rfind(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == host_port.size()) {
    throw std::invalid_argument("expected HOST:PORT, got '" + host_port + "'");
  }
  std::string host = host_port.substr(0, colon);
  const std::string port = host_port.substr(colon + 1);
  if (host.size() > 2 && host.front() == '[' && host.back() == ']') {
    host = host.substr(1, host.size() - 2);
  }
  // Digits only, 0-65535, checked digit by digit: std::stol threw std::out_of_range for
  // 99999999999999999999, an "internal error" in `drive` and std::terminate in `serve`.
  long value = 0;
  for (char c : port) {
    if (c < '0' || c > '9') throw std::invalid_argument("bad port in '" + host_port + "'");
    value = value * 10 + (c - '0');
    if (value > 65535) {
      throw std::invalid_argument("bad port in '" + host_port + "' (ports are 0-65535)");
    }
  }
  return {host, port};
}

}  // namespace

FdStream::FdStream(int fd, std::string name) : fd_(fd), name_(std::move(name)) {
  struct stat st {};
  socket_ = ::fstat(fd_, &st) == 0 && S_ISSOCK(st.st_mode);
}

FdStream::~FdStream() {
  if (fd_ >= 0) ::close(fd_);
}

void FdStream::write(std::span<const std::uint8_t> bytes) {
  std::size_t done = 0;
  const auto deadline = std::chrono::steady_clock::now() + kWriteTimeout;
  while (done < bytes.size()) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) throw StreamError(name_ + ": write timed out");
    pollfd p{fd_, POLLOUT, 0};
    const int r = ::poll(&p, 1, static_cast<int>(left.count()));
    if (r < 0) {
      if (errno == EINTR) continue;
      throw StreamError(sys_error("poll", name_));
    }
    if (r == 0) continue;
    if (p.revents & (POLLHUP | POLLERR)) throw StreamClosed(name_ + ": connection closed");
    if (!socket_) {
      // Serial port or pty: plain write; SIGPIPE does not apply to terminals.
      const ssize_t m = ::write(fd_, bytes.data() + done, bytes.size() - done);
      if (m < 0) {
        if (errno == EAGAIN || errno == EINTR) continue;
        if (errno == EIO || errno == EPIPE) throw StreamClosed(sys_error("write", name_));
        throw StreamError(sys_error("write", name_));
      }
      done += static_cast<std::size_t>(m);
      continue;
    }
    const ssize_t n = ::send(fd_, bytes.data() + done, bytes.size() - done, MSG_NOSIGNAL);
    if (n < 0) {
      if (errno == EAGAIN || errno == EINTR) continue;
      if (errno == EPIPE || errno == ECONNRESET) throw StreamClosed(sys_error("send", name_));
      throw StreamError(sys_error("send", name_));
    }
    done += static_cast<std::size_t>(n);
  }
}

bool FdStream::accepts_writes() {
  pollfd p{fd_, POLLOUT, 0};
  // A hang-up or error also counts as "yes": the next write() reports it as such.
  return ::poll(&p, 1, 0) != 0;
}

std::size_t FdStream::read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) {
  if (buffer.empty()) return 0;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    pollfd p{fd_, POLLIN, 0};
    const int r = ::poll(&p, 1, static_cast<int>(std::max<long long>(0, left.count())));
    if (r < 0) {
      if (errno == EINTR) continue;
      throw StreamError(sys_error("poll", name_));
    }
    if (r == 0) return 0;
    const ssize_t n = ::read(fd_, buffer.data(), buffer.size());
    if (n > 0) return static_cast<std::size_t>(n);
    if (n == 0) throw StreamClosed(name_ + ": end of stream");
    if (errno == EAGAIN || errno == EINTR) {
      if (left.count() <= 0) return 0;
      continue;
    }
    // A pty master reads EIO once no slave is open: the client hung up.
    if (errno == EIO || errno == ECONNRESET) throw StreamClosed(sys_error("read", name_));
    throw StreamError(sys_error("read", name_));
  }
}

void configure_raw_terminal(int fd, int baud, const std::string& name) {
  const speed_t speed = baud_constant(baud);
  termios tio{};
  if (::tcgetattr(fd, &tio) != 0) throw StreamError(sys_error("tcgetattr", name));
  ::cfmakeraw(&tio);
  tio.c_cflag &= ~static_cast<tcflag_t>(CSTOPB | PARENB | CRTSCTS | CSIZE);
  tio.c_cflag |= CS8 | CLOCAL | CREAD;
  tio.c_iflag &= ~static_cast<tcflag_t>(IXON | IXOFF | IXANY);
  tio.c_cc[VMIN] = 0;
  tio.c_cc[VTIME] = 0;
  if (::cfsetispeed(&tio, speed) != 0 || ::cfsetospeed(&tio, speed) != 0) {
    throw StreamError(sys_error("cfsetspeed", name));
  }
  if (::tcsetattr(fd, TCSANOW, &tio) != 0) throw StreamError(sys_error("tcsetattr", name));
  ::tcflush(fd, TCIOFLUSH);
}

std::unique_ptr<FdStream> open_serial_port(const std::string& device, int baud) {
  baud_constant(baud);  // reject a bad rate before touching the device
  const int fd = ::open(device.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    const int error = errno;
    // A directory (or a path through a file) is a wrong --port, as a regular file is below; a
    // device that is missing or busy may be a robot not plugged in yet (exit 1).
    if (error == EISDIR || error == ENOTDIR) {
      throw std::invalid_argument(device + ": " +
                                  (error == EISDIR ? "a directory" : "no such path") +
                                  ", not a serial port or terminal device (check the device name)");
    }
    throw StreamError(sys_error("open", device));
  }
  auto stream = std::make_unique<FdStream>(fd, device);
  // A regular file, /dev/null or a pipe is a wrong --port (bad input), not a robot that does
  // not answer: refused before anything is written to it.
  if (!::isatty(fd)) {
    throw std::invalid_argument(device +
                                ": not a serial port or terminal device (check the device name)");
  }
  configure_raw_terminal(fd, baud, device);
  return stream;
}

std::unique_ptr<FdStream> connect_tcp(const std::string& host_port,
                                      std::chrono::milliseconds timeout) {
  const auto [host, port] = split_host_port(host_port);
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* list = nullptr;
  if (const int rc = ::getaddrinfo(host.c_str(), port.c_str(), &hints, &list); rc != 0) {
    throw StreamError(host_port + ": " + ::gai_strerror(rc));
  }
  std::string last_error = "no address";
  for (addrinfo* a = list; a != nullptr; a = a->ai_next) {
    const int fd = ::socket(a->ai_family, a->ai_socktype | SOCK_CLOEXEC, a->ai_protocol);
    if (fd < 0) continue;
    auto stream = std::make_unique<FdStream>(fd, "tcp:" + host_port);
    set_nonblocking(fd, host_port);
    if (::connect(fd, a->ai_addr, a->ai_addrlen) != 0 && errno != EINPROGRESS) {
      last_error = std::strerror(errno);
      continue;
    }
    pollfd p{fd, POLLOUT, 0};
    const int r = ::poll(&p, 1, static_cast<int>(timeout.count()));
    int err = 0;
    socklen_t len = sizeof err;
    if (r <= 0) {
      last_error = "connect timed out";
      continue;
    }
    ::getsockopt(fd, SOL_SOCKET, SO_ERROR, &err, &len);
    if (err != 0) {
      last_error = std::strerror(err);
      continue;
    }
    const int one = 1;
    ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);  // small packets, no batching
    ::freeaddrinfo(list);
    return stream;
  }
  ::freeaddrinfo(list);
  throw StreamError(host_port + ": connect: " + last_error);
}

TcpListener::TcpListener(const std::string& host_port) : fd_(-1), port_(0), name_(host_port) {
  const auto [host, port] = split_host_port(host_port);
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = AI_PASSIVE;
  addrinfo* list = nullptr;
  if (const int rc = ::getaddrinfo(host.c_str(), port.c_str(), &hints, &list); rc != 0) {
    throw StreamError(host_port + ": " + ::gai_strerror(rc));
  }
  std::string last_error = "no address";
  for (addrinfo* a = list; a != nullptr && fd_ < 0; a = a->ai_next) {
    const int fd = ::socket(a->ai_family, a->ai_socktype | SOCK_CLOEXEC, a->ai_protocol);
    if (fd < 0) continue;
    const int one = 1;
    ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    if (::bind(fd, a->ai_addr, a->ai_addrlen) != 0 || ::listen(fd, 1) != 0) {
      last_error = std::strerror(errno);
      ::close(fd);
      continue;
    }
    fd_ = fd;
  }
  ::freeaddrinfo(list);
  if (fd_ < 0) throw StreamError(host_port + ": listen: " + last_error);
  sockaddr_storage addr{};
  socklen_t len = sizeof addr;
  ::getsockname(fd_, reinterpret_cast<sockaddr*>(&addr), &len);
  port_ = addr.ss_family == AF_INET6 ? ntohs(reinterpret_cast<sockaddr_in6*>(&addr)->sin6_port)
                                     : ntohs(reinterpret_cast<sockaddr_in*>(&addr)->sin_port);
}

TcpListener::~TcpListener() {
  if (fd_ >= 0) ::close(fd_);
}

std::unique_ptr<FdStream> TcpListener::accept(std::chrono::milliseconds timeout) {
  pollfd p{fd_, POLLIN, 0};
  const int r = ::poll(&p, 1, static_cast<int>(timeout.count()));
  if (r < 0 && errno != EINTR) throw StreamError(sys_error("poll", name_));
  if (r <= 0) return nullptr;
  const int fd = ::accept4(fd_, nullptr, nullptr, SOCK_CLOEXEC | SOCK_NONBLOCK);
  if (fd < 0) throw StreamError(sys_error("accept", name_));
  const int one = 1;
  ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  return std::make_unique<FdStream>(fd, "tcp-client@" + name_);
}

Pty::~Pty() {
  if (slave_fd >= 0) ::close(slave_fd);
}

std::unique_ptr<Pty> open_pty() {
  int master = -1, slave = -1;
  char path[256] = {};
  if (::openpty(&master, &slave, path, nullptr, nullptr) != 0) {
    throw StreamError(sys_error("openpty", "pty"));
  }
  auto pty = std::make_unique<Pty>();
  pty->master = std::make_unique<FdStream>(master, std::string("pty-master:") + path);
  pty->slave_path = path;
  pty->slave_fd = slave;
  ::fcntl(master, F_SETFD, FD_CLOEXEC);
  ::fcntl(slave, F_SETFD, FD_CLOEXEC);
  set_nonblocking(master, pty->master->name());
  // Raw on the slave side: no echo, no line discipline, so binary packets pass unchanged.
  configure_raw_terminal(slave, 38400, path);
  return pty;
}

}  // namespace cogmap::hw
