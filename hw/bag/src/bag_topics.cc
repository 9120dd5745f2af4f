// Topic detection. RosAria records /RosAria/sonar (PointCloud) and, when subscribed,
// /RosAria/sonar_pointcloud2 with the same data; p2os records /sonar (SonarArray). Odometry is
// /RosAria/pose or /pose (nav_msgs/Odometry); without one, /tf carries odom -> base_link.
#include "bag_topics.h"

#include <algorithm>
#include <cctype>
#include <optional>
#include <stdexcept>

#include "sonar_array_decoder.h"

namespace cogmap::hw::bag {
namespace {

std::optional<SonarEncoding> sonar_encoding(const std::string& type) {
  if (type == "sensor_msgs/PointCloud") return SonarEncoding::kPointCloud;
  if (type == "sensor_msgs/PointCloud2") return SonarEncoding::kPointCloud2;
  if (type == kSonarArrayType) return SonarEncoding::kSonarArray;
  return std::nullopt;
}

std::optional<OdometryEncoding> odometry_encoding(const std::string& type) {
  if (type == "nav_msgs/Odometry") return OdometryEncoding::kOdometry;
  if (type == "tf2_msgs/TFMessage" || type == "tf/tfMessage") return OdometryEncoding::kTf;
  return std::nullopt;
}

// Lower rank wins among sonar types: the SonarArray carries ranges directly; PointCloud is
// RosAria's primary topic, PointCloud2 its optional copy.
int sonar_rank(SonarEncoding e) {
  switch (e) {
    case SonarEncoding::kSonarArray:
      return 0;
    case SonarEncoding::kPointCloud:
      return 1;
    case SonarEncoding::kPointCloud2:
      return 2;
  }
  return 3;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string namespace_of(const std::string& topic) {
  const auto slash = topic.find_last_of('/');
  return slash == std::string::npos ? "" : topic.substr(0, slash);
}

std::string describe(const std::vector<const TopicInfo*>& topics) {
  std::string out;
  for (const TopicInfo* t : topics) {
    if (!out.empty()) out += ", ";
    out += t->topic + " (" + t->datatype + ", " + std::to_string(t->messages) + " messages)";
  }
  return out.empty() ? "none" : out;
}

std::string describe_all(const std::vector<TopicInfo>& topics) {
  std::vector<const TopicInfo*> all;
  for (const TopicInfo& t : topics) all.push_back(&t);
  return describe(all);
}

const TopicInfo* find(const std::vector<TopicInfo>& topics, const std::string& name) {
  for (const TopicInfo& t : topics) {
    if (t.topic == name) return &t;
  }
  return nullptr;
}

// Keeps the candidates for which `keep` holds, unless that would keep none.
template <typename Pred>
void narrow(std::vector<const TopicInfo*>& c, Pred keep) {
  std::vector<const TopicInfo*> kept;
  for (const TopicInfo* t : c) {
    if (keep(*t)) kept.push_back(t);
  }
  if (!kept.empty()) c = kept;
}

const TopicInfo& choose_sonar(const std::vector<TopicInfo>& topics, const std::string& named) {
  if (!named.empty()) {
    const TopicInfo* t = find(topics, named);
    if (!t)
      throw std::runtime_error("no topic " + named + " (topics: " + describe_all(topics) + ")");
    if (!sonar_encoding(t->datatype)) {
      throw std::runtime_error("topic " + named + " is " + t->datatype +
                               ", not a sonar type (sensor_msgs/PointCloud, "
                               "sensor_msgs/PointCloud2, p2os_msgs/SonarArray)");
    }
    return *t;
  }
  std::vector<const TopicInfo*> c;
  for (const TopicInfo& t : topics) {
    if (sonar_encoding(t.datatype) && t.messages > 0) c.push_back(&t);
  }
  if (c.empty()) {
    throw std::runtime_error(
        "no sonar topic (sensor_msgs/PointCloud, sensor_msgs/PointCloud2 or "
        "p2os_msgs/SonarArray with messages); topics: " +
        describe_all(topics));
  }
  narrow(c, [](const TopicInfo& t) { return lower(t.topic).find("sonar") != std::string::npos; });
  int best = 3;
  for (const TopicInfo* t : c) best = std::min(best, sonar_rank(*sonar_encoding(t->datatype)));
  narrow(c, [&](const TopicInfo& t) { return sonar_rank(*sonar_encoding(t.datatype)) == best; });
  if (c.size() > 1) {
    throw std::runtime_error("more than one sonar topic: " + describe(c) +
                             "; choose one with --sonar-topic");
  }
  return *c.front();
}

const TopicInfo& choose_odometry(const std::vector<TopicInfo>& topics, const std::string& named,
                                 const std::string& sonar_topic) {
  if (!named.empty()) {
    const TopicInfo* t = find(topics, named);
    if (!t)
      throw std::runtime_error("no topic " + named + " (topics: " + describe_all(topics) + ")");
    if (!odometry_encoding(t->datatype)) {
      throw std::runtime_error("topic " + named + " is " + t->datatype +
                               ", not nav_msgs/Odometry or tf2_msgs/TFMessage");
    }
    return *t;
  }
  std::vector<const TopicInfo*> c;
  for (const TopicInfo& t : topics) {
    if (t.datatype == "nav_msgs/Odometry" && t.messages > 0) c.push_back(&t);
  }
  if (c.empty()) {
    for (const TopicInfo& t : topics) {
      if (odometry_encoding(t.datatype) && t.messages > 0) c.push_back(&t);
    }
    narrow(c, [](const TopicInfo& t) { return t.topic == "/tf" || t.topic == "tf"; });
  }
  if (c.empty()) {
    throw std::runtime_error("no odometry: no nav_msgs/Odometry topic and no /tf topic; topics: " +
                             describe_all(topics));
  }
  // RosAria's pose sits beside its sonar (/RosAria/pose, /RosAria/sonar).
  const std::string ns = namespace_of(sonar_topic);
  narrow(c, [&](const TopicInfo& t) { return namespace_of(t.topic) == ns; });
  if (c.size() > 1) {
    throw std::runtime_error("more than one odometry topic: " + describe(c) +
                             "; choose one with --odom-topic");
  }
  return *c.front();
}

}  // namespace

TopicChoice choose_topics(const std::vector<TopicInfo>& topics, const BagImportOptions& options) {
  const TopicInfo& sonar = choose_sonar(topics, options.sonar_topic);
  const TopicInfo& odom = choose_odometry(topics, options.odom_topic, sonar.topic);
  if (sonar.topic == odom.topic) {
    throw std::runtime_error("sonar and odometry cannot both be " + sonar.topic);
  }
  TopicChoice choice;
  choice.request.sonar_topic = sonar.topic;
  choice.request.sonar = *sonar_encoding(sonar.datatype);
  choice.request.odometry_topic = odom.topic;
  choice.request.odometry = *odometry_encoding(odom.datatype);
  choice.sonar_type = sonar.datatype;
  choice.odom_type = odom.datatype;
  return choice;
}

}  // namespace cogmap::hw::bag
