// The child process that reads a bag, and the byte format it sends its result back in (native
// endianness: the same binary on both ends of the pipe).
#include "bag_isolation.h"

#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace cogmap::hw::bag {
namespace {

// Where the child is, in memory the parent can read after a crash.
struct Progress {
  char topic[256];
  std::uint64_t index;
  bool started;
};

class Out {
 public:
  template <typename T>
  void pod(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes_.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  void str(const std::string& s) {
    pod<std::uint64_t>(s.size());
    bytes_ += s;
  }
  void doubles(const std::vector<double>& v) {
    pod<std::uint64_t>(v.size());
    bytes_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(double));
  }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

class In {
 public:
  explicit In(const std::string& bytes) : bytes_(bytes) {}
  template <typename T>
  T pod() {
    T v;
    take(&v, sizeof v);
    return v;
  }
  std::string str() {
    std::string s(pod<std::uint64_t>(), '\0');
    take(s.data(), s.size());
    return s;
  }
  std::vector<double> doubles() {
    std::vector<double> v(pod<std::uint64_t>());
    take(v.data(), v.size() * sizeof(double));
    return v;
  }

 private:
  void take(void* dst, std::size_t n) {
    if (n > bytes_.size() - pos_) throw std::runtime_error("bag reader: short reply from child");
    std::memcpy(dst, bytes_.data() + pos_, n);
    pos_ += n;
  }
  const std::string& bytes_;
  std::size_t pos_ = 0;
};

constexpr std::uint8_t kOk = 0, kError = 1;

std::string encode(const BagContents& c) {
  Out o;
  o.pod(kOk);
  const StreamRequest& r = c.choice.request;
  o.str(r.sonar_topic);
  o.pod(r.sonar);
  o.str(r.odometry_topic);
  o.pod(r.odometry);
  o.str(c.choice.sonar_type);
  o.str(c.choice.odom_type);
  o.pod<std::uint64_t>(c.streams.sonar.size());
  for (const SonarMessage& m : c.streams.sonar) {
    o.pod<std::uint64_t>(m.index);
    o.pod(m.stamp_s);
    o.doubles(m.x_m);
    o.doubles(m.y_m);
    o.doubles(m.ranges_m);
  }
  o.pod<std::uint64_t>(c.streams.poses.size());
  for (const PoseMessage& p : c.streams.poses) {
    o.pod<std::uint64_t>(p.index);
    o.pod(p.stamp_s);
    o.pod(p.x_m);
    o.pod(p.y_m);
    o.pod(p.yaw_rad);
  }
  o.pod<std::uint64_t>(c.streams.tf_messages);
  o.str(c.streams.tf_parent);
  o.str(c.streams.tf_child);
  return o.bytes();
}

BagContents decode(const std::string& bytes) {
  In in(bytes);
  if (in.pod<std::uint8_t>() == kError) throw std::runtime_error(in.str());
  BagContents c;
  StreamRequest& r = c.choice.request;
  r.sonar_topic = in.str();
  r.sonar = in.pod<SonarEncoding>();
  r.odometry_topic = in.str();
  r.odometry = in.pod<OdometryEncoding>();
  c.choice.sonar_type = in.str();
  c.choice.odom_type = in.str();
  c.streams.sonar.resize(in.pod<std::uint64_t>());
  for (SonarMessage& m : c.streams.sonar) {
    m.index = in.pod<std::uint64_t>();
    m.stamp_s = in.pod<double>();
    m.x_m = in.doubles();
    m.y_m = in.doubles();
    m.ranges_m = in.doubles();
  }
  c.streams.poses.resize(in.pod<std::uint64_t>());
  for (PoseMessage& p : c.streams.poses) {
    p.index = in.pod<std::uint64_t>();
    p.stamp_s = in.pod<double>();
    p.x_m = in.pod<double>();
    p.y_m = in.pod<double>();
    p.yaw_rad = in.pod<double>();
  }
  c.streams.tf_messages = in.pod<std::uint64_t>();
  c.streams.tf_parent = in.str();
  c.streams.tf_child = in.str();
  return c;
}

void write_all(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // the parent reports the short reply
    done += static_cast<std::size_t>(n);
  }
}

[[noreturn]] void child(int fd, Progress* progress, const std::string& path,
                        const BagImportOptions& options, std::size_t max_transducers) {
  std::string reply;
  try {
    BagContents c;
    c.choice = choose_topics(list_topics(path), options);
    c.choice.request.max_transducers = max_transducers;
    c.streams =
        read_streams(path, c.choice.request, [progress](const std::string& t, std::size_t i) {
          std::strncpy(progress->topic, t.c_str(), sizeof progress->topic - 1);
          progress->index = i;
          progress->started = true;
        });
    reply = encode(c);
  } catch (const std::exception& e) {
    Out o;
    o.pod(kError);
    o.str(e.what());
    reply = o.bytes();
  } catch (...) {
    Out o;
    o.pod(kError);
    o.str("the ROS bag library threw an unknown exception");
    reply = o.bytes();
  }
  write_all(fd, reply);
  ::close(fd);
  ::_exit(0);  // no destructors or atexit handlers of the parent's objects in the child
}

}  // namespace

BagContents read_bag_isolated(const std::string& path, const BagImportOptions& options,
                              std::size_t max_transducers) {
  void* shared =
      ::mmap(nullptr, sizeof(Progress), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
  if (shared == MAP_FAILED) throw std::runtime_error("bag reader: mmap failed");
  auto* progress = new (shared) Progress{};
  struct Unmap {
    void* p;
    ~Unmap() { ::munmap(p, sizeof(Progress)); }
  } unmap{shared};
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error("bag reader: pipe failed");
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error("bag reader: fork failed");
  }
  if (pid == 0) {
    ::close(fds[0]);
    child(fds[1], progress, path, options, max_transducers);
  }
  ::close(fds[1]);
  std::string reply;
  char buf[65536];
  for (;;) {
    const ssize_t n = ::read(fds[0], buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    reply.append(buf, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    std::string where = progress->started ? "topic " + std::string(progress->topic) + ", message " +
                                                std::to_string(progress->index) + ": "
                                          : "";
    throw std::runtime_error(where + "the ROS bag library crashed (signal " + std::to_string(sig) +
                             ", " + ::strsignal(sig) +
                             ") reading this message: the bag is corrupt");
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || reply.empty()) {
    throw std::runtime_error("the bag reader process failed (exit status " +
                             std::to_string(WEXITSTATUS(status)) + ")");
  }
  return decode(reply);
}

}  // namespace cogmap::hw::bag
