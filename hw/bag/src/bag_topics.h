#pragma once
// Which topics of a bag hold the sonar and the odometry: named by the user, or found by type.

#include <string>
#include <vector>

#include "cogmap/hw/bag_import.h"
#include "ros_bag_reader.h"

namespace cogmap::hw::bag {

/// The topics chosen and how they are encoded.
struct TopicChoice {
  StreamRequest request;
  std::string sonar_type, odom_type;
};

/// Picks the topics. Throws std::runtime_error with a message that lists the candidates when
/// there is none, or more than one and no rule decides, or a named topic is missing or of a
/// type that cannot be read.
TopicChoice choose_topics(const std::vector<TopicInfo>& topics, const BagImportOptions& options);

}  // namespace cogmap::hw::bag
